#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

#include <modsynth/geometry/primitive.h>
#include <modsynth/io/task_io.h>
#include <modsynth/nlp/formulation.h>
#include <modsynth/nlp/solver.h>
#include <modsynth/nlp/warm_start.h>

#include "../support/arm_problems.h"

using namespace modsynth;

namespace {

// Keys of the test programs: a family and a number.
nlp::Key key(nlp::Key::Family family, int index) {
    nlp::Key k;
    k.family = family;
    k.index = index;
    return k;
}

// min (x - 2)^2 + (y - 1)^2 on the unit disc, written twice (`twice`
// repeats the disc's key, as both ends of a separating line share one),
// plus, when `with_z`, a variable z >= 0.5 minimised on its own.
nlp::QuadraticProgram disc_program(bool with_z, bool twice) {
    using F = nlp::Key::Family;
    nlp::QuadraticProgram qp;
    int z = -1;
    if (with_z) z = qp.add_variable(0.5, 3.0, 2.0, "z", key(F::Lambda, 0));  // shifts every index
    const int x = qp.add_variable(-nlp::kInfinity, nlp::kInfinity, 0.0, "x", key(F::Base, 0));
    const int y = qp.add_variable(-nlp::kInfinity, nlp::kInfinity, 0.0, "y", key(F::Base, 1));
    nlp::Quadratic f;
    f.add(5.0).add(x, x, 1.0).add(x, -4.0).add(y, y, 1.0).add(y, -2.0);
    if (with_z) f.add(z, 1.0);
    qp.set_objective(f);
    if (with_z)
        qp.add_constraint(nlp::Quadratic{}.add(z, z, 1.0), 0.0, 9.0, "z box", key(F::Bisector, 0));
    const auto disc = nlp::Quadratic{}.add(x, x, 1.0).add(y, y, 1.0);
    qp.add_constraint(disc, -nlp::kInfinity, 1.0, "disc", key(F::Clearance, 0));
    if (twice)
        qp.add_constraint(nlp::Quadratic{}.add(x, x, 2.0).add(y, y, 2.0), -nlp::kInfinity, 2.0,
                          "disc", key(F::Clearance, 0));
    qp.finalize();
    return qp;
}

}  // namespace

TEST_CASE("a solution carries over to a larger program by key", "[nlp]") {
    const nlp::QuadraticProgram small = disc_program(false, true);
    const nlp::SolverResult solved = nlp::minimize(small, {});
    REQUIRE(solved.usable());
    REQUIRE(solved.lambda.size() == 2);
    REQUIRE(solved.z_lower.size() == 2);
    const nlp::QuadraticProgram large = disc_program(true, true);
    const nlp::WarmStart w = nlp::carry_over(small, solved, large);
    REQUIRE(w.x.size() == 3);
    REQUIRE(w.lambda.size() == 3);
    // x and y moved from indices 0, 1 to 1, 2; z keeps its own start.
    CHECK(w.x[0] == 2.0);
    CHECK(w.x[1] == solved.x[0]);
    CHECK(w.x[2] == solved.x[1]);
    CHECK(w.z_lower[0] == 0.0);
    CHECK(w.z_lower[1] == solved.z_lower[0]);
    // "z box" is new; the two "disc" constraints, of one key, match in order.
    CHECK(w.lambda[0] == 0.0);
    CHECK(w.lambda[1] == solved.lambda[0]);
    CHECK(w.lambda[2] == solved.lambda[1]);
    // Both disc constraints are active at the optimum: real multipliers.
    CHECK(solved.lambda[0] + 2.0 * solved.lambda[1] > 0.1);
}

TEST_CASE("a warm-started solve reaches the cold solve's optimum", "[nlp]") {
    const nlp::QuadraticProgram small = disc_program(false, false);
    const nlp::SolverResult first = nlp::minimize(small, {});
    REQUIRE(first.usable());
    const nlp::QuadraticProgram large = disc_program(true, false);
    const nlp::SolverResult cold = nlp::minimize(large, {});
    const nlp::WarmStart w = nlp::carry_over(small, first, large);
    const nlp::SolverResult warm = nlp::minimize(large, {}, &w);
    REQUIRE(cold.usable());
    REQUIRE(warm.usable());
    for (int i = 0; i < 3; ++i) CHECK(warm.x[i] == Approx(cold.x[i]).margin(1e-5));
    CHECK(warm.x[1] == Approx(2.0 / std::sqrt(5.0)).margin(1e-5));
    CHECK(warm.x[0] == Approx(0.5).margin(1e-5));
}

