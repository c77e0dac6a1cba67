#pragma once
// A build sheet in Markdown for a spatial arm (a DH chain): the parts to
// get, each tube's cut length, the bracket each twist needs
// (hardware/dh_stack.h), the modules that carry the motion, where the base
// goes and the joint angles of the start pose; without an arm, why not.
#include <string>

#include <modsynth/parts/printed_parts.h>
#include <modsynth/synth/solution.h>
#include <modsynth/task/spatial_task.h>

namespace modsynth::output {

/// The sheet for a solved spatial solution (solution.dh_robot); sizes come
/// from task.robot. With `printed` (--parts), it lists the printed parts,
/// their print settings and screws (output/parts_export.h). For an
/// infeasible or unknown one, why there is no arm: the explanation's
/// message, its core and a wall's obstacles.
std::string build_sheet(const task::SpatialTask& task, const synth::Solution& solution,
                        const parts::PrintedParts* printed = nullptr);

}  // namespace modsynth::output
