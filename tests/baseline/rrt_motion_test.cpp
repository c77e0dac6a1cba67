#include <catch2/catch.hpp>

#include <cmath>

#include <modsynth/baseline/fidelity.h>
#include <modsynth/baseline/rrt_motion.h>
#include <modsynth/kinematics/pose_clearance.h>

#include "../support/fixtures.h"

using namespace modsynth;
using geometry::kPi;

namespace {

// Link 1 must turn from -1 rad to +1 rad, and an obstacle sits on its
// sweep at angle 0: the only way is the long way round, through pi.
struct Detour {
    task::Task task = testing::line_task();
    kinematics::Robot robot;
    std::vector<std::vector<double>> poses{{-1.0, 0.3}, {1.0, 0.3}};
    Detour() {
        task.obstacles = {{{0.15, 0.0}, 0.03}};
        robot.base = {0.0, 0.0};
        robot.link_lengths = {0.3, 0.2};
        robot.link_diameter = 0.02;
    }
};

}  // namespace

TEST_CASE("RRT goes round an obstacle that blocks the straight joint motion", "[baseline]") {
    const Detour d;
    REQUIRE(kinematics::pose_clearance(d.task.obstacles, d.robot, std::vector<double>{0.0, 0.3})
                .obstacles < 0.0);
    const baseline::PlannedMotion m = baseline::plan_rrt(d.task, d.robot, d.poses, {});
    REQUIRE(m.complete);
    REQUIRE(m.waypoints.size() >= 2);
    CHECK(m.waypoints.front() == d.poses.front());
    // It ends at the goal, reached the long way: q1 = 1 - 2 pi.
    CHECK(m.waypoints.back()[0] == Approx(1.0 - 2.0 * kPi).margin(1e-9));
    CHECK(m.waypoints.back()[1] == Approx(0.3).margin(1e-9));
    for (const auto& q : m.waypoints)
        CHECK(kinematics::pose_clearance(d.task.obstacles, d.robot, q).worst() >= 0.0);
    // Between waypoints too (checked at 5 mrad; allow what a step can hide).
    const baseline::Fidelity f = baseline::measure_fidelity(d.task, d.robot, m.waypoints);
    CHECK(f.min_clearance > -0.002);
}

TEST_CASE("RRT plans are repeatable for a seed", "[baseline]") {
    const Detour d;
    baseline::PlannerOptions o;
    o.shortcut = false;
    const auto a = baseline::plan_rrt(d.task, d.robot, d.poses, o);
    const auto b = baseline::plan_rrt(d.task, d.robot, d.poses, o);
    REQUIRE(a.complete);
    CHECK(a.waypoints == b.waypoints);
    CHECK(a.iterations == b.iterations);
}

TEST_CASE("RRT reports the pair it cannot connect", "[baseline]") {
    Detour d;
    // A second obstacle closes the long way round as well.
    d.task.obstacles.push_back({{-0.15, 0.0}, 0.03});
    baseline::PlannerOptions o;
    o.max_iterations = 2000;
    const auto m = baseline::plan_rrt(d.task, d.robot, d.poses, o);
    CHECK_FALSE(m.complete);
    CHECK(m.failed_pair == 0);
    CHECK(m.message.find("point 0 to point 1") != std::string::npos);
}