// Whether it saves iterations is a matter for the benchmark: on a 640-primitive
// path a later round took 11 instead of 57; here, a small one, about as many.
TEST_CASE("a later refinement round warm-started from the last one finds the same robot",
          "[nlp][slow]") {
    nlp::ArmProblem p = testing::rose_arm_problem(nlp::SweptVolume::Sampled);
    const task::Task& rose = *p.task;
    p.start.base = {-0.02, 0.007};
    p.start.link_lengths = {0.56, 0.47};
    p.horizon = 0.10;
    p.points.clear();  // the primitives' starts only
    for (int j = 0; j < static_cast<int>(rose.trajectory.size()); ++j) p.points.push_back({j, 0.0});
    const nlp::Formulation first = nlp::formulate(p);
    const nlp::SolverResult solved = nlp::minimize(first.program, {});
    REQUIRE(solved.usable());
    // The next round: the refined robot, and points in the middle of every
    // primitive, as counterexamples would add.
    nlp::ArmProblem next = p;
    next.start = nlp::robot_from(first, solved.x);
    for (int j = 0; j < static_cast<int>(rose.trajectory.size()); ++j)
        next.points.push_back({j, 0.5 * geometry::length(rose.trajectory[j])});
    const nlp::Formulation second = nlp::formulate(next);
    const nlp::SolverResult cold = nlp::minimize(second.program, {});
    const nlp::WarmStart w = nlp::carry_over(first.program, solved, second.program);
    const nlp::SolverResult warm = nlp::minimize(second.program, {}, &w);
    REQUIRE(cold.usable());
    REQUIRE(warm.usable());
    INFO("cold " << cold.iterations << " iterations, warm " << warm.iterations);
    CHECK(second.program.infeasibility(warm.x.data()) < 1e-5);
    CHECK(warm.objective == Approx(cold.objective).margin(1e-4));
    const kinematics::Robot a = nlp::robot_from(second, warm.x);
    const kinematics::Robot b = nlp::robot_from(second, cold.x);
    CHECK((a.base - b.base).norm() < 1e-3);
}

TEST_CASE("a warm start that does not fit the program is refused", "[nlp]") {
    const nlp::QuadraticProgram qp = disc_program(false, false);
    nlp::WarmStart w;
    w.x = {0.0};
    CHECK_THROWS_AS(nlp::minimize(qp, {}, &w), std::invalid_argument);
}

namespace {

// Whether two entries share a key exactly when they share a label (or a
// name): the warm start then matches what it matched by words before.
template <typename KeyOf, typename WordsOf>
void check_keys_follow_words(int count, KeyOf key_of, WordsOf words_of) {
    std::map<nlp::Key, std::string> words_of_key;
    std::map<std::string, nlp::Key> key_of_words;
    for (int i = 0; i < count; ++i) {
        const nlp::Key& k = key_of(i);
        const std::string& w = words_of(i);
        INFO(w);
        CHECK(k.family != nlp::Key::Family::None);
        const auto [a, new_key] = words_of_key.emplace(k, w);
        const auto [b, new_words] = key_of_words.emplace(w, k);
        CHECK(new_key == new_words);
        CHECK(a->second == w);
        CHECK(b->second == k);
    }
}

}  // namespace

TEST_CASE("every variable and constraint of a refinement is keyed as its words say", "[nlp]") {
    using nlp::SweptVolume;
    for (const SweptVolume swept : {SweptVolume::Sampled, SweptVolume::Over, SweptVolume::App}) {
        for (const int dof : {2, 3}) {
            INFO("swept " << static_cast<int>(swept) << ", " << dof << " joints");
            nlp::ArmProblem p = testing::rose_arm_problem(swept);
            if (dof == 3) {
                p.skeleton.dof = 3;
                p.start.link_lengths = {0.2, 0.35, 0.3};
                for (int j = 0; j < static_cast<int>(p.task->trajectory.size()); ++j)
                    p.start.proximal_angles.push_back(0.3 + 0.05 * j);
            }
            const nlp::Formulation f = nlp::formulate(p);
            const nlp::QuadraticProgram& qp = f.program;
            check_keys_follow_words(
                qp.num_variables(), [&](int i) -> const nlp::Key& { return qp.variable_key(i); },
                [&](int i) -> const std::string& { return qp.variable_name(i); });
            check_keys_follow_words(
                qp.num_constraints(),
                [&](int m) -> const nlp::Key& { return qp.constraint_key(m); },
                [&](int m) -> const std::string& { return qp.constraint_label(m); });
        }
    }
}
