#include <modsynth/io/task_io.h>
#include <modsynth/prove/branch_and_bound.h>
#include <modsynth/prove/no_go.h>
#include <modsynth/prove/obstacle_proof.h>
#include <modsynth/synth/synthesizer.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <random>

#include "../support/fixtures.h"

using namespace modsynth;
using geometry::Vec2;
using Outcome = prove::BranchAndBoundResult::Outcome;

namespace {

// A row of overlapping posts (radius 0.03, 5 cm apart) along x = x0 from
// y = from to y = to.
void post_row(task::Task& t, double x0, double from, double to) {
    const int n = static_cast<int>(std::round((to - from) / 0.05));
    for (int k = 0; k <= n; ++k) t.obstacles.push_back({{x0, from + (to - from) * k / n}, 0.03});
}

// A zig-zag corridor: the base plate at the origin, a short stroke at
// x = 0.8, a wall at x = 0.3 open above y = top_a and a wall at x = 0.55
// open below y = bottom_b. The free space is connected and the way through
// it (about 1.5 m) is within the 2 m of two 1 m links, but a 2-joint arm
// bends once and the corridor needs two bends.
task::Task zigzag(double top_a = 0.25, double bottom_b = -0.25) {
    task::Task t;
    t.name = "zigzag";
    t.trajectory.push_back(geometry::make_line({0.8, -0.05}, {0.8, 0.05}));
    post_row(t, 0.3, -1.5, top_a);
    post_row(t, 0.55, bottom_b, 1.5);
    t.base_regions.push_back({{-0.05, -0.05}, {0.05, 0.05}});
    t.robot.dof = {2};
    return t;
}

prove::BranchAndBoundOptions generous() {
    prove::BranchAndBoundOptions o;
    o.time_limit = 30.0;
    o.max_boxes = 5000000;
    return o;
}

}  // namespace

TEST_CASE("branch and bound options are validated", "[bnb]") {
    prove::BranchAndBoundOptions o;
    std::string error;
    CHECK(o.IsValid(&error));
    o.delta = 0.0;
    CHECK_FALSE(o.IsValid(&error));
    CHECK(error.find("BranchAndBoundOptions::delta") != std::string::npos);
    CHECK_THROWS_AS(prove::branch_and_bound(zigzag(), prove::all_obstacles(zigzag()), o),
                    std::invalid_argument);
}

TEST_CASE("branch and bound proves a corridor with two bends closed to two joints", "[bnb][slow]") {
    const task::Task t = zigzag();
    // Neither a wall nor a detour proves it.
    REQUIRE_FALSE(prove::prove_obstacle_infeasible(t).has_value());
    const auto r = prove::branch_and_bound(t, prove::all_obstacles(t), generous());
    INFO("boxes " << r.boxes << ", " << r.seconds << " s");
    REQUIRE(r.outcome == Outcome::Infeasible);
    CHECK(!r.obstacles.empty());
    CHECK(r.primitives == std::vector<int>{0});
}

TEST_CASE("branch and bound finds a box when the corridor needs one bend", "[bnb][slow]") {
    // Both openings above: an elbow above the walls sees base and stroke.
    const task::Task t = zigzag(0.25, -1.5);
    task::Task open = t;
    open.obstacles.clear();
    post_row(open, 0.3, -1.5, 0.25);
    post_row(open, 0.55, -1.5, 0.25);
    const auto r = prove::branch_and_bound(open, prove::all_obstacles(open), generous());
    REQUIRE(r.outcome == Outcome::Box);
    REQUIRE(r.box.has_value());
    CHECK(r.violation < 4 * generous().delta);
    CHECK(r.box->r1_max - r.box->r1_min <= generous().delta);
}

TEST_CASE("branch and bound never refutes a planted 2-joint task", "[bnb][slow]") {
    namespace fs = std::filesystem;
    int tried = 0;
    for (const char* folder : {"tests/fixtures/planted", "tests/fixtures/planted-obstacles"}) {
        for (const auto& f : fs::directory_iterator(testing::source_path(folder))) {
            const std::string name = f.path().filename().string();
            if (name.rfind("p2-", 0) != 0 || name.find(".task.json") == std::string::npos) continue;
            task::Task t = io::load_task(f.path().string());
            t.robot.dof = {2};
            prove::BranchAndBoundOptions o;
            o.time_limit = 3.0;
            const auto r = prove::branch_and_bound(t, prove::all_obstacles(t), o);
            INFO(name << ": boxes " << r.boxes);
            CHECK(r.outcome != Outcome::Infeasible);
            ++tried;
        }
    }
    CHECK(tried >= 10);
}

