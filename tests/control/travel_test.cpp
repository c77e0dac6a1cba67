// Travel between strokes: a certified joint-space motion, straight when a
// line is clear, planned round obstacles when none is; and the motion and
// verification of a task of several strokes.
#include <catch2/catch.hpp>

#include "../support/fixtures.h"

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include <modsynth/control/motion.h>
#include <modsynth/control/travel.h>
#include <modsynth/io/solution_io.h>
#include <modsynth/kinematics/kinematics.h>
#include <modsynth/kinematics/motion_clearance.h>
#include <modsynth/kinematics/pose_clearance.h>
#include <modsynth/task/strokes.h>
#include <modsynth/verify/verifier.h>

using namespace modsynth;

namespace {

double largest_change(const std::vector<double>& a, const std::vector<double>& b) {
    double m = 0.0;
    for (std::size_t k = 0; k < a.size(); ++k) m = std::max(m, std::abs(b[k] - a[k]));
    return m;
}

// Every step of the plan is short and certified clear.
void check_certified(const task::Task& t, const kinematics::Robot& robot,
                     const std::vector<double>& from, const control::TravelPlan& plan) {
    std::vector<double> prev = from;
    for (const auto& q : plan.poses) {
        CHECK(largest_change(prev, q) <= 0.01 + 1e-12);
        CHECK(kinematics::linear_motion_clearance(t.obstacles, robot, prev, q).worst() >= 0.0);
        prev = q;
    }
}

// Two short strokes on either side of the base.
task::Task two_strokes() {
    task::Task t;
    t.trajectory.push_back(geometry::make_line({0.45, 0.05}, {0.45, 0.10}));
    t.trajectory.push_back(geometry::make_line({0.45, 0.10}, {0.40, 0.10}));
    t.trajectory.push_back(geometry::make_line({-0.45, 0.10}, {-0.45, 0.05}));
    t.stroke_starts = {0, 2};
    t.robot.dof = {2};
    return t;
}

}  // namespace

TEST_CASE("travel: a clear straight line is taken as it is", "[control][travel]") {
    task::Task t;
    const auto robot = testing::line_robot();
    const std::vector<double> from{0.1, 0.5}, to{0.6, 0.2};
    const auto plan = control::plan_travel(t, robot, from, to, {});
    REQUIRE(plan);
    CHECK(plan->method == "straight");
    REQUIRE(!plan->poses.empty());
    CHECK(largest_change(plan->poses.back(), to) < 1e-12);
    CHECK(plan->poses.size() == 50);  // 0.5 rad in steps of 0.01
    check_certified(t, robot, from, *plan);
}

TEST_CASE("travel: the other way round when the short way is blocked", "[control][travel]") {
    task::Task t;
    // Above the base, in the way of the stretched arm turning ccw.
    t.obstacles.push_back({{0.0, 0.45}, 0.05});
    const auto robot = testing::line_robot();
    const std::vector<double> from{0.2, 0.3}, to{2.9, 0.3};
    const auto plan = control::plan_travel(t, robot, from, to, {});
    REQUIRE(plan);
    CHECK(plan->method == "straight");
    // Joint 1 ends a whole turn below `to`: it went clockwise.
    CHECK(plan->poses.back()[0] == Approx(to[0] - geometry::kTau).margin(1e-9));
    CHECK(plan->poses.back()[1] == Approx(to[1]).margin(1e-9));
    check_certified(t, robot, from, *plan);
}

TEST_CASE("travel: planned round obstacles when every straight line collides",
          "[control][travel]") {
    task::Task t;
    // Posts above and below the base: the stretched arm cannot turn either
    // way, a folded one passes.
    t.obstacles.push_back({{0.0, 0.45}, 0.05});
    t.obstacles.push_back({{0.0, -0.45}, 0.05});
    kinematics::Robot robot = testing::line_robot();
    robot.link_lengths = {0.25, 0.25};
    const std::vector<double> from{0.1, 0.3}, to{3.0, 0.3};
    const auto plan = control::plan_travel(t, robot, from, to, {});
    REQUIRE(plan);
    CHECK(plan->method == "planned");
    const auto& end = plan->poses.back();
    for (std::size_t k = 0; k < end.size(); ++k) {
        const double turns = (end[k] - to[k]) / geometry::kTau;
        CHECK(std::abs(turns - std::round(turns)) < 1e-9);
    }
    check_certified(t, robot, from, *plan);
}

TEST_CASE("travel: none when the goal pose itself collides", "[control][travel]") {
    task::Task t;
    t.obstacles.push_back({{0.55, 0.0}, 0.05});
    control::TravelOptions o;
    o.plan_seconds = 0.2;
    CHECK_FALSE(control::plan_travel(t, testing::line_robot(), {1.5, 0.2}, {0.0, 0.0}, o));
}

