#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <modsynth/control/joint_limits.h>
#include <modsynth/control/motion.h>
#include <modsynth/control/path_corners.h>
#include <modsynth/control/retime.h>
#include <modsynth/geometry/primitive.h>
#include <modsynth/task/input_error.h>
#include <modsynth/task/limits.h>
#include <modsynth/verify/verifier.h>

#include "../output/output_fixtures.h"
#include "timing_rules.h"

using namespace modsynth;
using control::JointLimits;
using control::Phase;
using control::Sample;

namespace {

Sample at(std::vector<double> q, Phase phase = Phase::Trace, int primitive = 0) {
    Sample s;
    s.phase = phase;
    s.primitive = primitive;
    s.q = std::move(q);
    return s;
}

/// Joint 1 from 0 to `length` in steps of `step`, joint 2 still.
std::vector<Sample> straight(double length, double step) {
    std::vector<Sample> out;
    const int n = static_cast<int>(std::round(length / step));
    for (int i = 0; i <= n; ++i) out.push_back(at({length * i / n, 0.2}));
    return out;
}

bool at_rest(const Sample& s) {
    for (double v : s.qd)
        if (std::abs(v) > 1e-12) return false;
    return true;
}

}  // namespace

TEST_CASE("a straight joint move takes the trapezoid's time", "[control][retime]") {
    const JointLimits limits{{2.0, 2.0}, {4.0, 4.0}};
    const auto samples = straight(3.0, 0.01);
    control::RetimeStats stats;
    const auto timed = control::retime(samples, limits, {}, &stats);
    REQUIRE(timed.size() == samples.size());
    CHECK(testing::timing_violation(timed, limits).empty());
    // Accelerate 0.5 s to 2 rad/s (0.5 rad), cruise 2 rad in 1 s, brake 0.5 s.
    CHECK(stats.duration == Approx(2.0).epsilon(0.01));
    CHECK(stats.duration >= 2.0 - 1e-9);  // nothing beats the limits
    CHECK(timed.front().t == 0.0);
    CHECK(stats.rests == 2);
    double fastest = 0.0;
    for (const auto& s : timed) fastest = std::max(fastest, std::abs(s.qd[0]));
    CHECK(fastest == Approx(2.0).epsilon(1e-9));
    for (std::size_t i = 0; i < samples.size(); ++i) REQUIRE(timed[i].q == samples[i].q);
}

TEST_CASE("a short move never reaches full speed and stays consistent", "[control][retime]") {
    const JointLimits limits{{2.0, 2.0}, {4.0, 4.0}};
    const auto timed = control::retime(straight(0.04, 0.01), limits);
    CHECK(testing::timing_violation(timed, limits).empty());
    // Bang-bang over 0.04 rad at 4 rad/s^2: 2 sqrt(0.04 / 4) = 0.2 s.
    CHECK(timed.back().t == Approx(0.2).epsilon(0.05));
}

TEST_CASE("the motion stops at a corner of the joint path", "[control][retime]") {
    std::vector<Sample> s;
    for (int i = 0; i <= 50; ++i) s.push_back(at({0.01 * i, 0.0}));
    for (int i = 1; i <= 50; ++i) s.push_back(at({0.5, 0.01 * i}));
    const JointLimits limits = control::default_joint_limits(2);
    control::RetimeStats stats;
    const auto timed = control::retime(s, limits, {}, &stats);
    CHECK(testing::timing_violation(timed, limits).empty());
    CHECK(at_rest(timed[50]));
    CHECK_FALSE(at_rest(timed[25]));
    CHECK(stats.rests == 3);
}

