#include <modsynth/prove/spatial_enclosure.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include <modsynth/io/spatial_task_io.h>

#include "../support/fixtures.h"

using namespace modsynth;
using geometry::Vec3;

namespace {

task::SpatialTask example(const std::string& name) {
    return io::load_spatial_task(testing::source_path("tasks/spatial/infeasible/" + name));
}

std::vector<std::string> core_of(const prove::Proof& p) { return task::to_strings(p.core); }

/// Six slabs of thickness t closing the cube [-h, h]^3, with a square
/// window of side `window` cut in the +x slab when it is not 0 (the slab
/// then becomes four pieces round the window).
task::SpatialTask box_of_boxes(double h, double t, double window) {
    task::SpatialTask task;
    task.name = "box of boxes";
    task.trajectory.push_back(geometry::Line3{Vec3(0.6, -0.1, 0.2), Vec3(0.6, 0.1, 0.2)});
    task.base_regions.push_back({Vec3(-0.05, -0.05, -0.1), Vec3(0.05, 0.05, -0.1)});
    for (int a = 0; a < 3; ++a) {
        for (int side = 0; side < 2; ++side) {
            geometry::Box3 b{Vec3::Constant(-h - t), Vec3::Constant(h + t)};
            (side == 0 ? b.max : b.min)[a] = side == 0 ? -h : h;
            if (a == 0 && side == 1 && window > 0.0) {
                const double w = window / 2;
                // Four pieces framing the window in the yz-plane.
                auto piece = b;
                piece.max.y() = -w;
                task.obstacles.push_back(piece);
                piece = b;
                piece.min.y() = w;
                task.obstacles.push_back(piece);
                piece = b;
                piece.min.y() = -w, piece.max.y() = w, piece.max.z() = -w;
                task.obstacles.push_back(piece);
                piece = b;
                piece.min.y() = -w, piece.max.y() = w, piece.min.z() = w;
                task.obstacles.push_back(piece);
                continue;
            }
            task.obstacles.push_back(b);
        }
    }
    return task;
}

}  // namespace

TEST_CASE("a base region inside a closed box of boxes is walled off, with all six in the core",
          "[prove][spatial]") {
    const task::SpatialTask task = example("walled.task.json");
    const auto proof = prove::prove_spatial_enclosure(task);
    REQUIRE(proof);
    CHECK(proof->minimal);
    // robot.link_diameter too: for a tube of diameter 0 a box constrains
    // nothing (dist(segment, box) >= 0 always holds).
    CHECK(core_of(*proof) ==
          std::vector<std::string>{"trajectory[0]", "obstacles[0]", "obstacles[1]", "obstacles[2]",
                                   "obstacles[3]", "obstacles[4]", "obstacles[5]", "base_regions",
                                   "robot.link_diameter"});
    REQUIRE(proof->enclosure);
    REQUIRE(proof->enclosure->walls.size() == 1);
    const prove::Enclosure& w = proof->enclosure->walls[0];
    CHECK(w.base_inside);
    CHECK(w.obstacles == std::vector<int>{0, 1, 2, 3, 4, 5});
    // Corners exact in binary: a power-of-two cell, an origin on its grid.
    CHECK(std::exp2(std::round(std::log2(w.grid.cell))) == w.grid.cell);
    for (int a = 0; a < 3; ++a) CHECK(std::fmod(w.grid.origin[a], w.grid.cell) == 0.0);
    CHECK(!w.cells.empty());
    CHECK(proof->message.find("close in base_regions[0], and the path (") != std::string::npos);
    CHECK(proof->message.find("no arm from the base box can reach round them") !=
          std::string::npos);
    // In a builder's words: the grid is the witness's, not the sentence's.
    CHECK(proof->message.find("cells") == std::string::npos);
    CHECK(proof->message.find("link_diameter / 2") == std::string::npos);
}

TEST_CASE("a path inside a closed shell of spheres is walled off from the base",
          "[prove][spatial]") {
    const task::SpatialTask task = example("shelled.task.json");
    const auto proof = prove::prove_spatial_enclosure(task);
    REQUIRE(proof);
    REQUIRE(proof->enclosure);
    const prove::Enclosure& w = proof->enclosure->walls[0];
    CHECK(!w.base_inside);
    CHECK(w.primitive == 0);
    // The point is on the circle round (0.6, 0, 0.35) of radius 0.05.
    CHECK(std::abs((w.point - Vec3(0.6, 0.0, 0.35)).norm() - 0.05) < 1e-9);
    // Minimal: the shell's spheres only, and fewer than all 80 of them
    // would not do for every one (each is needed at this grid).
    CHECK(w.obstacles.size() >= 12);
    CHECK(w.obstacles.size() <= task.obstacles.size());
    CHECK(core_of(*proof).front() == "trajectory[0]");
    CHECK(core_of(*proof).back() == "base_regions");
}

