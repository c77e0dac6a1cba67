#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <stdexcept>

#include <modsynth/control/joint_limits.h>
#include <modsynth/control/motion.h>
#include <modsynth/control/retime.h>
#include <modsynth/task/input_error.h>
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
    const auto traced = control::retime(sol.samples, limits, ee);
    CHECK(testing::timing_violation(traced, limits).empty());
    for (std::size_t i = 1; i < traced.size(); ++i) {
        const auto& a = traced[i - 1];
        const auto& b = traced[i];
        if (a.primitive != b.primitive) continue;
        // The EE's mean speed over the step, with a little room for the
        // tangents at the samples differing from the step's direction.
        REQUIRE(std::abs(b.s - a.s) / (b.t - a.t) <= 0.05 * 1.01);
    }
}

TEST_CASE("retiming a planned motion keeps its certificate", "[control][retime]") {
    const JointLimits limits = control::default_joint_limits(2);
    const task::Task task = testing::two_joint_task();
    const synth::Solution sol = testing::two_joint_solution(task);
    const auto timed = control::retime(sol.samples, limits);
    CHECK(testing::timing_violation(timed, limits).empty());
    REQUIRE(timed.size() == sol.samples.size());
    for (std::size_t i = 0; i < timed.size(); ++i) REQUIRE(timed[i].q == sol.samples[i].q);
    CHECK(verify::certify(task, sol.robot, timed).ok);
    // The line meets the arc at a tangent: the motion stops only where the
    // planner repeats the junction's configuration (the end of one
    // primitive and the start of the next), and nowhere else inside.
    int rests = 0, repeats = 0;
    for (std::size_t i = 1; i + 1 < timed.size(); ++i) {
        rests += at_rest(timed[i]);
        repeats += timed[i].q == timed[i + 1].q;
    }
    CHECK(rests == 2 * repeats);
    CHECK(repeats <= 1);
}

TEST_CASE("a 3-joint motion stops at both ends of its transition", "[control][retime]") {
    const task::Task task = testing::three_joint_task();
    const synth::Solution sol = testing::three_joint_solution(task);
    const JointLimits limits{{3.35, 2.0, 3.35}, {10.0, 5.0, 10.0}};
    const auto timed = control::retime(sol.samples, limits);
    CHECK(testing::timing_violation(timed, limits).empty());
    for (std::size_t i = 1; i < timed.size(); ++i) {
        if (timed[i].phase != timed[i - 1].phase) {
            CHECK(at_rest(timed[i]));
            CHECK(at_rest(timed[i - 1]));
        }
    }
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

TEST_CASE("retiming a long motion is fast", "[control][retime]") {
    // 20 000 samples along a curve: a motion as long as the shipped tasks'.
    std::vector<Sample> s;
    for (int i = 0; i <= 20000; ++i) {
        const double u = 0.0005 * i;
        s.push_back(at({std::sin(u), std::cos(1.3 * u)}));
    }
    const JointLimits limits = control::default_joint_limits(2);
    const auto t0 = std::chrono::steady_clock::now();
    const auto timed = control::retime(s, limits);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    CHECK(testing::timing_violation(timed, limits).empty());
    CHECK(ms < 500.0);
}