TEST_CASE("each joint keeps its own limits", "[control][retime]") {
    std::vector<Sample> s;
    for (int i = 0; i <= 300; ++i) s.push_back(at({0.01 * i, -0.01 * i}));
    const JointLimits limits{{3.0, 1.0}, {10.0, 2.0}};
    const auto timed = control::retime(s, limits);
    CHECK(testing::timing_violation(timed, limits).empty());
    double fastest = 0.0;
    for (const auto& x : timed) fastest = std::max(fastest, std::abs(x.qd[1]));
    CHECK(fastest == Approx(1.0).epsilon(1e-6));  // the slow joint decides
    // 3 rad at 1 rad/s with 0.5 s ramps at 2 rad/s^2: 3.5 s.
    CHECK(timed.back().t == Approx(3.5).epsilon(0.01));
}

TEST_CASE("repeated samples and single samples are timed", "[control][retime]") {
    const JointLimits limits = control::default_joint_limits(2);
    auto s = straight(0.5, 0.01);
    s.insert(s.begin() + 20, s[20]);  // a step that does not move
    const auto timed = control::retime(s, limits);
    CHECK(testing::timing_violation(timed, limits).empty());
    CHECK(at_rest(timed[20]));
    CHECK(at_rest(timed[21]));
    const auto one = control::retime({at({0.1, 0.2})}, limits);
    REQUIRE(one.size() == 1);
    CHECK(one[0].t == 0.0);
    CHECK(at_rest(one[0]));
    CHECK(control::retime({}, limits).empty());
}

TEST_CASE("the EE and joint speed caps slow the motion down", "[control][retime]") {
    const JointLimits limits = control::default_joint_limits(2);
    const auto fast = control::retime(straight(3.0, 0.01), limits);
    control::RetimeOptions capped;
    capped.joint_speed = 1.0;
    const auto slow = control::retime(straight(3.0, 0.01), limits, capped);
    CHECK(testing::timing_violation(slow, {{1.0, 1.0}, limits.acceleration}).empty());
    CHECK(slow.back().t > fast.back().t + 1.5);

    const task::Task task = testing::two_joint_task();
    const synth::Solution sol = testing::two_joint_solution(task);
    control::RetimeOptions ee;
    ee.ee_speed = 0.05;
    control::RetimeStats stats;
    const auto traced = control::retime_for(task, sol.samples, limits, ee, &stats);
    CHECK(testing::timing_violation(traced, limits).empty());
    int even = 0;
    for (std::size_t i = 1; i < traced.size(); ++i) {
        const auto& a = traced[i - 1];
        const auto& b = traced[i];
        const double ds = a.primitive == b.primitive ? std::abs(b.s - a.s) : b.s;
        // The EE's mean speed over the step: at most the speed asked for,
        // and exactly it away from the ramps at both ends.
        const double v = ds / (b.t - a.t);
        REQUIRE(v <= 0.05 * (1.0 + 1e-3));
        even += v >= 0.05 * (1.0 - 1e-3);
    }
    CHECK(even >= static_cast<int>(traced.size()) * 9 / 10);
    CHECK(stats.slow.empty());
    CHECK(stats.traced_seconds == Approx(stats.duration));

    // Joints too slow for 1 m/s along the whole path: the stretches where
    // the limits hold the EE back are reported, the ramps are not.
    control::RetimeOptions quick;
    quick.ee_speed = 1.0;
    const JointLimits slow_joints{{0.5, 0.5}, {10.0, 10.0}};
    const auto held = control::retime_for(task, sol.samples, slow_joints, quick, &stats);
    CHECK(testing::timing_violation(held, slow_joints).empty());
    REQUIRE_FALSE(stats.slow.empty());
    for (const auto& st : stats.slow) {
        CHECK(st.first <= st.last);
        CHECK(st.slowest < 1.0);
        CHECK(st.limit == "velocity");
    }
    CHECK(stats.slow_seconds > 0.3 * stats.duration);
}

