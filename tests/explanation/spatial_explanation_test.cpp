#include <modsynth/explanation/spatial_explanation.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <variant>

#include <modsynth/explanation/explain.h>
#include <modsynth/io/spatial_task_io.h>

#include "../support/fixtures.h"

using namespace modsynth;

namespace {

task::SpatialTask fixture(const std::string& name) {
    return io::load_spatial_task(testing::source_path("tests/fixtures/spatial/" + name));
}

bool names(const std::vector<task::TaskPart>& core, const std::string& part) {
    const auto s = task::to_strings(core);
    return std::find(s.begin(), s.end(), part) != s.end();
}

}  // namespace

TEST_CASE("explain proves a planted unreachable spatial task with its core",
          "[explain][spatial][slow]") {
    const task::SpatialTask task = fixture("sir-0001.task.json");
    const auto expect =
        testing::read_json(testing::source_path("tests/fixtures/spatial/sir-0001.expect.json"));
    explanation::ExplainOptions o;
    o.solve_seconds = 0.5;
    const explanation::Explanation e = explanation::explain(task, o);
    REQUIRE(e.proved);
    CHECK(e.status == synth::Status::Infeasible);
    CHECK(e.message.rfind("Proved infeasible: trajectory[0] is out of reach", 0) == 0);
    // The planted parts: every one the planter requires, and one of its
    // primitives.
    for (const auto& part : expect["core_should_include"])
        if (part.get<std::string>().rfind("trajectory", 0) != 0) CHECK(names(e.core, part));
    CHECK(std::any_of(expect["core_should_include_one_of"].begin(),
                      expect["core_should_include_one_of"].end(),
                      [&](const auto& part) { return names(e.core, part); }));
    // Longer links and a grown region remove the conflict, each re-checked
    // on the relaxed spatial task.
    std::vector<std::string> parts;
    for (const auto& r : e.suggestions) {
        parts.push_back(task::to_string(r.part));
        REQUIRE(std::holds_alternative<task::SpatialTask>(r.relaxed));
        const auto& relaxed = std::get<task::SpatialTask>(r.relaxed);
        CHECK(explanation::prove_infeasible(relaxed, 5.0).proved == false);
    }
    CHECK(parts == std::vector<std::string>{"robot.max_link_length", "base_regions"});
    CHECK(e.suggestions[0].change.rfind("robot.max_link_length >= ", 0) == 0);
    CHECK(e.suggestions[1].change.rfind("grow base_regions[0] by ", 0) == 0);
}

TEST_CASE("explain names the front stage's core of a spatial task and relaxes it",
          "[explain][spatial]") {
    // Every joint axis vertical (twists 0 only): the EE keeps one height,
    // and the path climbs.
    const task::SpatialTask task = io::parse_spatial_task_text(R"({
 "format": "modsynth-task/1", "name": "upright", "space": "3d",
 "trajectory": [{"type": "line", "start": [0.3, 0.0, 0.2], "end": [0.3, 0.0, 0.6]}],
 "base_regions": [{"min": [-0.05, -0.05, 0.0], "max": [0.05, 0.05, 0.02]}],
 "robot": {"dof": [3], "twists": [0.0]}})");
    explanation::ExplainOptions o;
    o.solve_seconds = 10.0;
    const explanation::Explanation e = explanation::explain(task, o);
    REQUIRE(e.proved);
    CHECK(task::to_strings(e.core) == std::vector<std::string>{"trajectory[0]", "robot.twists"});
    REQUIRE(e.suggestions.size() == 1);
    CHECK(task::to_string(e.suggestions[0].part) == "robot.twists");
    CHECK(e.suggestions[0].status == synth::Status::Solved);
}

TEST_CASE("explain solves a feasible spatial task instead", "[explain][spatial]") {
    const explanation::Explanation e = explanation::explain(fixture("s3-0001.task.json"));
    CHECK_FALSE(e.proved);
    CHECK(e.status == synth::Status::Solved);
    CHECK(e.message == "No conflict: a 3-joint robot does this task (run solve).");
    CHECK(e.suggestions.empty());
}

TEST_CASE("explain opens a wall in space: an obstacle removed or moved, the path moved",
          "[explain][spatial][slow]") {
    const task::SpatialTask task =
        io::load_spatial_task(testing::source_path("tasks/spatial/infeasible/walled.task.json"));
    const auto proof = explanation::prove_infeasible(task, 10.0);
    REQUIRE(proof.proved);
    REQUIRE(proof.enclosure);
    // The wall's parts only: the obstacles and the path.
    std::vector<task::TaskPart> core;
    for (const auto& p : proof.core)
        if (p.kind() == task::TaskPart::Kind::Obstacle ||
            p.kind() == task::TaskPart::Kind::Primitive)
            core.push_back(p);
    const auto suggestions = explanation::suggest_relaxations(task, core, 0.5, 60.0);
    std::vector<std::string> changes;
    for (const auto& r : suggestions) {
        changes.push_back(r.change);
        REQUIRE(std::holds_alternative<task::SpatialTask>(r.relaxed));
        // Re-checked: no proof holds on the changed task.
        CHECK_FALSE(
            explanation::prove_infeasible(std::get<task::SpatialTask>(r.relaxed), 5.0).proved);
    }
    const auto starts = [&](const std::string& head) {
        return std::any_of(changes.begin(), changes.end(),
                           [&](const std::string& c) { return c.rfind(head, 0) == 0; });
    };
    CHECK(starts("remove obstacles["));
    CHECK(starts("move obstacles["));
    CHECK(starts("move the path "));
}
