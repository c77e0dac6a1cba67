#include <modsynth/io/task_io.h>
#include <modsynth/synth/branch_and_bound.h>
#include <modsynth/synth/no_go.h>
#include <modsynth/synth/obstacle_proof.h>

#include <catch2/catch.hpp>
#include <filesystem>

#include "../support/fixtures.h"

using namespace modsynth;
using geometry::Vec2;
using Outcome = synth::BranchAndBoundResult::Outcome;

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

synth::BranchAndBoundOptions generous() {
    synth::BranchAndBoundOptions o;
    o.time_limit = 30.0;
    o.max_boxes = 5000000;
    return o;
}

}  // namespace

TEST_CASE("branch and bound options are validated", "[bnb]") {
    synth::BranchAndBoundOptions o;
    std::string error;
    CHECK(o.IsValid(&error));
    o.delta = 0.0;
    CHECK_FALSE(o.IsValid(&error));
    CHECK(error.find("BranchAndBoundOptions::delta") != std::string::npos);
    CHECK_THROWS_AS(synth::branch_and_bound(zigzag(), synth::all_obstacles(zigzag()), o),
                    std::invalid_argument);
}

TEST_CASE("branch and bound proves a corridor with two bends closed to two joints", "[bnb][slow]") {
    const task::Task t = zigzag();
    // Neither a wall nor a detour proves it.
    REQUIRE_FALSE(synth::prove_obstacle_infeasible(t).has_value());
    const auto r = synth::branch_and_bound(t, synth::all_obstacles(t), generous());
    WARN("boxes " << r.boxes << ", " << r.seconds << " s");
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
    const auto r = synth::branch_and_bound(open, synth::all_obstacles(open), generous());
    WARN("boxes " << r.boxes << ", " << r.seconds << " s, violation " << r.violation);
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
            synth::BranchAndBoundOptions o;
            o.time_limit = 3.0;
            const auto r = synth::branch_and_bound(t, synth::all_obstacles(t), o);
            WARN(name << ": boxes " << r.boxes << " " << r.seconds << " s " << int(r.outcome));
            CHECK(r.outcome != Outcome::Infeasible);
            ++tried;
        }
    }
    CHECK(tried >= 10);
}
