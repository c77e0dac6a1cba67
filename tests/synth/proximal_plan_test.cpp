#include <modsynth/synth/proximal_plan.h>

#include <cmath>

#include <catch2/catch.hpp>

#include <modsynth/control/motion.h>
#include <modsynth/geometry/primitive.h>
#include <modsynth/verify/verifier.h>

namespace {

using namespace modsynth;
using geometry::Vec2;

// The loop of scripts/loop-tasks: a closed polygon of `n` segments, radius
// 0.3 m round a post of radius 0.05 m at its centre, 0.6 m from the base.
task::Task loop_round_post(int n) {
    task::Task t;
    t.name = "loop";
    const Vec2 c(0.6, 0.0);
    for (int k = 0; k < n; ++k) {
        const double a = geometry::kTau * k / n, b = geometry::kTau * (k + 1) / n;
        t.trajectory.push_back(
            geometry::make_line(c + 0.3 * geometry::unit(a), c + 0.3 * geometry::unit(b)));
    }
    t.obstacles.push_back({c, 0.05});
    t.base_regions.push_back({Vec2(-0.01, -0.01), Vec2(0.01, 0.01)});
    t.robot.dof = {3};
    return t;
}

kinematics::Robot design(double r1, double r2, double r3, int elbow) {
    kinematics::Robot r;
    r.link_lengths = {r1, r2, r3};
    r.link_diameter = task::RobotSpec{}.link_diameter;
    r.elbow = elbow;
    return r;
}

}  // namespace

TEST_CASE("the proximal plan takes link 1 round a post that a loop winds round, and certifies",
          "[synth]") {
    const task::Task t = loop_round_post(12);
    kinematics::Robot robot = design(0.52, 0.38, 0.57, 1);
    const synth::ProximalPlan plan = synth::plan_proximal_angles(t, robot);
    REQUIRE(plan.found);
    REQUIRE(plan.angles.size() == t.trajectory.size());
    CHECK(plan.margin >= synth::ProximalPlanOptions{}.margin);
    // No arm with link 1 still could trace the loop (the winding argument):
    // some transitions must move it, and not all need to.
    CHECK(plan.moves > 0);
    CHECK(plan.moves < 12);
    for (double a : plan.angles) {
        CHECK(a >= 0.0);
        CHECK(a < geometry::kTau);
    }
    robot.proximal_angles = plan.angles;
    control::MotionFailure failure;
    const auto motion = control::plan_motion(t, robot, control::MotionOptions{}, &failure);
    INFO(failure.message);
    REQUIRE(motion);
    const verify::Certificate cert = verify::certify(t, robot, *motion);
    CHECK(cert.ok);
    CHECK(cert.min_clearance >= 0.0);
}

TEST_CASE("the proximal plan says where no sequence of angles gets through", "[synth]") {
    const task::Task t = loop_round_post(12);
    // Link 1 too short to carry the distal pair round the post: the last
    // segment is traced clear with some angle of link 1, but no sequence of
    // sweeps from the first gets there.
    const synth::ProximalPlan plan = synth::plan_proximal_angles(t, design(0.2, 0.6, 0.45, -1));
    CHECK_FALSE(plan.found);
    CHECK(plan.angles.empty());
    CHECK(plan.blocked_primitive == 11);
    CHECK(plan.message == "no transition into trajectory[11] keeps the links clear");
    // A design that cannot reach the loop at all is stopped at its start.
    const synth::ProximalPlan far = synth::plan_proximal_angles(t, design(0.05, 0.1, 0.1, 1));
    CHECK_FALSE(far.found);
    CHECK(far.blocked_primitive == 0);
    CHECK(far.message == "no proximal angle traces trajectory[0] clear");
}

TEST_CASE("the proximal plan refuses bad options and designs", "[synth]") {
    const task::Task t = loop_round_post(4);
    synth::ProximalPlanOptions o;
    o.angles = 2;
    CHECK_THROWS_WITH(synth::plan_proximal_angles(t, design(0.3, 0.3, 0.3, 1), o),
                      Catch::Contains("ProximalPlanOptions::angles"));
    kinematics::Robot two;
    two.link_lengths = {0.5, 0.5};
    CHECK_THROWS_AS(synth::plan_proximal_angles(t, two), std::invalid_argument);
}
