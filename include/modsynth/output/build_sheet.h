#pragma once
// A build sheet in Markdown for the person assembling the robot: the parts
// to get, the tube cut lengths (output/hardware.h), the heights of the
// stack, where the base goes and the joint angles of the start pose.
#include <string>

#include <modsynth/parts/printed_parts.h>
#include <modsynth/synth/solution.h>
#include <modsynth/task/task.h>

namespace modsynth::output {

/// The sheet for a solved solution; module sizes come from task.robot.
/// With `printed` (--parts), it lists the printed parts, their print
/// settings and screws (output/parts_export.h).
std::string build_sheet(const task::Task& task, const synth::Solution& solution,
                        const parts::PrintedParts* printed = nullptr);

/// The sheet's "Modules" section: the modules chosen to carry the motion
/// (hardware/select_modules.h), or what overloads; "" when the solution has
/// no choice.
std::string modules_section(const synth::Solution& solution);

}  // namespace modsynth::output
