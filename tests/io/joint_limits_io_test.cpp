#include <catch2/catch.hpp>

#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include <modsynth/control/joint_limits.h>
#include <modsynth/io/solution_io.h>
#include <modsynth/io/task_io.h>
#include <modsynth/task/input_error.h>

#include "../output/output_fixtures.h"

using modsynth::io::parse_task;
using modsynth::task::InputError;
using nlohmann::json;

namespace {

json task_with(const json& limits, const json& dof = nullptr) {
    json robot = {{"joint_limits", limits}};
    if (!dof.is_null()) robot["dof"] = dof;
    return {{"format", "modsynth-task/1"},
            {"trajectory", {{{"type", "line"}, {"start", {0.4, 0.0}}, {"end", {0.4, 0.1}}}}},
            {"robot", robot}};
}

/// The message of the InputError parsing throws; fails when none is thrown.
std::string rejection(const json& doc) {
    try {
        parse_task(doc);
    } catch (const InputError& e) {
        return e.what();
    }
    FAIL("no InputError thrown");
    return "";
}

}  // namespace

TEST_CASE("joint limits are read as one value or one per joint", "[task][timing]") {
    json plain = task_with(nullptr);
    plain["robot"].erase("joint_limits");
    CHECK_FALSE(parse_task(plain).robot.joint_limits.has_value());

    const auto one = parse_task(task_with({{"velocity", 3.35}, {"acceleration", 10}}));
    REQUIRE(one.robot.joint_limits);
    CHECK(one.robot.joint_limits->velocity == std::vector<double>{3.35});
    CHECK(one.robot.joint_limits->acceleration == std::vector<double>{10.0});
    CHECK(one.robot.dof == std::vector<int>{2, 3});  // a value for every joint fixes nothing

    // A list fixes the joint count; the search then considers only it.
    const auto three = parse_task(task_with({{"velocity", {1.0, 2.0, 3.0}}, {"acceleration", 5}}));
    CHECK(three.robot.dof == std::vector<int>{3});
    CHECK(three.robot.joint_limits->velocity == std::vector<double>{1.0, 2.0, 3.0});

    // Written back as read, and read again the same.
    const json written = modsynth::io::to_json(three);
    CHECK(written["robot"]["joint_limits"]["velocity"] == json({1.0, 2.0, 3.0}));
    CHECK(written["robot"]["joint_limits"]["acceleration"] == json(5.0));
    const auto again = parse_task(written);
    CHECK(again.robot.joint_limits->velocity == three.robot.joint_limits->velocity);
    CHECK(again.robot.dof == three.robot.dof);
    CHECK_FALSE(modsynth::io::to_json(parse_task(plain))["robot"].contains("joint_limits"));
}

TEST_CASE("bad joint limits are rejected naming the key", "[task][timing]") {
    CHECK_THAT(rejection(task_with({{"velocity", {1.0, -1.0}}, {"acceleration", 5}})),
               Catch::StartsWith("robot.joint_limits.velocity[1]: must be greater than 0"));
    CHECK_THAT(rejection(task_with({{"velocity", 1.0}, {"acceleration", "fast"}})),
               Catch::StartsWith("robot.joint_limits.acceleration: expected a limit"));
    CHECK_THAT(rejection(task_with({{"velocity", {1, 1, 1, 1}}, {"acceleration", 5}})),
               Catch::StartsWith("robot.joint_limits.velocity: has 4 values"));
    CHECK_THAT(rejection(task_with({{"velocity", {1, 1, 1}}, {"acceleration", 5}}, {2})),
               Catch::StartsWith("robot.joint_limits.velocity: has 3 values") &&
                   Catch::Contains("2 joints"));
    CHECK_THAT(rejection(task_with({{"velocity", {1, 1}}, {"acceleration", {1, 1, 1}}})),
               Catch::StartsWith("robot.joint_limits.acceleration: has 3 values but velocity "
                                 "has 2"));
    CHECK_THAT(rejection(task_with({{"velocity", 1}})),
               Catch::StartsWith("robot.joint_limits.acceleration: missing"));
    CHECK_THAT(rejection(task_with({{"velocity", 1e9}, {"acceleration", 1}})),
               Catch::StartsWith("robot.joint_limits.velocity: 1e+09 rad/s is outside"));
    CHECK_THAT(rejection(task_with(json::array({1, 2}))),
               Catch::StartsWith("robot.joint_limits: expected an object"));
    CHECK_THAT(rejection(task_with({{"velocity", json::array()}, {"acceleration", 1}})),
               Catch::StartsWith("robot.joint_limits.velocity: has 0 values"));
}