TEST_CASE("retiming a planned motion keeps its certificate", "[control][retime]") {
    const JointLimits limits = control::default_joint_limits(2);
    const task::Task task = testing::two_joint_task();
    const synth::Solution sol = testing::two_joint_solution(task);
    control::RetimeStats stats;
    const auto timed = control::retime_for(task, sol.samples, limits, {}, &stats);
    CHECK(testing::timing_violation(timed, limits).empty());
    REQUIRE(timed.size() == sol.samples.size());
    for (std::size_t i = 0; i < timed.size(); ++i) REQUIRE(timed[i].q == sol.samples[i].q);
    CHECK(verify::certify(task, sol.robot, timed).ok);
    // The line meets the arc at a tangent: the motion goes through the
    // junction without stopping, and stops nowhere else inside.
    for (std::size_t i = 1; i + 1 < timed.size(); ++i) REQUIRE_FALSE(at_rest(timed[i]));
    CHECK(stats.rests == 2);
}

TEST_CASE("the motion stops at a corner of the task's path", "[control][retime]") {
    task::Task task = testing::two_joint_task();
    // The arc turned the other way round: the path turns by 90 degrees
    // where it begins.
    task.trajectory[1] = geometry::make_arc({0.40, 0.30}, {0.30, 0.40}, {0.40, 0.40}, false);
    const synth::Solution sol = testing::two_joint_solution(task);
    const auto corners = control::path_corners(task, sol.samples);
    REQUIRE(corners.size() == 1);
    const Sample& junction = sol.samples[corners[0]];
    CHECK(junction.primitive == 0);
    CHECK(junction.s == Approx(geometry::length(task.trajectory[0])));
    const JointLimits limits = control::default_joint_limits(2);
    control::RetimeStats stats;
    const auto timed = control::retime_for(task, sol.samples, limits, {}, &stats);
    CHECK(testing::timing_violation(timed, limits).empty());
    CHECK(at_rest(timed[corners[0]]));
    CHECK(stats.rests == 3);
    // Without the task's corners only the joint path's own would stop it.
    CHECK(control::path_corners(testing::two_joint_task(), sol.samples).empty());
}

TEST_CASE("a joint-space circle is followed at the speed its turning allows", "[control][retime]") {
    // q on a circle of radius R: the acceleration v^2 / R points at the
    // centre, and joint k carries v^2 / R |cos|, so the fastest steady
    // speed is sqrt(A R) (velocity limits out of the way).
    const double r = 0.5, a = 2.0;
    std::vector<Sample> s;
    const int n = 2000;
    for (int i = 0; i <= n; ++i) {
        const double th = 4.0 * std::numbers::pi * i / n;  // two turns
        s.push_back(at({r * std::cos(th), r * std::sin(th)}));
    }
    const JointLimits limits{{100.0, 100.0}, {a, a}};
    const auto timed = control::retime(s, limits);
    CHECK(testing::timing_violation(timed, limits).empty());
    // Along the middle the speed is within a few per cent of the bound
    // (the bound holds for the steepest joint only at the axes).
    const double steady = std::sqrt(a * r);
    double slowest = 1e9, fastest = 0.0;
    for (int i = n / 4; i <= 3 * n / 4; ++i) {
        const double v = std::hypot(timed[i].qd[0], timed[i].qd[1]);
        slowest = std::min(slowest, v);
        fastest = std::max(fastest, v);
    }
    CHECK(slowest >= steady * 0.98);
    CHECK(fastest <= steady * 1.2);
}

TEST_CASE("a 3-joint motion stops at both ends of its transition", "[control][retime]") {
    const task::Task task = testing::three_joint_task();
    const synth::Solution sol = testing::three_joint_solution(task);
    const JointLimits limits{{3.35, 2.0, 3.35}, {10.0, 5.0, 10.0}};
    control::RetimeStats stats;
    const auto timed = control::retime(sol.samples, limits, {}, &stats);
    CHECK(testing::timing_violation(timed, limits).empty());
    // At the traced sample where the transition begins and the one where it
    // ends (the EE's point, where the joint path turns), and nowhere else.
    int changes = 0;
    for (std::size_t i = 1; i < timed.size(); ++i) {
        if (timed[i].phase == timed[i - 1].phase) continue;
        ++changes;
        CHECK(at_rest(timed[i].phase == Phase::Trace ? timed[i] : timed[i - 1]));
        CHECK_FALSE(at_rest(timed[i].phase == Phase::Trace ? timed[i - 1] : timed[i]));
    }
    CHECK(changes == 2);
    CHECK(stats.rests == 4);
}

