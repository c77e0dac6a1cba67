#include <modsynth/synth/spatial_synthesizer.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <set>

#include <modsynth/control/joint_limits.h>
#include <modsynth/control/retime.h>
#include <modsynth/control/sample.h>
#include <modsynth/geometry/primitive3.h>
#include <modsynth/io/spatial_task_io.h>
#include <modsynth/kinematics/dh_chain.h>
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

TEST_CASE("spatial synthesis times its motion within the task's jerk limits", "[synth][spatial]") {
    // The same task without jerk limits and with them: the jerk-limited
    // motion starts and ends at rest with no acceleration, keeps every
    // limit between samples (the rules of formats.md), and takes longer.
    auto task = fixture("s3-0001.task.json");
    task.robot.joint_limits = modsynth::task::JointLimitsSpec{{2.0}, {5.0}};
    const auto free = modsynth::synth::synthesize(task, {});
    task.robot.joint_limits->jerk = {5.0};
    const auto limited = modsynth::synth::synthesize(task, {});
    REQUIRE(free.status == modsynth::synth::Status::Solved);
    REQUIRE(limited.status == modsynth::synth::Status::Solved);
    REQUIRE(limited.dh_robot);
    const auto limits = modsynth::control::joint_limits_for(task, limited.dh_robot->dof());
    REQUIRE(limits.jerk.size() == static_cast<std::size_t>(limited.dh_robot->dof()));
    CHECK(modsynth::control::timing_fault(limited.samples, limits).empty());
    for (const auto* end : {&limited.samples.front(), &limited.samples.back()})
        for (const double a : end->qdd) CHECK(std::abs(a) <= 1e-9);
    CHECK(limited.samples.back().t > free.samples.back().t);
    // The unlimited timing breaks the jerk rules: the test tells them apart.
    CHECK_FALSE(modsynth::control::timing_fault(
                    free.samples, modsynth::control::joint_limits_for(task, free.dh_robot->dof()))
                    .empty());
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

namespace {

/// The largest angle between the solved chain's tool and the wanted
/// direction at the trace samples of primitives with a tool axis, less
/// their tolerance (formats.md rule 6), measured here from the chain.
double worst_tool_excess(const modsynth::task::SpatialTask& task,
                         const modsynth::synth::Solution& s) {
    double worst = -1.0;
    for (const auto& x : s.samples) {
        if (x.phase != modsynth::control::Phase::Trace) continue;
        const int j = modsynth::control::primitive_index(task, x);
        const auto segments = modsynth::kinematics::chain_segments(*s.dh_robot, x.q);
        const auto wanted = modsynth::task::wanted_tool(task, j, segments.back().end);
        if (!wanted) continue;
        const auto tool = (segments.back().end - segments.back().start).normalized();
        worst = std::max(worst, std::acos(std::clamp(tool.dot(wanted->direction), -1.0, 1.0)) -
                                    wanted->tolerance);
    }
    return worst;
}

}  // namespace

TEST_CASE("a tool held along a direction or at an axis is designed for and certified",
          "[synth][spatial][slow]") {
    // Planted by the shared planter: straight down (a 4-joint arm), square
    // into a tilted plane (a wrist), square at a pipe's axis.
    for (const char* name : {"std-0001", "stn-0001", "stt-0001"}) {
        const auto task = fixture(std::string(name) + ".task.json");
        REQUIRE(modsynth::task::holds_tool(task));
        modsynth::synth::SpatialSynthesisOptions o;
        o.time_limit = 60.0;
        const auto s = modsynth::synth::synthesize(task, o);
        INFO(name << ": " << s.explanation.message);
        REQUIRE(s.status == modsynth::synth::Status::Solved);
        REQUIRE(s.dh_robot);
        CHECK(s.certificate.ok);
        CHECK(s.certificate.min_tool_angle_margin >= 0.0);
        CHECK(worst_tool_excess(task, s) <= 1e-9);
    }
}

TEST_CASE("a slanted tool no family can hold is not answered solved", "[synth][spatial]") {
    // Twists 0 only: a SCARA, whose tool is a quill straight down or a flat
    // link; a tool wanted 45 degrees from both is refused by the front stage,
    // naming the tool axis.
    auto task = modsynth::io::load_spatial_task(
        modsynth::testing::source_path("tasks/spatial/scara-dispense.json"));
    modsynth::task::ToolAxis axis;
    axis.direction = modsynth::geometry::Vec3(1.0, 0.0, -1.0);
    task.tool_axis = axis;
    modsynth::synth::SpatialSynthesisOptions o;
    o.time_limit = 10.0;
    const auto s = modsynth::synth::synthesize(task, o);
    REQUIRE(s.status == modsynth::synth::Status::Infeasible);
    const auto& core = s.explanation.core;
    CHECK(std::find(core.begin(), core.end(), TaskPart::tool_axis()) != core.end());
}
