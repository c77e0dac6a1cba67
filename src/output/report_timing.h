#pragma once
// The timing of the motion in the report: joint angles, velocities and
// accelerations against time, with the joint limits the motion was timed
// with drawn as dashed lines.
#include <string>

#include <modsynth/synth/solution.h>
#include <modsynth/task/task.h>

namespace modsynth::output::timing {

/// HTML section id="timing" with three SVG charts (id="chart-q", "chart-qd",
/// "chart-qdd"); "" when the solution is not solved or its samples carry no
/// velocities and accelerations.
std::string section(const task::Task& task, const synth::Solution& solution);

}  // namespace modsynth::output::timing
