#include <catch2/catch.hpp>

#include <cmath>

#include <modsynth/control/motion.h>
#include <modsynth/geometry/distance.h>
#include <modsynth/io/task_io.h>
#include <modsynth/kinematics/kinematics.h>
#include <modsynth/synth/synthesizer.h>
#include <modsynth/verify/verifier.h>

#include "../support/fixtures.h"

using namespace modsynth;

namespace {

double largest_step(const control::Sample& a, const control::Sample& b) {
    double m = 0.0;
    for (std::size_t k = 0; k < a.q.size(); ++k) m = std::max(m, std::abs(b.q[k] - a.q[k]));
    return m;
}

// A 3-joint robot whose proximal link turns by 0.6 rad between two lines.
task::Task two_lines() {
    task::Task t;
    t.trajectory.push_back(geometry::make_line({0.45, 0.00}, {0.45, 0.10}));
    t.trajectory.push_back(geometry::make_line({0.45, 0.10}, {0.35, 0.10}));
    t.robot.dof = {3};
    return t;
}

kinematics::Robot three_link() {
    kinematics::Robot r;
    r.base = {0.0, 0.0};
    r.link_lengths = {0.20, 0.18, 0.16};
    r.link_diameter = 0.03175;
    r.elbow = 1;
    r.proximal_angles = {-0.2, 0.4};
    return r;
}

}  // namespace

TEST_CASE("3-joint motion: still proximal link in traces, EE held while it sweeps", "[control]") {
    const task::Task t = two_lines();
    const auto robot = three_link();
    const auto motion = control::plan_motion(t, robot, {});
    REQUIRE(motion.has_value());
    int transitions = 0;
    for (std::size_t i = 0; i < motion->size(); ++i) {
        const auto& s = (*motion)[i];
        const auto pts = kinematics::forward(robot.base, robot.link_lengths, s.q);
        if (s.phase == control::Phase::Trace) {
            CHECK(s.q[0] == Approx(robot.proximal_angles[s.primitive]).margin(1e-12));
            CHECK(geometry::point_primitive(pts.back(), t.trajectory[s.primitive]) < 1e-9);
        } else {
            ++transitions;
            CHECK(s.primitive == 0);
            CHECK((pts.back() - t.trajectory[0].end).norm() < 1e-9);
        }
        if (i > 0) REQUIRE(largest_step((*motion)[i - 1], s) <= 0.01 + 1e-12);
    }
    CHECK(transitions >= 55);  // 0.6 rad in steps of at most 0.01
    CHECK(verify::certify(t, robot, *motion).ok);
}

TEST_CASE("a transition the distal pair cannot follow is reported", "[control]") {
    task::Task t = two_lines();
    auto robot = three_link();
    robot.proximal_angles = {-0.2, 2.6};  // sweeps the proximal link away from the point
    control::MotionFailure failure;
    CHECK_FALSE(control::plan_motion(t, robot, {}, &failure).has_value());
    CHECK(failure.transition);
    CHECK(failure.primitive == 0);
    CHECK(failure.message.find("transition after trajectory[0]") != std::string::npos);
}

TEST_CASE("path parameters recovered from joint angles match the planned ones", "[control][slow]") {
    // The rose has lines, arcs and a full circle.
    const task::Task rose = io::load_task(testing::source_path("tasks/rose.json"));
    const synth::Solution s = synth::synthesize(rose, {});
    REQUIRE(s.status == synth::Status::Solved);
    auto samples = s.samples;
    for (auto& x : samples) x.s = -1.0;
    control::recover_parameters(rose, s.robot, samples);
    for (std::size_t i = 0; i < samples.size(); ++i)
        REQUIRE(samples[i].s == Approx(s.samples[i].s).margin(1e-5));
    CHECK(verify::certify(rose, s.robot, samples).ok);

    const task::Task t = two_lines();
    const auto robot = three_link();
    auto motion = *control::plan_motion(t, robot, {});
    const auto planned = motion;
    for (auto& x : motion) x.s = -1.0;
    control::recover_parameters(t, robot, motion);
    for (std::size_t i = 0; i < motion.size(); ++i)
        REQUIRE(motion[i].s == Approx(planned[i].s).margin(1e-5));
}

TEST_CASE("times follow the slower of the EE speed and the joint speed limit", "[control]") {
    const task::Task t = testing::line_task();
    kinematics::Robot r;
    r.link_lengths = {0.30, 0.25};
    r.elbow = 1;
    auto motion = *control::plan_motion(t, r, {});
    control::MotionOptions o;
    o.ee_speed = 0.05;
    o.joint_speed = 1.0;
    control::assign_times(motion, o);
    CHECK(motion.front().t == 0.0);
    // At least the path length over the EE speed: 0.25 m at 0.05 m/s.
    CHECK(motion.back().t >= 5.0 - 1e-6);
    for (std::size_t i = 1; i < motion.size(); ++i) {
        const double dt = motion[i].t - motion[i - 1].t;
        REQUIRE(dt >= largest_step(motion[i - 1], motion[i]) / o.joint_speed - 2e-6);
        REQUIRE(dt >= (motion[i].s - motion[i - 1].s) / o.ee_speed - 2e-6);
    }
}

TEST_CASE("on a small circle a trace step is at most a quarter turn, and the verifier refuses half",
          "[control]") {
    // flag-icons' dm.svg, placed 0.25 m wide, holds circles of radius
    // 0.44 mm: 2.8 mm round, less than two of the planner's 2 mm steps, so a
    // grader unwrapping the angle between samples read a step back.
    task::Task t;
    const double r = 0.00044;
    t.trajectory.push_back(geometry::make_circle({0.35 + r, 0.0}, {0.35, 0.0}, false));
    t.robot.dof = {2};
    kinematics::Robot robot;
    robot.base = {0.0, 0.0};
    robot.link_lengths = {0.2, 0.2};
    robot.link_diameter = 0.03175;
    robot.elbow = 1;
    const auto motion = control::plan_motion(t, robot, {});
    REQUIRE(motion.has_value());
    double widest = 0.0;
    for (std::size_t i = 1; i < motion->size(); ++i)
        widest = std::max(widest, (*motion)[i].s - (*motion)[i - 1].s);
    CHECK(widest <= r * geometry::kPi / 2 + 1e-12);
    CHECK(verify::certify(t, robot, *motion).ok);
    // Every other sample left out: steps of half a turn, refused by name.
    std::vector<control::Sample> sparse;
    for (std::size_t i = 0; i < motion->size(); ++i)
        if (i % 2 == 0 || i + 1 == motion->size()) sparse.push_back((*motion)[i]);
    const auto cert = verify::certify(t, robot, sparse);
    CHECK_FALSE(cert.ok);
    bool named = false;
    for (const auto& v : cert.violations)
        named = named || v.message.find("half a turn") != std::string::npos;
    CHECK(named);
}