TEST_CASE("a window wider than the tube opens the box; a narrower one needs the tube's diameter",
          "[prove][spatial]") {
    // 6 cm window, 3.175 cm tube: a chain threads it.
    CHECK_FALSE(prove::prove_spatial_enclosure(box_of_boxes(0.25, 0.03, 0.06)));
    // 2 cm window: closed for the tube, open for a tube of diameter 0.
    const auto proof = prove::prove_spatial_enclosure(box_of_boxes(0.25, 0.03, 0.02));
    REQUIRE(proof);
    const auto core = core_of(*proof);
    CHECK(std::find(core.begin(), core.end(), "robot.link_diameter") != core.end());
    // Minimal: the two pieces above and below the window go (without them
    // it is a slot 2 cm wide, still closed to the tube), the other seven
    // stay.
    CHECK(proof->enclosure->walls[0].obstacles == std::vector<int>{0, 1, 2, 5, 6, 7, 8});
}

TEST_CASE("no wall without base regions, without obstacles, or with a face missing",
          "[prove][spatial]") {
    task::SpatialTask task = example("walled.task.json");
    task::SpatialTask open = task;
    open.obstacles.erase(open.obstacles.begin() + 3);
    CHECK_FALSE(prove::prove_spatial_enclosure(open));
    task::SpatialTask anywhere = task;
    anywhere.base_regions.clear();
    CHECK_FALSE(prove::prove_spatial_enclosure(anywhere));
    task::SpatialTask empty = task;
    empty.obstacles.clear();
    CHECK_FALSE(prove::prove_spatial_enclosure(empty));
    // A tool that reaches through the wall from the path (which is 0.33 m
    // from the box) breaks the proof; a shorter one is in the core.
    task::SpatialTask tool = task;
    tool.robot.tool_length = 0.5;
    CHECK_FALSE(prove::prove_spatial_enclosure(tool));
    tool.robot.tool_length = 0.1;
    const auto with_tool = prove::prove_spatial_enclosure(tool);
    REQUIRE(with_tool);
    const auto core = core_of(*with_tool);
    CHECK(std::find(core.begin(), core.end(), "robot.tool_length") != core.end());
}

TEST_CASE("an expired deadline gives no wall rather than a wrong one", "[prove][spatial]") {
    const task::SpatialTask task = example("shelled.task.json");
    CHECK_FALSE(prove::prove_spatial_enclosure(task, run::Deadline::in(0.0)));
}

TEST_CASE("no planted feasible spatial task is walled off", "[prove][spatial]") {
    for (const char* name : {"s3-0001", "s3-0004", "s3-0017", "s4-0010", "s4-0017", "s4-0030"}) {
        const task::SpatialTask task = io::load_spatial_task(
            testing::source_path(std::string("tests/fixtures/spatial/") + name + ".task.json"));
        INFO(name);
        CHECK_FALSE(prove::prove_spatial_enclosure(task));
    }
}

TEST_CASE("a base region with no free cell round it is walled by the obstacle that fills them",
          "[prove][spatial]") {
    // The base region deep inside a sphere, and a tube so thick that the
    // post fills every cell round the path: no free point there for a
    // chain to leave from. The obstacle that fills the cells is the wall
    // (and in the core); the witness holds no cells.
    for (const char* name : {"base-in-sphere", "thick-tube"}) {
        INFO(name);
        const task::SpatialTask task = io::load_spatial_task(testing::source_path(
            std::string("tests/fixtures/spatial-walls-empty/") + name + ".task.json"));
        const auto proof = prove::prove_spatial_enclosure(task);
        REQUIRE(proof);
        REQUIRE(proof->enclosure);
        REQUIRE(proof->enclosure->walls.size() == 1);
        const prove::Enclosure& w = proof->enclosure->walls.front();
        CHECK(w.cells.empty());
        REQUIRE_FALSE(w.obstacles.empty());
        const auto core = core_of(*proof);
        for (int i : w.obstacles)
            CHECK(std::count(core.begin(), core.end(), "obstacles[" + std::to_string(i) + "]") ==
                  1);
        CHECK_THAT(proof->message, Catch::Contains("no free point there"));
    }
}
