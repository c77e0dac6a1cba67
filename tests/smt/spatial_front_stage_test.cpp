#include <modsynth/smt/spatial_front_stage.h>

#include <catch2/catch.hpp>

#include <modsynth/io/spatial_task_io.h>
#include <modsynth/task/part.h>

namespace {

using modsynth::task::RobotKey;
using modsynth::task::TaskPart;

// A vertical line for a chain whose joint axes are all vertical (twists 0
// only): its EE keeps one height, so the relaxation is unsat for the line
// and robot.twists alone.
modsynth::task::SpatialTask upright_line(double max_link_length) {
    return modsynth::io::parse_spatial_task_text(R"({
 "format": "modsynth-task/1", "name": "upright", "space": "3d",
 "trajectory": [{"type": "line", "start": [0.3, 0.0, 0.2], "end": [0.3, 0.0, 0.6]}],
 "base_regions": [{"min": [-0.05, -0.05, 0.0], "max": [0.05, 0.05, 0.02]}],
 "robot": {"dof": [3], "twists": [0.0], "max_link_length": )" +
                                                 std::to_string(max_link_length) + "}}");
}

}  // namespace

TEST_CASE("the spatial front stage's core is task parts", "[smt][spatial]") {
    modsynth::smt::SpatialFrontStage fs(upright_line(1.0), 3);
    REQUIRE(fs.check() == modsynth::smt::SpatialFrontStage::Result::Unsat);
    const std::vector<TaskPart> core = fs.minimal_core();
    CHECK(core ==
          std::vector<TaskPart>{TaskPart::trajectory(0), TaskPart::robot(RobotKey::Twists)});
    CHECK(fs.conflicts(core));
    CHECK_FALSE(fs.conflicts({TaskPart::trajectory(0)}));
    // The SMT-LIB script names its assumptions as the document does.
    CHECK(fs.smtlib().find("|robot.twists|") != std::string::npos);
}

TEST_CASE("the spatial front stage answers unknown past its deadline", "[smt][spatial]") {
    modsynth::smt::SpatialFrontStageOptions o;
    o.deadline = modsynth::run::Deadline::in(0.0);
    modsynth::smt::SpatialFrontStage fs(upright_line(1.0), 3, o);
    CHECK(fs.check() == modsynth::smt::SpatialFrontStage::Result::Unknown);
    CHECK(fs.minimal_core().empty());
}
