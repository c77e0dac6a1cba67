#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include <modsynth/io/check_timeout.h>
#include <modsynth/io/spatial_task_io.h>
#include <modsynth/io/task_document.h>
#include <modsynth/io/task_io.h>
#include <modsynth/task/spatial_strokes.h>
#include <modsynth/text/printable.h>

using Catch::Matchers::Contains;
using modsynth::geometry::kPi;
using modsynth::io::parse_spatial_task;
using modsynth::io::to_json;
using modsynth::task::InputError;
using modsynth::task::SpatialTask;
using nlohmann::json;
namespace geometry = modsynth::geometry;

namespace {

const std::string kFixtures = std::string(MODSYNTH_SOURCE_DIR) + "/tests/fixtures/";

template <class F>
InputError input_error(F&& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e;
    }
    FAIL("no InputError thrown");
    return InputError("", "");
}

/// One of each primitive, obstacle and key, continuous and clear.
json full_doc() {
    return json::parse(R"({
      "format": "modsynth-task/1", "name": "full3d", "space": "3d",
      "trajectory": [
        {"type": "line", "start": [0.5, 0.0, 0.2], "end": [0.5, 0.1, 0.2]},
        {"type": "arc", "start": [0.5, 0.1, 0.2], "end": [0.5, 0.2, 0.3],
         "center": [0.5, 0.2, 0.2], "normal": [2, 0, 0], "direction": "cw"},
        {"type": "circle", "start": [0.5, 0.2, 0.3], "center": [0.5, 0.2, 0.25],
         "normal": [0, 1, 0], "direction": "ccw", "radius": 0.05},
        {"type": "helix", "start": [0.5, 0.2, 0.3], "center": [0.45, 0.2, 0.3],
         "axis": [0, 0, 1], "direction": "ccw", "pitch": 0.02, "turns": 1.5,
         "end": [0.4, 0.2, 0.33]}
      ],
      "obstacles": [
        {"type": "sphere", "center": [0.0, 0.5, 0.5], "radius": 0.05},
        {"center": [0.0, -0.5, 0.5], "radius": 0.05},
        {"type": "capsule", "a": [-0.3, 0, 0], "b": [-0.3, 0, 0.6], "radius": 0.03},
        {"type": "box", "min": [-1, -1, -0.1], "max": [1, 1, -0.05]}
      ],
      "base_regions": [{"min": [-0.1, -0.1, 0.0], "max": [0.1, 0.1, 0.0]}],
      "robot": {"dof": [4, 3], "link_diameter": 0.03, "min_link_length": 0.04,
                "max_link_length": 0.8, "twists": [0, 1.5707963267948966],
                "tool_length": 0.05, "modules": ["X8-9"], "payload": 0.3,
                "gravity": [0, 0, -9.8],
                "joint_limits": {"velocity": 2.0, "acceleration": [5, 5, 5, 5]}}
    })");
}

}  // namespace

TEST_CASE("a spatial task is read with every key", "[task]") {
    const SpatialTask t = parse_spatial_task(full_doc());
    CHECK(t.name == "full3d");
    REQUIRE(t.trajectory.size() == 4);
    CHECK(std::holds_alternative<geometry::Line3>(t.trajectory[0]));
    const auto& arc = std::get<geometry::Arc3>(t.trajectory[1]);
    CHECK(arc.turn.axis.isApprox(geometry::Vec3(1, 0, 0)));
    CHECK_FALSE(arc.turn.ccw);
    // cw about +x (from +y towards -z) from (y, z) = (-0.1, 0) to (0, +0.1)
    // relative to the center: a quarter turn.
    CHECK(arc.sweep == Approx(0.5 * kPi));
    CHECK(std::holds_alternative<geometry::Circle3>(t.trajectory[2]));
    const auto& helix = std::get<geometry::Helix3>(t.trajectory[3]);
    CHECK(helix.turns == 1.5);
    CHECK(geometry::end_point(t.trajectory[3]).isApprox(geometry::Vec3(0.4, 0.2, 0.33)));
    REQUIRE(t.obstacles.size() == 4);
    CHECK(std::holds_alternative<geometry::Sphere>(t.obstacles[1]));  // type left out
    CHECK(std::holds_alternative<geometry::Capsule>(t.obstacles[2]));
    CHECK(std::holds_alternative<geometry::Box3>(t.obstacles[3]));
    REQUIRE(t.base_regions.size() == 1);
    CHECK(t.robot.dof == std::vector<int>{4});  // narrowed by the per-joint limits
    CHECK(t.robot.twists.size() == 2);
    CHECK(t.robot.tool_length == 0.05);
    CHECK(t.robot.gravity.z() == -9.8);
    CHECK(t.robot.payload == 0.3);
    CHECK(t.robot.joint_limits->acceleration.size() == 4);
}