namespace {

// A zig-zag corridor of random size, turned and moved at random: walls of
// posts at x = a and x = a + g, the first open above `top`, the second
// below -`bottom` (or, with `one_bend`, above `top` too: then an elbow above
// both walls sees base and stroke, and a 2-joint arm fits).
task::Task random_zigzag(unsigned seed, bool one_bend) {
    std::mt19937 rng(seed);
    auto u = [&](double lo, double hi) {
        return std::uniform_real_distribution<double>(lo, hi)(rng);
    };
    const double rho = u(0.02, 0.04), a = u(0.2, 0.35), g = u(0.15, 0.3);
    const double top = u(0.1, 0.35), bottom = u(0.1, 0.35), px = a + g + u(0.15, 0.3);
    const double phi = u(0.0, geometry::kTau);
    const Vec2 shift(u(-1, 1), u(-1, 1));
    const auto at = [&](double x, double y) {
        return Vec2(shift + x * geometry::unit(phi) + y * geometry::perp(geometry::unit(phi)));
    };
    task::Task t;
    t.name = "random-zigzag";
    const auto row = [&](double x0, double y0, double y1) {
        const int n = static_cast<int>(std::ceil((y1 - y0) / (1.6 * rho)));
        for (int k = 0; k <= n; ++k) t.obstacles.push_back({at(x0, y0 + (y1 - y0) * k / n), rho});
    };
    row(a, -1.5, top);
    if (one_bend)
        row(a + g, -1.5, top);
    else
        row(a + g, -bottom, 1.5);
    const double half = u(0.02, 0.08);
    t.trajectory.push_back(geometry::make_line(at(px, -half), at(px, half)));
    const Vec2 size(u(0.02, 0.12), u(0.02, 0.12));
    t.base_regions.push_back({at(0, 0) - size / 2, at(0, 0) + size / 2});
    t.robot.dof = {2};
    return t;
}

}  // namespace

TEST_CASE("branch and bound proves random two-bend corridors and never one-bend ones",
          "[bnb][slow]") {
    for (unsigned seed = 1; seed <= 4; ++seed) {
        INFO("seed " << seed);
        const task::Task closed = random_zigzag(seed, false);
        const auto r = prove::branch_and_bound(closed, prove::all_obstacles(closed), generous());
        CHECK(r.outcome == Outcome::Infeasible);
        // Moving the second wall's opening to the first one's side opens a
        // way with one bend: the proof must go.
        const task::Task open = random_zigzag(seed, true);
        const auto q = prove::branch_and_bound(open, prove::all_obstacles(open), generous());
        CHECK(q.outcome == Outcome::Box);
    }
}

TEST_CASE("a 2-joint search answers infeasible from the branch and bound, naming its parts",
          "[bnb][slow]") {
    const task::Task t = zigzag();
    synth::SynthesisOptions o;
    // A budget that a loaded machine cannot exhaust (alone it takes ~1 s).
    o.time_limit = 60.0;
    o.branch_and_bound.time_limit = 30.0;
    o.branch_and_bound_share = 0.5;
    const auto s = synth::synthesize(t, o);
    REQUIRE(s.status == synth::Status::Infeasible);
    const auto& core = s.explanation.core;
    CHECK(std::find(core.begin(), core.end(), task::TaskPart::robot(task::RobotKey::Dof)) !=
          core.end());
    CHECK(std::find(core.begin(), core.end(), task::TaskPart::trajectory(0)) != core.end());
    CHECK(std::find(core.begin(), core.end(), task::TaskPart::base_regions()) != core.end());
    CHECK(std::count_if(core.begin(), core.end(), [](const task::TaskPart& p) {
              return p.kind() == task::TaskPart::Kind::Obstacle;
          }) > 10);
    CHECK(s.explanation.message.find("branch and bound") != std::string::npos);
    // With 3 joints allowed the 2-joint proof says nothing.
    task::Task more = t;
    more.robot.dof = {2, 3};
    CHECK_FALSE(prove::prove_two_joint_infeasible(more, {}).has_value());
}

