#include <modsynth/modsynth.h>

#include <catch2/catch.hpp>

#include "../support/fixtures.h"

TEST_CASE("the public API reads, solves, writes, reads back and certifies", "[api]") {
    const modsynth::Task task =
        modsynth::load_task(modsynth::testing::source_path("tasks/rose.json"));
    modsynth::SolveOptions options;
    options.time_limit = 20.0;
    int lines = 0;
    options.progress = [&](const modsynth::ProgressEvent&) { ++lines; };
    const modsynth::Solution solution = modsynth::solve(task, options);
    REQUIRE(solution.status == modsynth::Status::Solved);
    CHECK(lines > 0);
    const modsynth::Solution read =
        modsynth::read_solution(modsynth::write_solution_json(solution));
    CHECK(modsynth::certify(task, read).ok);

    SECTION("a motion edited by hand does not certify") {
        modsynth::Solution edited = read;
        auto& q = edited.samples[edited.samples.size() / 2].q;
        q[0] += 0.2;
        CHECK_FALSE(modsynth::certify(task, edited).ok);
    }
    SECTION("an answer that is not solved has no certificate") {
        modsynth::Solution unknown = read;
        unknown.status = modsynth::Status::Unknown;
        CHECK_FALSE(modsynth::certify(task, unknown).ok);
    }
}

TEST_CASE("the public API names the offending part of a bad task", "[api]") {
    CHECK_THROWS_AS(modsynth::read_task("{"), modsynth::InputError);
    try {
        modsynth::read_task(R"({"format": "modsynth-task/1", "name": "x", "trajectory": []})");
        FAIL("an empty trajectory was accepted");
    } catch (const modsynth::InputError& e) {
        CHECK(e.part() == "trajectory");
    }
}

TEST_CASE("the public API refuses invalid options, naming the field", "[api]") {
    const modsynth::Task task =
        modsynth::load_task(modsynth::testing::source_path("tasks/rose.json"));
    modsynth::SolveOptions options;
    options.time_limit = -1.0;
    CHECK_THROWS_WITH(modsynth::solve(task, options), Catch::Contains("time_limit"));
}

TEST_CASE("the public API's explain carries an obstacle proof's witness", "[api][walls][slow]") {
    const modsynth::Task task =
        modsynth::load_task(modsynth::testing::source_path("tasks/infeasible/long-wall.task.json"));
    const modsynth::Explanation e = modsynth::explain(task, 30.0, 0.5);
    CHECK(e.status == modsynth::Status::Infeasible);
    REQUIRE(e.geodesic);
    CHECK_FALSE(e.separation);
    CHECK(e.geodesic->detours.at(0).lower_bound > e.geodesic->reach);
    // The same sentence as `modsynth explain`, and as a solve.
    CHECK(e.message.rfind("Proved infeasible: the shortest way around obstacles", 0) == 0);
    CHECK(e.message == modsynth::solve(task).explanation.message);
}
