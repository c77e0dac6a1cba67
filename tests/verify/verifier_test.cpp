#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include <modsynth/control/motion.h>
#include <modsynth/geometry/distance.h>
#include <modsynth/geometry/primitive.h>
#include <modsynth/kinematics/kinematics.h>
#include <modsynth/verify/verifier.h>

#include "../support/fixtures.h"

using namespace modsynth;
using verify::Violation;

namespace {

bool has(const verify::Certificate& c, Violation::Kind kind) {
    return std::any_of(c.violations.begin(), c.violations.end(),
                       [&](const Violation& v) { return v.kind == kind; });
}

std::vector<control::Sample> motion_for(const task::Task& t, const kinematics::Robot& r) {
    auto m = control::plan_motion(t, r, {});
    REQUIRE(m.has_value());
    return *m;
}

}  // namespace

TEST_CASE("a clear motion is certified, with margins that match the geometry", "[verify]") {
    task::Task t = testing::line_task();
    t.obstacles.push_back({{0.0, 0.45}, 0.05});
    const auto robot = testing::line_robot();
    const auto samples = motion_for(t, robot);
    const auto cert = verify::certify(t, robot, samples);
    INFO((cert.violations.empty() ? "" : cert.violations.front().message));
    CHECK(cert.ok);
    CHECK(cert.violations.empty());
    CHECK(cert.max_deviation < 1e-4);
    CHECK(cert.max_joint_step <= 0.01 + 1e-12);
    CHECK(std::isfinite(cert.min_clearance));
    CHECK(cert.min_clearance > 0.0);
}

TEST_CASE("the certified clearance never exceeds the clearance of the replayed motion",
          "[verify]") {
    // Soundness of the between-sample bound: replay the joint-linear motion
    // at 50 sub-steps per pair and compare.
    task::Task t = testing::line_task();
    t.obstacles.push_back({{0.12, 0.30}, 0.04});
    t.obstacles.push_back({{0.30, 0.36}, 0.02});
    const auto robot = testing::line_robot();
    const auto samples = motion_for(t, robot);
    const auto cert = verify::certify(t, robot, samples);
    double replayed = 1e9, replayed_self = 1e9;
    for (std::size_t i = 0; i + 1 < samples.size(); ++i) {
        for (int k = 0; k <= 50; ++k) {
            const double u = k / 50.0;
            std::vector<double> q(2);
            for (int j = 0; j < 2; ++j) q[j] = (1 - u) * samples[i].q[j] + u * samples[i + 1].q[j];
            const auto pts = kinematics::forward(robot.base, robot.link_lengths, q);
            for (const auto& ob : t.obstacles)
                for (int l = 0; l < 2; ++l)
                    replayed =
                        std::min(replayed, geometry::point_segment(ob.center, pts[l], pts[l + 1]) -
                                               ob.radius - robot.link_diameter / 2);
            replayed_self =
                std::min(replayed_self,
                         geometry::point_segment(pts[2], pts[0], pts[1]) - robot.link_diameter);
        }
    }
    CHECK(cert.min_clearance <= replayed + 1e-12);
    CHECK(cert.min_self_clearance <= replayed_self + 1e-12);
    // ...and it is tight: the bound costs well under a millimetre.
    CHECK(cert.min_clearance > replayed - 5e-4);
}

TEST_CASE("an obstacle on the arm is a clearance violation located on the path", "[verify]") {
    task::Task t = testing::line_task();
    const auto robot = testing::line_robot();
    const auto samples = motion_for(t, robot);
    // Put an obstacle on link 1 of the pose half-way along the line.
    const auto& mid = samples[samples.size() / 2];
    const auto pts = kinematics::forward(robot.base, robot.link_lengths, mid.q);
    t.obstacles.push_back({0.5 * (pts[0] + pts[1]), 0.01});
    const auto cert = verify::certify(t, robot, samples);
    CHECK_FALSE(cert.ok);
    REQUIRE(has(cert, Violation::Kind::Clearance));
    const auto v =
        *std::find_if(cert.violations.begin(), cert.violations.end(),
                      [](const Violation& x) { return x.kind == Violation::Kind::Clearance; });
    CHECK(v.primitive == 0);
    CHECK(v.obstacle == 0);
    CHECK(v.link == 0);
    CHECK(v.amount > 0.0);
}

