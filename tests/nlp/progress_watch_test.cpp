#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>
#include <vector>

#include <modsynth/nlp/progress_watch.h>

using namespace modsynth;

namespace {

struct Iterate {
    double primal, dual;
};

nlp::ProgressWatch watch_over(const std::vector<Iterate>& run) {
    nlp::ProgressWatch w;
    for (std::size_t i = 0; i < run.size(); ++i)
        w.observe(static_cast<int>(i), run[i].primal, run[i].dual);
    return w;
}

}  // namespace

TEST_CASE("a healthy refinement is left to converge", "[nlp][watch]") {
    // The infeasibilities of a refinement of a 160-primitive planted task
    // that converged in 33 iterations: from a feasible start the primal
    // infeasibility rises by orders of magnitude before it falls.
    const std::vector<Iterate> run = {
        {3.61e-16, 1.54e+00}, {2.09e-08, 3.30e-02}, {6.28e-02, 8.62e-02}, {3.16e-01, 3.32e-01},
        {2.43e-01, 5.05e-01}, {1.25e-01, 4.83e-01}, {5.67e-02, 1.65e-01}, {4.24e-03, 5.15e-03},
        {2.48e-02, 2.31e+00}, {9.38e-02, 1.91e+00}, {9.37e-02, 9.16e-01}, {8.42e-02, 5.10e+01},
        {7.61e-02, 4.38e+01}, {7.35e-02, 4.23e+01}, {2.36e-02, 1.30e+02}, {3.97e-03, 5.23e+01},
        {1.01e-03, 8.96e+01}, {1.20e-03, 9.97e+01}, {3.28e-05, 6.10e+00}, {5.13e-07, 2.24e-02},
        {8.11e-04, 2.01e-02}, {1.52e-03, 2.11e-02}, {1.11e-02, 1.84e-02}, {3.69e-04, 9.93e-04},
        {3.25e-04, 1.18e-02}, {5.27e-04, 2.43e-03}, {2.27e-05, 2.55e-03}, {4.49e-02, 1.39e-02},
        {6.13e-02, 1.32e-02}, {6.89e-03, 2.92e-03}, {1.99e-03, 6.63e-04}, {1.40e-05, 1.14e-04},
        {1.23e-06, 7.05e-07}, {1.52e-10, 1.06e-08}};
    CHECK(watch_over(run).doomed().empty());
}

TEST_CASE("a stalled primal infeasibility is doomed", "[nlp][watch]") {
    // The same task's next refinement (a wrong elbow branch): the primal
    // infeasibility stays near 0.019 while the duals grow without bound;
    // Ipopt spent 70 s on a dozen iterations there.
    std::vector<Iterate> run = {{2.05e-02, 2.61e+00}, {1.98e-02, 8.88e+00}, {1.96e-02, 1.01e+03},
                                {1.90e-02, 5.41e+03}, {1.90e-02, 2.77e+05}, {1.89e-02, 8.15e+06}};
    CHECK(watch_over(run).doomed().empty());  // too early to tell
    for (double dual : {9.87e+07, 2.30e+09, 2.56e+10, 6.30e+10, 1.71e+14})
        run.push_back({1.90e-02, dual});
    // Eleven iterates within 10% of each other: stopped at the eleventh.
    run.pop_back();
    CHECK(watch_over(run).doomed().empty());
    run.push_back({1.90e-02, 1.71e+14});
    CHECK(watch_over(run).doomed().find("stalled") == 0);
}

TEST_CASE("diverging duals without primal progress are doomed", "[nlp][watch]") {
    std::vector<Iterate> run;
    for (int i = 0; i < 5; ++i) run.push_back({i % 2 ? 0.03 : 0.02, 1e9 * (i + 1)});
    CHECK(watch_over(run).doomed().empty());
    run.push_back({0.03, 1e10});
    CHECK(watch_over(run).doomed().find("diverging") == 0);
}

TEST_CASE("a flat primal infeasibility with tame duals is stalled", "[nlp][watch]") {
    std::vector<Iterate> run;
    for (int i = 0; i < 10; ++i) run.push_back({0.05 * (1.0 - 0.01 * i), 1.0});
    CHECK(watch_over(run).doomed().empty());  // ten iterations: one short of the window
    run.push_back({0.049, 1.0});
    const auto w = watch_over(run);
    REQUIRE_FALSE(w.doomed().empty());
    CHECK(w.doomed().find("stalled") == 0);
}

TEST_CASE("a slow but steady decrease, or a nearly feasible plateau, goes on", "[nlp][watch]") {
    std::vector<Iterate> slow, close;
    for (int i = 0; i < 40; ++i) {
        slow.push_back({0.1 * std::pow(0.95, i), 1.0});  // x0.6 every ten iterations
        close.push_back({5e-4, 1e9});                    // duals large, but nearly feasible
    }
    CHECK(watch_over(slow).doomed().empty());
    CHECK(watch_over(close).doomed().empty());
}

TEST_CASE("the watch's options are checked", "[nlp][watch]") {
    nlp::ProgressWatchOptions o;
    o.flat_ratio = 1.0;
    CHECK_THROWS_AS(nlp::ProgressWatch(o), std::invalid_argument);
}