TEST_CASE("strokes: each stroke traced, travel between, certified", "[control][travel]") {
    task::Task t = two_strokes();
    t.obstacles.push_back({{0.0, 0.5}, 0.05});
    const auto robot = testing::line_robot();
    control::MotionFailure failure;
    auto motion = control::plan_motion(t, robot, {}, &failure);
    INFO(failure.message);
    REQUIRE(motion);
    int travel = 0, last_stroke = 0;
    for (std::size_t i = 0; i < motion->size(); ++i) {
        const auto& s = (*motion)[i];
        CHECK(s.stroke >= last_stroke);
        last_stroke = s.stroke;
        if (s.phase == control::Phase::Travel) {
            ++travel;
            CHECK(s.stroke == 0);
            CHECK(s.primitive == 1);  // the last of stroke 0
        } else {
            CHECK(s.phase == control::Phase::Trace);
        }
        if (i > 0) CHECK(largest_change((*motion)[i - 1].q, s.q) <= 0.01 + 1e-12);
    }
    CHECK(travel > 100);
    CHECK(motion->back().stroke == 1);
    CHECK(motion->back().primitive == 0);
    const verify::Certificate c = verify::certify(t, robot, *motion);
    INFO((c.violations.empty() ? std::string() : c.violations.front().message));
    CHECK(c.ok);
    CHECK(c.min_clearance >= 0.0);

    SECTION("the solution round-trips with stroke, and certifies again") {
        synth::Solution s;
        s.status = synth::Status::Solved;
        s.robot = robot;
        s.samples = *motion;
        control::assign_times(s.samples, {});
        const auto doc = io::to_json(s);
        CHECK(doc["samples"][0]["stroke"] == 0);
        CHECK(doc["samples"].back()["stroke"] == 1);
        auto back = io::parse_solution(doc).solution;
        io::check_solution_fits(t, back);
        control::recover_parameters(t, back.robot, back.samples);
        CHECK(verify::certify(t, back.robot, back.samples).ok);
    }
    SECTION("a travel sample moved into a stroke is out of order") {
        auto bad = *motion;
        bad[3].phase = control::Phase::Travel;
        const auto c2 = verify::certify(t, robot, bad);
        CHECK_FALSE(c2.ok);
    }
    SECTION("a travel through an obstacle is a clearance violation in travel") {
        task::Task blocked = t;
        std::size_t mid = 0;
        for (std::size_t i = 0; i < motion->size(); ++i)
            if ((*motion)[i].phase == control::Phase::Travel) mid = i;
        mid -= 60;
        const auto ee =
            kinematics::forward(robot.base, robot.link_lengths, (*motion)[mid].q).back();
        blocked.obstacles.push_back({ee, 0.02});
        const auto c3 = verify::certify(blocked, robot, *motion);
        REQUIRE_FALSE(c3.violations.empty());
        bool in_travel = false;
        for (const auto& v : c3.violations) in_travel |= v.travel && v.primitive == 1;
        CHECK(in_travel);
    }
    SECTION("one stroke's end straight to the next stroke's start is checked for clearance") {
        auto skipped = *motion;
        skipped.erase(std::remove_if(skipped.begin(), skipped.end(),
                                     [](const control::Sample& s) {
                                         return s.phase == control::Phase::Travel;
                                     }),
                      skipped.end());
        const auto c4 = verify::certify(t, robot, skipped);
        CHECK_FALSE(c4.ok);  // a joint jumps
    }
}

TEST_CASE("strokes: a one-stroke solution is written without stroke", "[control][travel]") {
    task::Task t = two_strokes();
    t.trajectory.pop_back();
    t.stroke_starts.clear();
    auto motion = control::plan_motion(t, testing::line_robot(), {});
    REQUIRE(motion);
    synth::Solution s;
    s.status = synth::Status::Solved;
    s.robot = testing::line_robot();
    s.samples = *motion;
    const auto doc = io::to_json(s);
    for (const auto& x : doc["samples"]) CHECK_FALSE(x.contains("stroke"));
}

TEST_CASE("strokes: a sample of a stroke the task lacks does not fit", "[control][travel]") {
    task::Task t = two_strokes();
    synth::Solution s;
    s.samples.push_back({0.0, control::Phase::Trace, 0, 0.0, {0.0, 0.0}, 2});
    CHECK_THROWS_AS(io::check_solution_fits(t, s), task::InputError);
    s.samples[0] = {0.0, control::Phase::Trace, 1, 0.0, {0.0, 0.0}, 1};
    CHECK_THROWS_AS(io::check_solution_fits(t, s), task::InputError);
    s.samples[0] = {0.0, control::Phase::Trace, 1, 0.0, {0.0, 0.0}, 0};
    CHECK_NOTHROW(io::check_solution_fits(t, s));
}