TEST_CASE("structural violations: base outside the regions, link too long, wrong dof", "[verify]") {
    task::Task t = testing::line_task();
    auto robot = testing::line_robot();
    const auto samples = motion_for(t, robot);
    robot.base = {0.2, 0.2};
    CHECK(has(verify::certify(t, robot, samples), Violation::Kind::Structure));
    robot = testing::line_robot();
    t.robot.max_link_length = 0.28;
    CHECK(has(verify::certify(t, robot, samples), Violation::Kind::Structure));
    t = testing::line_task();
    t.robot.dof = {3};
    CHECK(has(verify::certify(t, robot, samples), Violation::Kind::Structure));
}

TEST_CASE("sparse samples are flagged: large joint steps and skipped progress", "[verify]") {
    const task::Task t = testing::line_task();
    const auto robot = testing::line_robot();
    auto samples = motion_for(t, robot);
    std::vector<control::Sample> sparse;
    for (std::size_t i = 0; i < samples.size(); i += 20) sparse.push_back(samples[i]);
    sparse.push_back(samples.back());
    const auto cert = verify::certify(t, robot, sparse);
    CHECK_FALSE(cert.ok);
    CHECK((has(cert, Violation::Kind::JointStep) || has(cert, Violation::Kind::Order)));
}

TEST_CASE("a motion that stops short of a primitive's end is not accepted", "[verify]") {
    const task::Task t = testing::line_task();
    const auto robot = testing::line_robot();
    auto samples = motion_for(t, robot);
    samples.resize(samples.size() - 3);
    CHECK(has(verify::certify(t, robot, samples), Violation::Kind::Order));
}

TEST_CASE("the EE too close to link 1 is a self-collision", "[verify]") {
    // Links 0.30 and 0.25, EE 0.055 m from the base: the triangle's height
    // over link 1 is about 0.021 m, less than the 0.032 m tube.
    task::Task t;
    t.trajectory.push_back(geometry::make_line({0.055, -0.02}, {0.055, 0.02}));
    t.robot.dof = {2};
    const auto robot = testing::line_robot();
    const auto samples = motion_for(t, robot);
    const auto cert = verify::certify(t, robot, samples);
    CHECK(has(cert, Violation::Kind::SelfCollision));
}

TEST_CASE("refining coarse pairs keeps the motion on the path", "[verify]") {
    const task::Task t = testing::line_task();
    const auto robot = testing::line_robot();
    auto samples = motion_for(t, robot);
    const std::size_t before = samples.size();
    REQUIRE(control::refine_motion(t, robot, samples, {0, 5, 10}));
    CHECK(samples.size() == before + 3);
    CHECK(verify::certify(t, robot, samples).ok);
}

TEST_CASE("a junction without a transition repeats no pose and is certified", "[verify]") {
    // A line and an arc that goes on tangent to it.
    task::Task t = testing::line_task();
    t.trajectory[0] = geometry::make_line({0.40, 0.05}, {0.40, 0.20});
    t.trajectory.push_back(geometry::make_arc({0.40, 0.20}, {0.30, 0.30}, {0.30, 0.20}, true));
    const auto robot = testing::line_robot();
    const auto samples = motion_for(t, robot);
    std::size_t junction = 0;
    for (std::size_t i = 0; i + 1 < samples.size(); ++i) {
        REQUIRE(samples[i].q != samples[i + 1].q);
        if (samples[i].primitive == 0 && samples[i + 1].primitive == 1) junction = i;
    }
    REQUIRE(junction > 0);
    CHECK(samples[junction].s == Approx(geometry::length(t.trajectory[0])));
    CHECK(samples[junction + 1].s == Approx(control::MotionOptions{}.junction_step));
    CHECK(verify::certify(t, robot, samples).ok);

    // The pair across the junction is split on the primitive that begins
    // there.
    auto refined = samples;
    REQUIRE(control::refine_motion(t, robot, refined, {static_cast<int>(junction)}));
    CHECK(refined[junction + 1].primitive == 1);
    CHECK(refined[junction + 1].s == Approx(0.5 * samples[junction + 1].s));
    CHECK(verify::certify(t, robot, refined).ok);

    // A trace may begin past its start only right after the primitive
    // before it, and by no more than a progress step.
    auto late = samples;
    late.erase(late.begin());
    CHECK(has(verify::certify(t, robot, late), Violation::Kind::Order));
    auto far = samples;
    const auto after = far.begin() + static_cast<long>(junction) + 1;
    far.erase(after, after + 4);  // primitive 1 begins 7.5 mm past its start
    CHECK(has(verify::certify(t, robot, far), Violation::Kind::Order));
}
