#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <set>

#include <modsynth/geometry/primitive.h>
#include <modsynth/io/task_io.h>
#include <modsynth/smt/front_stage.h>

#include "../support/fixtures.h"

using namespace modsynth;
using smt::FrontStage;

namespace {

bool contains(const std::vector<std::string>& v, const std::string& s) {
    return std::find(v.begin(), v.end(), s) != v.end();
}

}  // namespace

TEST_CASE("front stage finds a skeleton whose coarse point meets the relaxation", "[smt][slow]") {
    const task::Task t = io::load_task(testing::source_path("tasks/rose.json"));
    FrontStage fs(t, 2);
    REQUIRE(fs.check() == FrontStage::Result::Sat);
    const smt::Skeleton s = fs.skeleton();
    CHECK(s.dof == 2);
    REQUIRE(s.base_region == 0);
    CHECK(t.base_regions[0].contains(s.base, 1e-6));
    REQUIRE(s.link_lengths.size() == 2);
    const double reach = s.link_lengths[0] + s.link_lengths[1];
    for (double r : s.link_lengths) {
        CHECK(r >= t.robot.min_link_length - 1e-6);
        CHECK(r <= t.robot.max_link_length + 1e-6);
    }
    for (const auto& p : t.trajectory) {
        // The front stage constrains sampled points: the ends at least.
        CHECK((p.start - s.base).norm() <= reach + 1e-5);
        CHECK((p.end - s.base).norm() <= reach + 1e-5);
    }
}

TEST_CASE("front stage proves an out-of-reach task infeasible with a minimal core", "[smt][slow]") {
    const std::string dir = testing::source_path("tests/fixtures/planted");
    int checked = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        const std::string name = entry.path().filename().string();
        if (name.rfind("ir-", 0) != 0 || name.find(".task.json") == std::string::npos) continue;
        const std::string stem = entry.path().string().substr(0, entry.path().string().size() - 10);
        const auto expect = testing::read_json(stem + ".expect.json");
        const task::Task t = io::load_task(entry.path().string());
        for (int dof : {2, 3}) {
            FrontStage fs(t, dof);
            REQUIRE(fs.check() == FrontStage::Result::Unsat);
            const auto core = task::to_strings(fs.minimal_core());
            INFO(name << " dof " << dof);
            CHECK(contains(core, "robot.max_link_length"));
            bool names_unreachable = false;
            for (const auto& part : expect["core_should_include_one_of"])
                names_unreachable = names_unreachable || contains(core, part.get<std::string>());
            CHECK(names_unreachable);
            // Minimal: without any one part the rest is satisfiable.
            for (const auto& drop : core) {
                task::Task relaxed = t;
                if (drop == "robot.max_link_length") relaxed.robot.max_link_length = 100.0;
                if (drop == "base_regions") relaxed.base_regions.clear();
                if (drop.rfind("trajectory[", 0) == 0) continue;  // cannot delete a primitive
                FrontStage again(relaxed, dof);
                CHECK(again.check() != FrontStage::Result::Unsat);
            }
        }
        ++checked;
    }
    CHECK(checked >= 3);
}

TEST_CASE("front stage answers sat on every planted feasible task", "[smt][slow]") {
    // Soundness: the relaxation only states necessary conditions.
    const std::string dir = testing::source_path("tests/fixtures/planted");
    int checked = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        const std::string name = entry.path().filename().string();
        if (name.rfind("p2-", 0) != 0 || name.find(".task.json") == std::string::npos) continue;
        FrontStage fs(io::load_task(entry.path().string()), 2);
        INFO(name);
        CHECK(fs.check() == FrontStage::Result::Sat);
        ++checked;
    }
    CHECK(checked >= 3);
}

TEST_CASE("an obstacle covering the whole base region is a conflict of three parts", "[smt]") {
    task::Task t = testing::line_task();
    t.obstacles.push_back({{0.0, 0.0}, 0.09});  // covers the region, clear of the line
    FrontStage fs(t, 2);
    REQUIRE(fs.check() == FrontStage::Result::Unsat);
    const auto core = task::to_strings(fs.minimal_core());
    CHECK(contains(core, "obstacles[0]"));
    CHECK(contains(core, "base_regions"));
    CHECK_FALSE(contains(core, "trajectory[0]"));
}

TEST_CASE("blocking every skeleton exhausts the search without claiming infeasibility", "[smt]") {
    const task::Task t = testing::line_task();
    FrontStage fs(t, 2);
    int found = 0;
    while (fs.check() == FrontStage::Result::Sat) {
        fs.block(fs.skeleton());
        ++found;
        REQUIRE(found <= 4);
    }
    CHECK(found == 2);  // one region, two elbow signs
    CHECK(fs.exhausted_by_blocking());
}

