#pragma once
// The timing of the motion in the report: joint angles, velocities,
// accelerations and jerks against time, with the joint limits the motion
// was timed with drawn as dashed lines, and the tool's speed along the path.
#include <string>

#include <modsynth/synth/solution.h>
#include <modsynth/task/task.h>

namespace modsynth::output::timing {

/// HTML section id="timing" with SVG charts of joint angles, velocities,
/// accelerations and jerks (id="chart-q", "chart-qd", "chart-qdd",
/// "chart-jerk", the jerk limits dashed when the task has them) and of the
/// tool's speed along the path ("chart-tool-speed"); "" when the solution
/// is not solved or its samples carry no velocities and accelerations.
std::string section(const task::Task& task, const synth::Solution& solution);

}  // namespace modsynth::output::timing