namespace {

std::vector<int> core_obstacles(const std::vector<task::TaskPart>& core) {
    std::vector<int> out;
    for (const auto& p : core)
        if (p.kind() == task::TaskPart::Kind::Obstacle) out.push_back(p.index());
    std::sort(out.begin(), out.end());
    return out;
}

// Checks that `keep` is a minimal proof for `t`: the search proves the task
// among `keep` alone, and without any one of them it does not (under a
// budget no loaded machine exhausts, so that "no proof" is the obstacles'
// doing, not the clock's).
void check_minimal(const task::Task& t, const std::vector<int>& keep) {
    const auto all = prove::branch_and_bound(t, keep, generous());
    CHECK(all.outcome == Outcome::Infeasible);
    for (std::size_t k = 0; k < keep.size(); ++k) {
        std::vector<int> fewer = keep;
        fewer.erase(fewer.begin() + static_cast<long>(k));
        const auto r = prove::branch_and_bound(t, fewer, generous());
        INFO("without obstacle " << keep[k] << ": boxes " << r.boxes << ", " << r.seconds << " s");
        CHECK(r.outcome != Outcome::Infeasible);
    }
}

}  // namespace

TEST_CASE("the 2-joint proof's core is minimal: without any obstacle listed the proof breaks",
          "[bnb][slow]") {
    // One corridor whose boxes are found fast: each needed obstacle costs a
    // search that ends in a box, and on zigzag() those take minutes in all.
    for (const task::Task& t : {random_zigzag(1, false)}) {
        INFO(t.name);
        prove::BranchAndBoundOptions unshrunk = generous();
        unshrunk.core_time_limit = 0.0;
        const auto before = prove::prove_two_joint_infeasible(t, unshrunk);
        REQUIRE(before.has_value());
        CHECK_FALSE(before->minimal);
        CHECK(before->message.find("core not minimised within the time limit") !=
              std::string::npos);

        prove::BranchAndBoundOptions shrinking = generous();
        shrinking.core_time_limit = 300.0;
        shrinking.core_run_time_limit = 30.0;
        const auto after = prove::prove_two_joint_infeasible(t, shrinking);
        REQUIRE(after.has_value());
        REQUIRE(after->minimal);
        CHECK(after->message.find("not minimised") == std::string::npos);
        const auto was = core_obstacles(before->core), is = core_obstacles(after->core);
        INFO("core " << was.size() << " -> " << is.size() << " obstacles");
        CHECK(!is.empty());
        CHECK(is.size() <= was.size());
        CHECK(std::includes(was.begin(), was.end(), is.begin(), is.end()));
        check_minimal(t, is);
    }
}

TEST_CASE("a 2-joint proof out of time to shrink keeps a sound core and says so", "[bnb][slow]") {
    const task::Task t = zigzag();
    prove::BranchAndBoundOptions o = generous();
    // Far less than the proof itself takes: no time is left to shrink.
    o.core_time_limit = 1e-6;
    const auto p = prove::prove_two_joint_infeasible(t, o);
    REQUIRE(p.has_value());
    CHECK_FALSE(p->minimal);
    CHECK(p->message.find("core not minimised within the time limit") != std::string::npos);
    // What it lists still proves the task.
    const auto r = prove::branch_and_bound(t, core_obstacles(p->core), generous());
    CHECK(r.outcome == Outcome::Infeasible);
}

TEST_CASE("branch and bound core options are validated", "[bnb]") {
    prove::BranchAndBoundOptions o;
    std::string error;
    o.core_time_limit = -1.0;
    CHECK_FALSE(o.IsValid(&error));
    CHECK(error.find("core_time_limit") != std::string::npos);
    o.core_time_limit = 0.0;
    o.core_run_time_limit = 0.0;
    CHECK_FALSE(o.IsValid(&error));
    CHECK(error.find("core_run_time_limit") != std::string::npos);
    synth::SynthesisOptions s;
    CHECK(s.IsValid(&error));
    CHECK(s.branch_and_bound.core_time_limit > 0.0);
}