TEST_CASE("a jerk limit is read, checked and written back", "[task][timing]") {
    const auto one = parse_task(task_with({{"velocity", 1.2}, {"acceleration", 3}, {"jerk", 30}}));
    REQUIRE(one.robot.joint_limits);
    CHECK(one.robot.joint_limits->jerk == std::vector<double>{30.0});
    CHECK(modsynth::io::to_json(one)["robot"]["joint_limits"]["jerk"] == json(30.0));
    const auto none = parse_task(task_with({{"velocity", 1.2}, {"acceleration", 3}}));
    CHECK(none.robot.joint_limits->jerk.empty());
    CHECK_FALSE(modsynth::io::to_json(none)["robot"]["joint_limits"].contains("jerk"));
    // A list fixes the joint count as the other limits' do.
    const auto two =
        parse_task(task_with({{"velocity", 1.2}, {"acceleration", 3}, {"jerk", {20, 40}}}));
    CHECK(two.robot.dof == std::vector<int>{2});
    const auto limits = modsynth::control::joint_limits_for(two, 2);
    CHECK(limits.jerk == std::vector<double>{20.0, 40.0});
    CHECK(modsynth::control::joint_limits_for(one, 3).jerk == std::vector<double>(3, 30.0));
    CHECK(modsynth::control::joint_limits_for(none, 3).jerk.empty());

    CHECK_THAT(rejection(task_with({{"velocity", 1}, {"acceleration", 3}, {"jerk", -1}})),
               Catch::StartsWith("robot.joint_limits.jerk: must be greater than 0 rad/s^3"));
    CHECK_THAT(
        rejection(task_with({{"velocity", {1, 1}}, {"acceleration", 3}, {"jerk", {1, 1, 1}}})),
        Catch::StartsWith("robot.joint_limits.jerk: has 3 values but velocity has 2"));
    CHECK_THAT(rejection(task_with({{"velocity", 1}, {"acceleration", 3}, {"jerk", "smooth"}})),
               Catch::StartsWith("robot.joint_limits.jerk: expected a limit"));
}

TEST_CASE("samples' velocities and accelerations round-trip", "[timing]") {
    auto s = modsynth::testing::two_joint_solution(modsynth::testing::two_joint_task());
    for (auto& x : s.samples) {
        x.qd = {0.5, -0.25};
        x.qdd = {1.0, 2.0};
    }
    const json doc = modsynth::io::to_json(s);
    CHECK(doc["samples"][3]["qd"] == json({0.5, -0.25}));
    const auto back = modsynth::io::parse_solution(doc).solution;
    CHECK(back.samples[3].qd == s.samples[3].qd);
    CHECK(back.samples[3].qdd == s.samples[3].qdd);

    json partial = doc;
    partial["samples"][2].erase("qd");
    try {
        modsynth::io::parse_solution(partial);
        FAIL("a sample without qd among samples with it was accepted");
    } catch (const InputError& e) {
        CHECK(e.part() == "samples[2].qd");
    }
    json wrong = doc;
    wrong["samples"][1]["qdd"] = {1.0};
    try {
        modsynth::io::parse_solution(wrong);
        FAIL("qdd with one number for two joints was accepted");
    } catch (const InputError& e) {
        CHECK(e.part() == "samples[1].qdd");
    }
    // Without them (as before the extension): read, and none written.
    const auto bare = modsynth::testing::two_joint_solution(modsynth::testing::two_joint_task());
    CHECK_FALSE(modsynth::io::to_json(bare)["samples"][0].contains("qd"));
}
