#pragma once
// A list of task parts for a person to read.
#include <cstddef>
#include <string>
#include <vector>

#include <modsynth/task/part.h>

namespace modsynth::task {

/// A run of parts of a list, [first, last] (indices into it): consecutive
/// primitives of one stroke, or consecutive obstacles; any other part is a
/// run of one.
struct PartRun {
    std::size_t first = 0;
    std::size_t last = 0;
    std::size_t size() const { return last - first + 1; }
};
std::vector<PartRun> part_runs(const std::vector<TaskPart>& parts);

/// One run for a person to read: its ends for three parts or more
/// ("obstacles[0] to obstacles[79]"), else the names.
std::string run_text(const std::vector<TaskPart>& parts, const PartRun& run);

/// The names for a person to read, space-separated, with every run of three
/// or more consecutive primitives of one stroke, or obstacles, said as its
/// ends ("trajectory[0] to trajectory[511] obstacles[0] robot.dof"): a proof
/// about a closed polyline names each of its segments, a shell of spheres
/// each sphere.
std::string to_short_list(const std::vector<TaskPart>& parts);

}  // namespace modsynth::task
