// Cancelling a run: the token ends every deadline derived from the run's,
// and a solve cancelled from another thread returns promptly, whatever
// stage it is in.
#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <thread>

#include <modsynth/modsynth.h>
#include <modsynth/run/deadline.h>
#include <modsynth/run/stopwatch.h>

using modsynth::run::CancelToken;
using modsynth::run::Deadline;

TEST_CASE("a cancelled token expires its deadline and every one derived from it", "[run]") {
    CancelToken token;
    const Deadline run = Deadline::in(100.0).cancelled_by(token);
    const Deadline step = run.within(50.0);
    const Deadline kept = run.reserve(10.0);
    const Deadline part = run.share(0.5);
    const Deadline longer = run.at_least(500.0);
    const Deadline joined = earlier(Deadline::never(), run);
    const Deadline postponed = later(Deadline::in(1000.0), run);
    for (const Deadline* d : {&run, &step, &kept, &part, &longer, &joined, &postponed}) {
        CHECK_FALSE(d->expired());
        CHECK(d->remaining() > 1.0);
    }
    CancelToken copy = token;
    copy.cancel();
    CHECK(token.cancelled());
    for (const Deadline* d : {&run, &step, &kept, &part, &longer, &joined, &postponed}) {
        CHECK(d->expired());
        CHECK(d->remaining() == 0.0);
    }
    // A deadline without the token is untouched.
    CHECK_FALSE(Deadline::in(100.0).expired());
    CHECK(std::isinf(Deadline::never().remaining()));
}

namespace {

/// A zigzag of many short lines: minutes of work for the search if it ran
/// to the end with a generous limit.
modsynth::Task long_zigzag(int lines) {
    modsynth::Task task;
    task.name = "zigzag";
    for (int k = 0; k < lines; ++k) {
        const double x0 = 0.3 + 0.0004 * k, x1 = x0 + 0.0004;
        const double y0 = (k % 2 == 0) ? 0.1 : 0.3, y1 = (k % 2 == 0) ? 0.3 : 0.1;
        task.trajectory.push_back(modsynth::geometry::make_line({x0, y0}, {x1, y1}));
    }
    task.base_regions.push_back({{-0.05, -0.05}, {0.05, 0.05}});
    task.obstacles.push_back({{0.45, 0.45}, 0.04});
    return task;
}

}  // namespace

TEST_CASE("a solve cancelled from another thread returns within 0.2 s", "[run][synth][slow]") {
    const modsynth::Task task = long_zigzag(400);
    for (double after : {0.05, 0.4, 1.2}) {
        INFO("cancelled after " << after << " s");
        modsynth::SolveOptions options;
        options.time_limit = 120.0;
        std::thread canceller([token = options.cancel, after] {
            std::this_thread::sleep_for(std::chrono::duration<double>(after));
            token.cancel();
        });
        modsynth::run::Stopwatch clock;
        const modsynth::Solution s = modsynth::solve(task, options);
        const double took = clock.seconds();
        canceller.join();
        CHECK(took < after + 0.2);
        CHECK(s.status != modsynth::Status::Infeasible);
    }
}