TEST_CASE("the encoding dumps as SMT-LIB2 with its task-part literals", "[smt]") {
    const task::Task t = io::load_task(testing::source_path("tasks/rose.json"));
    FrontStage fs(t, 2);
    const std::string smt2 = fs.smtlib();
    CHECK(smt2.find("declare-fun") != std::string::npos);
    CHECK(smt2.find("|trajectory[6]|") != std::string::npos);
    CHECK(smt2.find("base_regions") != std::string::npos);
}

namespace {

// `count` short lines along the x axis from x0: a path of many primitives.
task::Task many_lines(int count, double x0, double length) {
    task::Task t;
    const double step = length / count;
    for (int j = 0; j < count; ++j)
        t.trajectory.push_back(
            geometry::make_line({x0 + j * step, 0.3}, {x0 + (j + 1) * step, 0.3}));
    return t;
}

}  // namespace

TEST_CASE("front stage stops at its deadline, in encoding or in a check", "[smt]") {
    const task::Task t = many_lines(3000, -0.5, 1.0);
    smt::FrontStageOptions o;
    o.deadline = run::Deadline::in(0.0);
    const auto t0 = std::chrono::steady_clock::now();
    FrontStage fs(t, 2, o);
    CHECK(fs.check() == FrontStage::Result::Unknown);
    CHECK(task::to_strings(fs.minimal_core()).empty());
    CHECK(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() < 0.5);
    CHECK_THAT(fs.reason_unknown(), Catch::Matchers::Contains("time limit"));
}

TEST_CASE("front stage on a long path keeps the span of its widest pair", "[smt][slow]") {
    // 200 primitives (past the all-pairs threshold) spanning 3 m: with links
    // of at most 0.7 m no base reaches both ends.
    task::Task t = many_lines(200, -1.5, 3.0);
    t.robot.max_link_length = 0.7;
    t.robot.dof = {2};
    FrontStage fs(t, 2);
    REQUIRE(fs.check() == FrontStage::Result::Unsat);
    const auto core = task::to_strings(fs.minimal_core());
    CHECK(contains(core, "robot.max_link_length"));
    CHECK(std::count_if(core.begin(), core.end(),
                        [](const std::string& p) { return p.rfind("trajectory[", 0) == 0; }) >= 1);
}

TEST_CASE("the refined level proves what reach alone cannot, and is skipped on long paths",
          "[smt]") {
    // The line passes through the base region: the coarse level (reach
    // only) is satisfied, but the tip can never come within a tube's
    // diameter of the base joint (the refined level's gap atoms).
    task::Task t = testing::line_task();
    t.trajectory = {geometry::make_line({-0.2, 0.0}, {0.3, 0.0})};
    t.base_regions = {{{-0.01, -0.01}, {0.01, 0.01}}};
    FrontStage full(t, 2);
    CHECK(full.check() == FrontStage::Result::Unsat);
    smt::FrontStageOptions coarse_only;
    coarse_only.refined_max_primitives = 0;
    FrontStage coarse(t, 2, coarse_only);
    CHECK(coarse.check() == FrontStage::Result::Sat);
    CHECK_FALSE(coarse.conflicts({task::TaskPart::trajectory(0), task::TaskPart::base_regions()}));
    // The dump is the encoding actually checked: without the refined
    // families it is the shorter one.
    CHECK(coarse.smtlib().size() < full.smtlib().size());
}

TEST_CASE(
    "the refined level's circle atoms: a circle through the base region is refuted, one "
    "round it is not",
    "[smt]") {
    // Through the base region: the tip would have to pass over the base
    // joint (the self-collision gap of the refined level). The circle
    // starts 22.5 degrees past the base, so that its sampled points (every
    // 45 degrees) stay 39 mm away, more than the gap: only the exact atoms
    // see it.
    const double a = geometry::kTau * 202.5 / 360.0;
    task::Task through = testing::line_task();
    through.trajectory = {
        geometry::make_circle({0.1 + 0.1 * std::cos(a), 0.1 * std::sin(a)}, {0.1, 0.0}, true)};
    through.base_regions = {{{-0.001, -0.001}, {0.001, 0.001}}};
    FrontStage refuted(through, 2);
    CHECK(refuted.check() == FrontStage::Result::Unsat);
    const auto core = task::to_strings(refuted.minimal_core());
    CHECK(std::set<std::string>(core.begin(), core.end()) ==
          std::set<std::string>{"trajectory[0]", "base_regions", "robot.link_diameter"});
    // Round the base region, 0.3 m away: reached from inside, with the
    // annulus of two links of about equal length.
    task::Task round = through;
    round.trajectory = {geometry::make_circle({0.3, 0.0}, {0.0, 0.0}, true)};
    FrontStage reached(round, 2);
    REQUIRE(reached.check() == FrontStage::Result::Sat);
    const smt::Skeleton s = reached.skeleton();
    CHECK(s.link_lengths[0] + s.link_lengths[1] >= 0.29);
}