TEST_CASE("a spatial task without optional keys takes the contract's defaults", "[task]") {
    const SpatialTask t = parse_spatial_task(json::parse(R"({"format": "modsynth-task/1",
        "space": "3d", "trajectory": [{"type": "line", "start": [0.4, 0, 0.1], "end": [0.4, 0.1, 0.1]}]})"));
    CHECK(t.robot.dof == std::vector<int>{3, 4});
    CHECK(t.robot.link_diameter == 0.03175);
    CHECK(t.robot.min_link_length == 0.05);
    CHECK(t.robot.max_link_length == 1.0);
    CHECK(t.robot.twists == std::vector<double>{0.0, kPi / 2, -kPi / 2});
    CHECK(t.robot.tool_length == 0.0);
    CHECK(t.robot.gravity == geometry::Vec3(0, 0, -9.81));
    CHECK(t.obstacles.empty());
    CHECK(t.base_regions.empty());
}

TEST_CASE("a spatial task round-trips through its document", "[task]") {
    json doc = full_doc();
    const SpatialTask t = parse_spatial_task(doc);
    const json out = to_json(t);
    CHECK(out["space"] == "3d");
    const json again = to_json(parse_spatial_task(out));
    CHECK(again == out);
    // With strokes.
    doc.erase("trajectory");
    doc["strokes"] = json::array(
        {json::array({full_doc()["trajectory"][0]}), json::array({full_doc()["trajectory"][2]})});
    const SpatialTask s = parse_spatial_task(doc);
    CHECK(modsynth::task::stroke_count(s) == 2);
    CHECK(modsynth::task::part_name(s, 1) == "strokes[1][0]");
    const json strokes = to_json(s);
    CHECK(strokes.contains("strokes"));
    CHECK(to_json(parse_spatial_task(strokes)) == strokes);
}

TEST_CASE("documents of either kind are told apart", "[task]") {
    CHECK(modsynth::io::is_spatial(full_doc()));
    json planar = json::parse(R"({"format": "modsynth-task/1",
        "trajectory": [{"type": "line", "start": [0.4, 0.1], "end": [0.55, 0.1]}]})");
    CHECK_FALSE(modsynth::io::is_spatial(planar));
    CHECK(std::holds_alternative<modsynth::task::Task>(modsynth::io::parse_task_document(planar)));
    CHECK(std::holds_alternative<SpatialTask>(modsynth::io::parse_task_document(full_doc())));
    // The planar reader refuses a spatial task by name, the spatial one a planar task.
    CHECK(input_error([&] { modsynth::io::parse_task(full_doc()); }).part() == "space");
    CHECK(input_error([&] { parse_spatial_task(planar); }).part() == "space");
    planar["space"] = "plane";
    CHECK(input_error([&] { parse_spatial_task(planar); }).part() == "space");
}

