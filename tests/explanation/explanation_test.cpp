#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <set>

#include <modsynth/explanation/explanation.h>
#include <modsynth/io/task_io.h>
#include <modsynth/prove/conflict_text.h>
#include <modsynth/synth/synthesizer.h>

#include "../support/fixtures.h"

using namespace modsynth;

TEST_CASE("every hand-made infeasible task is proved with its expected core", "[explain]") {
    int checked = 0;
    for (const auto& e :
         std::filesystem::directory_iterator(testing::source_path("tasks/infeasible"))) {
        const std::string path = e.path().string();
        if (path.find(".task.json") == std::string::npos) continue;
        const std::string stem = path.substr(0, path.size() - std::string(".task.json").size());
        INFO(path);
        REQUIRE(std::filesystem::exists(stem + ".core.json"));
        const auto expected =
            testing::read_json(stem + ".core.json")["core"].get<std::vector<std::string>>();
        const synth::Solution s = synth::synthesize(io::load_task(path), {});
        REQUIRE(s.status == synth::Status::Infeasible);
        const auto core = task::to_strings(s.explanation.core);
        CHECK(std::set<std::string>(core.begin(), core.end()) ==
              std::set<std::string>(expected.begin(), expected.end()));
        CHECK(s.explanation.message.rfind("Proved infeasible: ", 0) == 0);
        ++checked;
    }
    CHECK(checked >= 4);
}

TEST_CASE("relaxations are the smallest change of one part, and they are re-checked",
          "[explain][slow]") {
    const task::Task t =
        io::load_task(testing::source_path("tasks/infeasible/table-too-far.task.json"));
    const auto proof = explanation::prove_infeasible(t, 10.0);
    REQUIRE(proof.proved);
    const auto suggestions = explanation::suggest_relaxations(t, proof.core, 5.0);
    const auto longer =
        std::find_if(suggestions.begin(), suggestions.end(), [](const explanation::Relaxation& r) {
            return r.part.is_robot(task::RobotKey::MaxLinkLength);
        });
    REQUIRE(longer != suggestions.end());
    // The farthest point, (2.7, 0.3), is 2.61 m from the plate's nearest
    // corner: two links need at least 1.30 m each.
    CHECK(std::get<task::Task>(longer->relaxed).robot.max_link_length >= 1.30);
    CHECK(std::get<task::Task>(longer->relaxed).robot.max_link_length <= 1.32);
    CHECK_FALSE(explanation::prove_infeasible(std::get<task::Task>(longer->relaxed), 10.0).proved);
    CHECK(longer->status == synth::Status::Solved);
    CHECK(longer->outcome.rfind("solved", 0) == 0);
    const auto moved = std::find_if(
        suggestions.begin(), suggestions.end(),
        [](const explanation::Relaxation& r) { return r.part == task::TaskPart::base_regions(); });
    REQUIRE(moved != suggestions.end());
    CHECK(moved->change.find("extend base_regions[0]") != std::string::npos);
    CHECK_FALSE(explanation::prove_infeasible(std::get<task::Task>(moved->relaxed), 10.0).proved);
}

TEST_CASE("task parts are described in words and numbers", "[explain]") {
    const task::Task t = io::load_task(testing::source_path("tasks/rose.json"));
    using task::TaskPart;
    CHECK(prove::describe_part(t, TaskPart::trajectory(0)) ==
          "trajectory[0]: a line from (0.500, 0.050) to (0.500, 0.220)");
    CHECK(prove::describe_part(t, TaskPart::trajectory(4)).find("a circle of radius 0.050 m") !=
          std::string::npos);
    CHECK(prove::describe_part(t, TaskPart::obstacle(2)) ==
          "obstacles[2]: a disc of radius 0.030 m at (0.640, 0.070)");
    CHECK(prove::describe_part(t, TaskPart::robot(task::RobotKey::MaxLinkLength)) ==
          "robot.max_link_length: links of at most 1.000 m");
}

TEST_CASE("a feasible task is not proved infeasible", "[explain]") {
    const task::Task t = io::load_task(testing::source_path("tasks/rose.json"));
    const auto proof = explanation::prove_infeasible(t, 10.0);
    CHECK_FALSE(proof.proved);
    CHECK(proof.open.find("not ruled out") != std::string::npos);
}

TEST_CASE("suggestions and proofs end at their time limit", "[explain]") {
    const task::Task t =
        io::load_task(testing::source_path("tasks/infeasible/table-too-far.task.json"));
    const auto proof = explanation::prove_infeasible(t, 10.0);
    REQUIRE(proof.proved);
    // Unbounded, the bisections and the solves of the relaxed tasks take
    // about 20 s here; with 1 s in all they stop in time.
    const auto t0 = std::chrono::steady_clock::now();
    const auto suggestions = explanation::suggest_relaxations(t, proof.core, 10.0, 1.0);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    CHECK(seconds < 2.0);
    for (const auto& s : suggestions) CHECK_FALSE(s.change.empty());
}