TEST_CASE("a step too long to measure is timed from rest to rest", "[control][retime]") {
    // Angles near the largest double, as a hostile file may hold: the
    // step's length overflows, its time must not.
    auto s = straight(0.2, 0.01);
    s[10].q = {1e300, -1e300};
    const JointLimits limits = control::default_joint_limits(2);
    const auto timed = control::retime(s, limits);
    for (const auto& x : timed) REQUIRE(std::isfinite(x.t));
    CHECK(at_rest(timed[9]));
    CHECK(at_rest(timed[10]));
    CHECK(at_rest(timed[11]));
}

TEST_CASE("retime refuses bad limits and options", "[control][retime]") {
    const auto s = straight(0.1, 0.01);
    CHECK_THROWS_AS(control::retime(s, {{1.0, 0.0}, {1.0, 1.0}}), std::invalid_argument);
    CHECK_THROWS_AS(control::retime(s, {{1.0, 1.0}, {1.0, NAN}}), std::invalid_argument);
    CHECK_THROWS_AS(control::retime(s, control::default_joint_limits(3)), std::invalid_argument);
    control::RetimeOptions bad;
    bad.ee_speed = 0.0;
    CHECK_THROWS_WITH(control::retime(s, control::default_joint_limits(2), bad),
                      Catch::Contains("RetimeOptions::ee_speed"));
}

TEST_CASE("joint limits come from the task or the modules", "[control][retime]") {
    task::Task task = testing::two_joint_task();
    const JointLimits d = control::joint_limits_for(task, 3);
    CHECK(d.velocity == std::vector<double>(3, control::kDefaultJointSpeed));
    CHECK(d.acceleration == std::vector<double>(3, control::kDefaultJointAcceleration));
    task.robot.joint_limits = task::JointLimitsSpec{{2.0}, {1.0, 2.0}};
    const JointLimits l = control::joint_limits_for(task, 2);
    CHECK(l.velocity == std::vector<double>{2.0, 2.0});
    CHECK(l.acceleration == std::vector<double>{1.0, 2.0});
    CHECK_THROWS_WITH(control::joint_limits_for(task, 3),
                      Catch::StartsWith("robot.joint_limits.acceleration: has 2 values"));
}

TEST_CASE("a long motion is timed in one pass", "[control][retime]") {
    // 20 000 samples along a curve: a motion as long as the shipped tasks'.
    // (How long retiming takes: the `timed:` line of solve, scripts/bench --motion.)
    std::vector<Sample> s;
    for (int i = 0; i <= 20000; ++i) {
        const double u = 0.0005 * i;
        s.push_back(at({std::sin(u), std::cos(1.3 * u)}));
    }
    const JointLimits limits = control::default_joint_limits(2);
    control::RetimeStats stats;
    const auto timed = control::retime(s, limits, {}, &stats);
    CHECK(testing::timing_violation(timed, limits).empty());
    CHECK(stats.passes == 1);
    CHECK(stats.rests == 2);
}

TEST_CASE("with jerk limits the motion is an S-curve within them", "[control][retime][jerk]") {
    JointLimits limits{{2.0, 2.0}, {4.0, 4.0}, {20.0, 20.0}};
    const auto samples = straight(3.0, 0.01);
    control::RetimeStats stats;
    const auto timed = control::retime(samples, limits, {}, &stats);
    CHECK(testing::timing_violation(timed, limits).empty());
    CHECK(testing::jerk_violation(timed, limits.jerk).empty());
    // Seven phases: jerk up to 4 rad/s^2 in 0.2 s, and so on: 3 rad at
    // 2 rad/s, plus a ramp of V / A + A / J = 0.7 s: 2.2 s.
    CHECK(stats.duration >= 2.2 * 0.98);  // the rules between samples, not a continuum
    CHECK(stats.duration <= 2.2 * 1.03);
    for (std::size_t i = 0; i < samples.size(); ++i) REQUIRE(timed[i].q == samples[i].q);
    CHECK(timed.front().qdd[0] == 0.0);
    CHECK(timed.back().qdd[0] == 0.0);
}