TEST_CASE("bad spatial input is refused naming the part", "[task]") {
    struct Case {
        const char* pointer;  // where to change the full document
        json value;           // the new value; null with remove = true deletes
        bool remove;
        const char* part;
        const char* contains;
    };
    const json null;
    const Case cases[] = {
        {"/space", "4d", false, "space", "expected \"3d\""},
        {"/trajectory/0/start", json::array({0.5, 0.0}), false, "trajectory[0].start", "3 numbers"},
        {"/trajectory/0/end", json::array({0.5, 0.0, 2000.0}), false, "trajectory[0].end",
         "beyond"},
        {"/trajectory/0/end", json::array({0.5, 0.0, 0.2}), false, "trajectory[0]", "zero length"},
        {"/trajectory/0/type", "spline", false, "trajectory[0].type", "unknown primitive"},
        {"/trajectory/1/normal", json::array({0, 0, 0}), false, "trajectory[1].normal", "non-zero"},
        {"/trajectory/1/normal", null, true, "trajectory[1].normal", "missing"},
        {"/trajectory/1/normal", json::array({1, 0.04, 0}), false, "trajectory[1].normal",
         "not perpendicular to start - center (0.004 m)"},
        {"/trajectory/1/end", json::array({0.5, 0.2, 0.31}), false, "trajectory[1]",
         "farther from center"},
        {"/trajectory/1/direction", "left", false, "trajectory[1].direction", "\"ccw\""},
        {"/trajectory/1/radius", 0.2, false, "trajectory[1].radius", "disagrees"},
        {"/trajectory/2/radius", 0.06, false, "trajectory[2].radius", "disagrees"},
        {"/trajectory/2/center", json::array({0.5, 0.2, 0.3}), false, "trajectory[2]",
         "radius is 0"},
        {"/trajectory/2/normal", json::array({0, 0, 1}), false, "trajectory[2].normal",
         "not perpendicular to start - center"},
        {"/trajectory/3/axis", json::array({0, 0, 0}), false, "trajectory[3].axis", "non-zero"},
        {"/trajectory/3/pitch", 0.001, false, "trajectory[3].pitch", "at least 0.005"},
        {"/trajectory/3/pitch", "steep", false, "trajectory[3].pitch", "a number"},
        {"/trajectory/3/turns", 0, false, "trajectory[3].turns", "greater than 0"},
        {"/trajectory/3/turns", 5000, false, "trajectory[3].turns", "more than the 1000"},
        // Zero length refused by name, as a line's is.
        {"/trajectory/3/turns", 1e-12, false, "trajectory[3]", "helix has zero length"},
        {"/trajectory/3/turns", 5e-324, false, "trajectory[3]", "helix has zero length"},
        {"/trajectory/3/pitch", 0.0049999, false, "trajectory[3].pitch", "got 0.0049999 m"},
        {"/robot/joint_limits/jerk", json::array({5, 5}), false, "robot.joint_limits.jerk",
         "has 2 values"},
        {"/robot/joint_limits/jerk", 1e-9, false, "robot.joint_limits.jerk", "outside the"},
        {"/trajectory/3/center", json::array({0.45, 0.2, 0.31}), false, "trajectory[3].center",
         "not level with start"},
        {"/trajectory/3/end", json::array({0.4, 0.2, 0.34}), false, "trajectory[3].end",
         "from the helix's end"},
        {"/trajectory/0/end", json::array({0.5, 0.1, 0.201}), false, "trajectory[1]",
         "consecutive primitives must connect"},
        {"/obstacles/0/type", "cone", false, "obstacles[0].type", "unknown obstacle type"},
        {"/obstacles/0/radius", -1, false, "obstacles[0].radius", "greater than 0"},
        {"/obstacles/1/radius", null, true, "obstacles[1].type", "missing"},
        {"/obstacles/2/b", null, true, "obstacles[2].b", "missing"},
        {"/obstacles/3/max", json::array({1, 1, -0.2}), false, "obstacles[3].max",
         "below min on z"},
        {"/obstacles/3/max", json::array({1, -1, -0.05}), false, "obstacles[3].max",
         "equal to min on y"},
        {"/obstacles/0/center", json::array({0.5, 0.05, 0.2}), false, "obstacles[0]",
         "touches trajectory[0]"},
        {"/obstacles/2",
         json::parse(R"({"type": "capsule", "a": [0.5, 0.15, 0], "b": [0.5, 0.15, 0.6],
                         "radius": 0.01})"),
         false, "obstacles[2]", "touches trajectory[1]"},
        {"/obstacles/3/max", json::array({1, 1, 0.2}), false, "obstacles[3]",
         "touches trajectory[0]"},
        {"/base_regions/0/max", json::array({0.1, 0.1, -0.1}), false, "base_regions[0].max",
         "below min on z"},
        {"/robot/dof", json::array({2, 3}), false, "robot.dof[0]", "3 to 6"},
        {"/robot/dof", json::array({3, 7}), false, "robot.dof[1]", "3 to 6"},
        {"/robot/dof", json::array({3, 3}), false, "robot.dof[1]", "listed twice"},
        {"/robot/dof", json::array(), false, "robot.dof", "is empty"},
        {"/robot/link_diameter", 0, false, "robot.link_diameter", "greater than 0"},
        {"/robot/min_link_length", -0.1, false, "robot.min_link_length", "negative"},
        {"/robot/max_link_length", 0.01, false, "robot.min_link_length", "larger than"},
        {"/robot/twists", json::array(), false, "robot.twists", "is empty"},
        {"/robot/twists", "all", false, "robot.twists", "expected a list"},
        {"/robot/twists/1", "pi/2", false, "robot.twists[1]", "a twist in radians"},
        {"/robot/tool_length", -0.01, false, "robot.tool_length", "negative"},
        {"/robot/payload", -1, false, "robot.payload", "negative"},
        {"/robot/gravity", json::array({0, -9.81}), false, "robot.gravity", "[gx, gy, gz]"},
        {"/robot/gravity", json::array({0, 0, -200}), false, "robot.gravity", "100 m/s^2"},
        {"/robot/modules", json::array(), false, "robot.modules", "is empty"},
        {"/robot/joint_limits/acceleration", json::array({5, 5}), false,
         "robot.joint_limits.acceleration", "has 2 values"},
        {"/robot/joint_limits/velocity", -2.0, false, "robot.joint_limits.velocity",
         "greater than 0"},
        {"/robot/module_length", 0, false, "robot.module_length", "greater than 0"},
    };
    for (const Case& c : cases) {
        json doc = full_doc();
        const json::json_pointer at(c.pointer);
        if (c.remove)
            doc[at.parent_pointer()].erase(at.back());
        else
            doc[at] = c.value;
        INFO(c.pointer << " = " << c.value.dump());
        const InputError e = input_error([&] { parse_spatial_task(doc); });
        CHECK(e.part() == c.part);
        CHECK_THAT(e.what(), Contains(c.contains));
        const std::string what = e.what();
        CHECK(what.size() < 400);
        CHECK(modsynth::text::printable(what, what.size()) == what);
    }
}

