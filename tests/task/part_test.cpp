#include <modsynth/task/part.h>
#include <modsynth/task/part_list.h>

#include <catch2/catch.hpp>

#include <string>

#include <modsynth/task/spatial_strokes.h>
#include <modsynth/task/strokes.h>

using namespace modsynth;
using task::RobotKey;
using task::TaskPart;

TEST_CASE("task parts are written as formats.md names them and read back", "[task]") {
    const std::vector<std::pair<TaskPart, std::string>> named = {
        {TaskPart::trajectory(3), "trajectory[3]"},
        {TaskPart::stroke_primitive(1, 0), "strokes[1][0]"},
        {TaskPart::obstacle(12), "obstacles[12]"},
        {TaskPart::base_regions(), "base_regions"},
        {TaskPart::base_region(0), "base_regions[0]"},
        {TaskPart::robot(RobotKey::MaxLinkLength), "robot.max_link_length"},
        {TaskPart::robot(RobotKey::Modules, 1), "robot.modules[1]"},
        // Spatial tasks name the same kinds of part.
        {TaskPart::trajectory(2).with_field("normal"), "trajectory[2].normal"},
        {TaskPart::robot(RobotKey::Twists), "robot.twists"},
        {TaskPart::robot(RobotKey::ToolLength), "robot.tool_length"},
        {TaskPart::obstacle(1).with_field("b"), "obstacles[1].b"},
        {TaskPart::robot(RobotKey::JointLimits).with_field("velocity[2]"),
         "robot.joint_limits.velocity[2]"},
    };
    for (const auto& [part, name] : named) {
        INFO(name);
        CHECK(task::to_string(part) == name);
        const auto back = task::parse_task_part(name);
        REQUIRE(back);
        CHECK(*back == part);
    }
}

TEST_CASE("names that are no task part are refused", "[task]") {
    for (const char* name : {"", "trajectory", "trajectory[]", "trajectory[-1]", "trajectory[01]",
                             "trajectory[1", "trajectory[1]x", "trajectory[1].", "strokes[1]",
                             "obstacles[a]", "base_regionsX", "robot.", "robot.wings", "robot.dofs",
                             "robot.modules[", "robot.dof.", "trajectory[99999999999]"}) {
        INFO(name);
        CHECK_FALSE(task::parse_task_part(name));
    }
}

TEST_CASE("a part holds its entries and its keys", "[task]") {
    CHECK(TaskPart::base_regions().holds(TaskPart::base_region(2)));
    CHECK(TaskPart::trajectory(2).holds(TaskPart::trajectory(2).with_field("normal")));
    CHECK(TaskPart::obstacle(1).holds(TaskPart::obstacle(1)));
    CHECK_FALSE(TaskPart::obstacle(1).holds(TaskPart::obstacle(10)));
    CHECK_FALSE(TaskPart::trajectory(2).with_field("normal").holds(TaskPart::trajectory(2)));
    CHECK_FALSE(TaskPart::base_region(0).holds(TaskPart::base_regions()));
    CHECK_FALSE(TaskPart::trajectory(0).holds(TaskPart::stroke_primitive(0, 0)));
}

TEST_CASE("a primitive part names its index in the task, as the document numbers it", "[task]") {
    task::Task t;
    for (int j = 0; j < 3; ++j)
        t.trajectory.push_back(geometry::make_line({0.1 * j, 0.5}, {0.1 * j + 0.1, 0.5}));
    CHECK(TaskPart::primitive(t, 2) == TaskPart::trajectory(2));
    CHECK(task::primitive_index(t, TaskPart::trajectory(2)) == 2);
    CHECK_FALSE(task::primitive_index(t, TaskPart::trajectory(3)));
    CHECK_FALSE(task::primitive_index(t, TaskPart::obstacle(0)));
    t.stroke_starts = {0, 2};
    CHECK(TaskPart::primitive(t, 2) == TaskPart::stroke_primitive(1, 0));
    CHECK(task::part_name(t, 1) == "strokes[0][1]");
    CHECK(task::primitive_index(t, TaskPart::stroke_primitive(1, 0)) == 2);
    CHECK_FALSE(task::primitive_index(t, TaskPart::stroke_primitive(1, 1)));
    CHECK_FALSE(task::primitive_index(t, TaskPart::trajectory(0)));
}

TEST_CASE("a spatial task names its primitives as the same parts", "[task]") {
    task::SpatialTask t;
    for (int j = 0; j < 3; ++j)
        t.trajectory.push_back(geometry::Line3{geometry::Vec3(0.1 * j, 0.5, 0.2),
                                               geometry::Vec3(0.1 * j + 0.1, 0.5, 0.2)});
    CHECK(task::primitive_part(t, 2) == TaskPart::trajectory(2));
    CHECK(task::part_name(t, 2) == "trajectory[2]");
    CHECK(task::to_string(task::primitive_part(t, 2).with_field("normal")) ==
          "trajectory[2].normal");
    t.stroke_starts = {0, 2};
    CHECK(task::primitive_part(t, 2) == TaskPart::stroke_primitive(1, 0));
    CHECK(task::part_name(t, 1) == "strokes[0][1]");
}

TEST_CASE("a list of parts for a person says a run of primitives by its ends", "[task]") {
    using task::RobotKey;
    std::vector<TaskPart> core;
    for (int j = 0; j < 512; ++j) core.push_back(TaskPart::trajectory(j));
    core.push_back(TaskPart::obstacle(0));
    core.push_back(TaskPart::robot(RobotKey::Dof));
    CHECK(task::to_short_list(core) == "trajectory[0] to trajectory[511] obstacles[0] robot.dof");
    // Two in a row, a gap, another stroke, a field: each said.
    CHECK(task::to_short_list({TaskPart::trajectory(3), TaskPart::trajectory(4),
                               TaskPart::trajectory(6), TaskPart::stroke_primitive(1, 0),
                               TaskPart::stroke_primitive(1, 1), TaskPart::stroke_primitive(1, 2),
                               TaskPart::trajectory(7).with_field("normal")}) ==
          "trajectory[3] trajectory[4] trajectory[6] strokes[1][0] to strokes[1][2] "
          "trajectory[7].normal");
    CHECK(task::to_short_list({}).empty());
}

TEST_CASE("a run of obstacles is said by its ends, as a run of primitives", "[task]") {
    std::vector<TaskPart> core = {TaskPart::trajectory(0)};
    for (int i = 0; i < 80; ++i) core.push_back(TaskPart::obstacle(i));
    core.push_back(TaskPart::base_regions());
    CHECK(task::to_short_list(core) == "trajectory[0] obstacles[0] to obstacles[79] base_regions");
    const auto runs = task::part_runs(core);
    REQUIRE(runs.size() == 3);
    CHECK(runs[1].first == 1);
    CHECK(runs[1].size() == 80);
    CHECK(task::run_text(core, runs[1]) == "obstacles[0] to obstacles[79]");
    // A gap ends a run; two in a row are both said.
    CHECK(task::to_short_list({TaskPart::obstacle(0), TaskPart::obstacle(1), TaskPart::obstacle(2),
                               TaskPart::obstacle(5), TaskPart::obstacle(6)}) ==
          "obstacles[0] to obstacles[2] obstacles[5] obstacles[6]");
}
