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

TEST_CASE("the public API reads and certifies spatial tasks", "[api]") {
    const std::string dir = modsynth::testing::source_path("tests/fixtures/spatial/");
    const std::string text = modsynth::testing::read_json(dir + "s4-0010.task.json").dump();
    CHECK(modsynth::is_spatial_task(text));
    CHECK_FALSE(modsynth::is_spatial_task(
        modsynth::testing::read_json(modsynth::testing::source_path("tasks/rose.json")).dump()));
    CHECK_THROWS_AS(modsynth::read_task(text), modsynth::InputError);
    const modsynth::SpatialTask task = modsynth::read_spatial_task(text);
    CHECK(task.trajectory.size() == 4);
    CHECK(modsynth::load_spatial_task(dir + "s4-0010.task.json").name == "s4-0010");
    const modsynth::Solution planted =
        modsynth::read_solution(modsynth::testing::read_json(dir + "s4-0010.planted.json").dump());
    REQUIRE(planted.dh_robot);
    CHECK(modsynth::certify(task, planted).ok);
    modsynth::Solution edited = planted;
    edited.dh_robot->rows[1].a += 0.01;
    CHECK_FALSE(modsynth::certify(task, edited).ok);
}

TEST_CASE("the public API solves spatial tasks, modules included", "[api]") {
    const std::string dir = modsynth::testing::source_path("tests/fixtures/spatial/");
    const modsynth::SpatialTask task = modsynth::load_spatial_task(dir + "s3-0001.task.json");
    const modsynth::Solution s = modsynth::solve(task);
    REQUIRE(s.status == modsynth::Status::Solved);
    REQUIRE(s.dh_robot);
    CHECK(s.dh_robot->dof() == 3);
    CHECK(s.modules);
    CHECK(modsynth::certify(task, s).ok);
    // Proved infeasible with the planted core, as `modsynth solve` says.
    const modsynth::Solution none =
        modsynth::solve(modsynth::load_spatial_task(dir + "sir-0001.task.json"));
    CHECK(none.status == modsynth::Status::Infeasible);
    CHECK(modsynth::task::to_strings(none.explanation.core) ==
          std::vector<std::string>{"robot.max_link_length", "base_regions", "trajectory[0]"});
}