TEST_CASE("spatial tasks keep the planar caps", "[task]") {
    json doc = full_doc();
    doc["obstacles"] = json::array();
    for (int i = 0; i < 1001; ++i)
        doc["obstacles"].push_back(
            {{"type", "sphere"}, {"center", {5.0, 5.0, 5.0}}, {"radius", 0.1}});
    CHECK_THAT(input_error([&] { parse_spatial_task(doc); }).what(),
               Contains("more than the 1000"));
    doc = full_doc();
    doc["trajectory"] = json::array();
    CHECK(input_error([&] { parse_spatial_task(doc); }).part() == "trajectory");
    doc = full_doc();
    doc["robot"]["link_diameter"] = 1e308;
    CHECK(input_error([&] { parse_spatial_task(doc); }).part() == "robot.link_diameter");
    doc = full_doc();
    doc["trajectory"][0]["start"] = json::array({0.5, "x", 0.2});
    CHECK(input_error([&] { parse_spatial_task(doc); }).part() == "trajectory[0].start");
}

TEST_CASE("every invalid spatial fixture is refused naming its part", "[task]") {
    const std::string dir = kFixtures + "invalid-spatial/";
    std::ifstream in(dir + "expected.json");
    REQUIRE(in);
    const json expected = json::parse(in);
    std::size_t files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        if (entry.path().filename() != "expected.json") ++files;
    CHECK(files == expected.size());
    for (const auto& [file, want] : expected.items()) {
        INFO(file);
        const InputError e = input_error([&] { modsynth::io::load_spatial_task(dir + file); });
        CHECK(e.part() == want.at("part").get<std::string>());
        CHECK_THAT(e.what(), Contains(want.at("message_contains").get<std::string>()));
    }
}

TEST_CASE("a spatial task's jerk limits are read and written as the plane's", "[task]") {
    json doc = full_doc();
    doc["robot"]["joint_limits"]["jerk"] = 30;
    const SpatialTask t = parse_spatial_task(doc);
    REQUIRE(t.robot.joint_limits);
    CHECK(t.robot.joint_limits->jerk == std::vector<double>{30.0});
    CHECK(to_json(t)["robot"]["joint_limits"]["jerk"] == 30.0);
    doc["robot"]["joint_limits"]["jerk"] = json::array({1, 2, 3, 4});
    const SpatialTask per_joint = parse_spatial_task(doc);
    CHECK(per_joint.robot.joint_limits->jerk == std::vector<double>{1, 2, 3, 4});
    CHECK(per_joint.robot.dof == std::vector<int>{4});
    CHECK(to_json(parse_spatial_task(to_json(per_joint))) == to_json(per_joint));
}

TEST_CASE("checking a spatial path against its obstacles stops at the reader's deadline",
          "[task]") {
    // A helix of a thousand turns round posts that nearly touch it all
    // along: each pair costs tens of milliseconds of checking.
    json doc = json::parse(R"({"format": "modsynth-task/1", "name": "coil", "space": "3d",
        "trajectory": [{"type": "helix", "start": [0.12, 0, 0.1], "center": [0, 0, 0.1],
                        "axis": [0, 0, 1], "direction": "ccw", "pitch": 0.005, "turns": 1000}],
        "base_regions": [{"min": [-0.05, -0.05, -0.9], "max": [0.05, 0.05, -0.9]}]})");
    for (int i = 0; i < 400; ++i)
        doc["obstacles"].push_back({{"type", "capsule"},
                                    {"a", {0, 0, 0}},
                                    {"b", {0, 0, 5.2}},
                                    {"radius", 0.1199 - 1e-6 * i}});
    const auto start = std::chrono::steady_clock::now();
    try {
        parse_spatial_task(doc, modsynth::run::Deadline::in(0.3));
        FAIL("checked to the end");
    } catch (const modsynth::io::CheckTimeout& e) {
        CHECK(e.task_name() == "coil");
        CHECK_THAT(e.what(), Contains("checking trajectory[0] against obstacles["));
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    CHECK(seconds < 1.5);
    // Without a deadline the same checks end, and a post away from the
    // path passes them.
    doc["obstacles"] = json::array({doc["obstacles"][0]});
    CHECK(parse_spatial_task(doc).obstacles.size() == 1);
}

