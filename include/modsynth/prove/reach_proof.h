#pragma once
// The cheapest proof of infeasibility: a primitive that no allowed arm
// reaches from any allowed base. An arm of n links reaches no farther than
// n * robot.max_link_length, and the least over a base region of the
// distance to the primitive's farthest point has a proved lower bound
// (geometry/farthest_reach.h), so where that bound exceeds the longest
// allowed arm for every region, no design exists. The front stage proves
// the same with Z3, in tenths of a second where this takes milliseconds.
#include <optional>
#include <vector>

#include <modsynth/task/part.h>
#include <modsynth/task/task.h>

namespace modsynth::prove {

/// The core of such a proof for the primitive farthest out of reach:
/// robot.max_link_length, base_regions and that primitive's part name (a
/// minimal core: without any one of them the primitive can be reached).
/// nullopt when every primitive is within reach of some base in some region
/// as far as the bound can tell, and for tasks without base regions.
std::optional<std::vector<task::TaskPart>> out_of_reach_core(const task::Task& task);

}  // namespace modsynth::prove