TEST_CASE("jerk limits hold along planned motions of two and three joints",
          "[control][retime][jerk]") {
    {
        const task::Task task = testing::two_joint_task();
        const synth::Solution sol = testing::two_joint_solution(task);
        const JointLimits limits{{1.2, 1.2}, {3.0, 3.0}, {15.0, 15.0}};
        control::RetimeStats stats, plain;
        const auto timed = control::retime_for(task, sol.samples, limits, {}, &stats);
        CHECK(testing::timing_violation(timed, limits).empty());
        CHECK(testing::jerk_violation(timed, limits.jerk).empty());
        CHECK(stats.rests == 2);
        control::retime_for(task, sol.samples, {limits.velocity, limits.acceleration}, {}, &plain);
        CHECK(stats.duration >= plain.duration);
        CHECK(stats.duration <= 2.0 * plain.duration);
    }
    {
        const task::Task task = testing::three_joint_task();
        const synth::Solution sol = testing::three_joint_solution(task);
        const JointLimits limits{{3.35, 2.0, 3.35}, {10.0, 5.0, 10.0}, {40.0, 20.0, 40.0}};
        const auto timed = control::retime(sol.samples, limits);
        CHECK(testing::timing_violation(timed, limits).empty());
        CHECK(testing::jerk_violation(timed, limits.jerk).empty());
    }
}

TEST_CASE("speed caps lie in the range of the joint limits", "[control][retime]") {
    const auto s = straight(0.1, 0.01);
    // 1e-9 rad/s would make a motion of centuries; 1e-300 would drop out
    // of the arithmetic and leave every qd 0 while the joints move.
    for (const double cap : {1e-9, 1e-300, 1e7}) {
        control::RetimeOptions o;
        o.joint_speed = cap;
        CHECK_THROWS_WITH(control::retime(s, control::default_joint_limits(2), o),
                          Catch::Contains("RetimeOptions::joint_speed"));
        control::RetimeOptions e;
        e.ee_speed = cap;
        CHECK_THROWS_WITH(control::retime(s, control::default_joint_limits(2), e),
                          Catch::Contains("RetimeOptions::ee_speed"));
    }
    control::RetimeOptions slowest;
    slowest.joint_speed = task::kMinJointLimit;
    const auto timed = control::retime(s, control::default_joint_limits(2), slowest);
    CHECK(timed.back().t > 0.1 / task::kMinJointLimit * 0.99);
    CHECK(timed.back().t <= task::kLongestMotion);
}

TEST_CASE("timing_fault names where a timed motion breaks the limits", "[control][retime]") {
    JointLimits limits{{2.0, 2.0}, {4.0, 4.0}, {20.0, 20.0}};
    const auto timed = control::retime(straight(3.0, 0.01), limits);
    CHECK(control::timing_fault(timed, limits).empty());
    // The same motion against a far smaller jerk: the rules between samples
    // break (a controller would be handed 20 rad/s^3 for 1e-6).
    JointLimits gentle = limits;
    gentle.jerk = {1e-6, 1e-6};
    CHECK_THAT(control::timing_fault(timed, gentle), Catch::Contains("its jerk"));
    auto edited = timed;
    edited[5].qdd[1] = 9.0;
    CHECK_THAT(control::timing_fault(edited, limits),
               Catch::StartsWith("samples[5]: joint 2's acceleration 9 rad/s^2 is over its 4"));
    auto moving = timed;
    moving.back().qd[0] = 0.5;
    CHECK_THAT(control::timing_fault(moving, limits), Catch::Contains("not at rest"));
    const auto untimed = straight(0.1, 0.01);
    CHECK_FALSE(control::timing_fault(untimed, limits).empty());
}