TEST_CASE("tool axes are read per primitive and for the task, and written back", "[task]") {
    json doc = full_doc();
    doc["tool_axis"] = {{"direction", {0, 0, -2}}};
    doc["trajectory"][1]["tool_axis"] = {{"toward", "axis"}, {"tolerance", 0.1}};
    const SpatialTask t = parse_spatial_task(doc);
    REQUIRE(t.tool_axis);
    CHECK(t.tool_axis->tolerance == modsynth::task::kDefaultToolTolerance);
    REQUIRE(t.tool_axes.size() == t.trajectory.size());
    CHECK_FALSE(t.tool_axes[0]);
    REQUIRE(t.tool_axes[1]);
    CHECK(t.tool_axes[1]->kind == modsynth::task::ToolAxis::Kind::TowardAxis);
    // The task's own applies where a primitive has none.
    CHECK(modsynth::task::tool_axis_of(t, 0) == &*t.tool_axis);
    CHECK(modsynth::task::tool_axis_of(t, 1) == &*t.tool_axes[1]);
    const auto w = modsynth::task::wanted_tool(t, 0, geometry::Vec3(0.5, 0.0, 0.2));
    REQUIRE(w);
    CHECK((w->direction - geometry::Vec3(0, 0, -1)).norm() < 1e-15);
    CHECK(to_string(modsynth::task::tool_axis_part(t, 1)) == "trajectory[1].tool_axis");
    CHECK(to_string(modsynth::task::tool_axis_part(t, 0)) == "tool_axis");
    const json back = to_json(t);
    CHECK(back["tool_axis"] == json({{"direction", {0.0, 0.0, -2.0}}}));
    CHECK(back["trajectory"][1]["tool_axis"] == doc["trajectory"][1]["tool_axis"]);
    CHECK_FALSE(back["trajectory"][0].contains("tool_axis"));
}

TEST_CASE("bad tool axes are refused naming the part", "[task]") {
    const auto refused = [](const json& axis, int j, const std::string& part,
                            const std::string& text) {
        json doc = full_doc();
        if (j < 0)
            doc["tool_axis"] = axis;
        else
            doc["trajectory"][j]["tool_axis"] = axis;
        const InputError e = input_error([&] { parse_spatial_task(doc); });
        INFO(axis.dump() << ": " << e.part() << ": " << e.what());
        CHECK(e.part().rfind(part, 0) == 0);
        CHECK_THAT(std::string(e.what()), Contains(text));
    };
    refused({{"direction", {0, 0, 0}}}, 0, "trajectory[0].tool_axis.direction", "");
    refused({{"direction", {0, 0, -1}}, {"tolerance", 0}}, 0, "trajectory[0].tool_axis.tolerance",
            "");
    refused({{"direction", {0, 0, -1}}, {"tolerance", 1.6}}, -1, "tool_axis.tolerance", "");
    refused({{"toward", "axis"}}, 0, "trajectory[0].tool_axis", "line");
    refused({{"toward", "sideways"}}, 1, "trajectory[1].tool_axis.toward", "");
    refused({{"direction", {0, 0, -1}}, {"toward", "axis"}}, 1, "trajectory[1].tool_axis", "");
    refused(json::object(), 1, "trajectory[1].tool_axis", "");
    refused({{"direction", {0, 0, -1}}, {"spin", 0}}, 1, "trajectory[1].tool_axis", "spin");
    // The task's "toward" must fit every primitive that has no tool axis of its own.
    refused({{"toward", "away"}}, -1, "tool_axis", "line");
    // A turn of radius under 5 mm has no axis a tool may point at.
    json doc = full_doc();
    doc["trajectory"] = json::array({{{"type", "circle"},
                                      {"start", {0.5, 0.0, 0.2}},
                                      {"center", {0.5, 0.0, 0.197}},
                                      {"normal", {1, 0, 0}},
                                      {"direction", "ccw"},
                                      {"tool_axis", {{"toward", "axis"}}}}});
    const InputError e = input_error([&] { parse_spatial_task(doc); });
    CHECK(e.part().rfind("trajectory[0].tool_axis", 0) == 0);
}
