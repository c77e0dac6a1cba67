#pragma once
// A list of task parts for a person to read.
#include <string>
#include <vector>

#include <modsynth/task/part.h>

namespace modsynth::task {

/// The names for a person to read, space-separated, with every run of three
/// or more consecutive primitives of one stroke said as its ends
/// ("trajectory[0] to trajectory[511] obstacles[0] robot.dof"): a proof
/// about a closed polyline names each of its segments.
std::string to_short_list(const std::vector<TaskPart>& parts);

}  // namespace modsynth::task
