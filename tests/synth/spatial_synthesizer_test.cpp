#include <modsynth/synth/spatial_synthesizer.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <set>

#include <modsynth/geometry/primitive3.h>
#include <modsynth/io/spatial_task_io.h>
#include <modsynth/prove/spatial_reach_proof.h>
#include <modsynth/task/part.h>
#include <modsynth/verify/spatial_verifier.h>

#include "../support/fixtures.h"

namespace {

using modsynth::run::ProgressEvent;
using modsynth::run::Stage;
using modsynth::task::RobotKey;
using modsynth::task::TaskPart;

modsynth::task::SpatialTask fixture(const std::string& name) {
    return modsynth::io::load_spatial_task(
        modsynth::testing::source_path("tests/fixtures/spatial/" + name));
}

}  // namespace

TEST_CASE("spatial synthesis tells its progress as typed events", "[synth][spatial]") {
    std::vector<ProgressEvent> events;
    modsynth::synth::SpatialSynthesisOptions o;
    o.progress = [&](const ProgressEvent& e) { events.push_back(e); };
    const auto s = modsynth::synth::synthesize(fixture("s3-0001.task.json"), o);
    REQUIRE(s.status == modsynth::synth::Status::Solved);
    std::set<Stage> stages;
    for (std::size_t i = 0; i < events.size(); ++i) {
        stages.insert(events[i].stage);
        CHECK(events[i].message.find('[') != 0);  // the console adds the clock, not the run
        if (i > 0) CHECK(events[i].elapsed >= events[i - 1].elapsed);
    }
    for (Stage st :
         {Stage::FrontStage, Stage::Search, Stage::Refinement, Stage::Verification, Stage::Timing})
        CHECK(stages.count(st) == 1);
}

TEST_CASE("spatial proofs carry their cores as task parts", "[synth][spatial]") {
    const auto task = fixture("sir-0001.task.json");
    const auto core = modsynth::prove::spatial_out_of_reach_core(task);
    REQUIRE(core);
    CHECK(*core == std::vector<TaskPart>{TaskPart::robot(RobotKey::MaxLinkLength),
                                         TaskPart::base_regions(), TaskPart::trajectory(0)});
    std::vector<ProgressEvent> events;
    modsynth::synth::SpatialSynthesisOptions o;
    o.progress = [&](const ProgressEvent& e) { events.push_back(e); };
    const auto s = modsynth::synth::synthesize(task, o);
    CHECK(s.status == modsynth::synth::Status::Infeasible);
    CHECK(s.explanation.core == *core);
    REQUIRE(events.size() == 1);
    CHECK(events[0].stage == Stage::Proofs);
}

TEST_CASE("spatial synthesis stops at its deadline with unknown", "[synth][spatial]") {
    modsynth::synth::SpatialSynthesisOptions o;
    o.time_limit = 0.0;
    const auto s = modsynth::synth::synthesize(fixture("s4-0010.task.json"), o);
    CHECK(s.status == modsynth::synth::Status::Unknown);
    CHECK(s.status.reason == "time limit");
}

TEST_CASE("a path at one height with every twist 0 is solved by a SCARA",
          "[synth][spatial][slow]") {
    const auto task = modsynth::io::load_spatial_task(
        modsynth::testing::source_path("tasks/spatial/scara-dispense.json"));
    REQUIRE(task.robot.twists == std::vector<double>{0.0});
    modsynth::synth::SpatialSynthesisOptions o;
    o.time_limit = 30.0;
    const auto s = modsynth::synth::synthesize(task, o);
    REQUIRE(s.status == modsynth::synth::Status::Solved);
    REQUIRE(s.dh_robot);
    for (const auto& row : s.dh_robot->rows) CHECK(row.alpha == 0.0);
    // Every joint axis vertical: the links at one height, the EE on the path.
    CHECK(s.certificate.ok);
    const auto again = modsynth::verify::certify(task, *s.dh_robot, s.samples,
                                                 modsynth::synth::verify_options_for(task, o));
    CHECK(again.ok);
}

TEST_CASE("a path at one height with twists 0 gets no yaw column", "[synth][spatial]") {
    auto task = modsynth::io::load_spatial_task(
        modsynth::testing::source_path("tasks/spatial/scara-dispense.json"));
    // A slanted line no vertical-axis chain can trace: proved so by the front
    // stage, naming the line and the twists.
    task.trajectory.push_back(modsynth::geometry::Line3{
        modsynth::geometry::end_point(task.trajectory.back()), {0.35, 0.1, 0.2}});
    modsynth::synth::SpatialSynthesisOptions o;
    o.time_limit = 10.0;
    const auto s = modsynth::synth::synthesize(task, o);
    REQUIRE(s.status == modsynth::synth::Status::Infeasible);
    const auto& core = s.explanation.core;
    CHECK(std::find(core.begin(), core.end(), TaskPart::trajectory(3)) != core.end());
    CHECK(std::find(core.begin(), core.end(), TaskPart::robot(RobotKey::Twists)) != core.end());
}
