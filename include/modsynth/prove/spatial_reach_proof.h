#pragma once
// The cheapest proof of infeasibility in space: a primitive that no allowed
// chain reaches from any allowed base. No EE of an n-joint chain gets
// farther from its base than the sum of its |a_k| + |d_k|, at most
// 2 n robot.max_link_length; and wherever the base stands in a box, some
// point of the primitive lies at least the primitive's largest distance
// from the box away (the largest distance of a point of the primitive to
// the box, attained, hence a lower bound). Where that exceeds the longest
// chain for every base box, no design exists.
#include <optional>
#include <string>
#include <vector>

#include <modsynth/task/part.h>
#include <modsynth/task/spatial_task.h>

namespace modsynth::prove {

/// The core of such a proof for the primitive farthest out of reach:
/// robot.max_link_length, base_regions, that primitive's part name and,
/// when a chain of more joints than robot.dof allows (up to 6) could reach
/// it, robot.dof. nullopt when every primitive is within reach of some box,
/// and for tasks without base regions.
std::optional<std::vector<task::TaskPart>> spatial_out_of_reach_core(const task::SpatialTask& task);

/// The proof's sentence, naming the primitive, the distance and the reach.
std::string describe_spatial_reach(const task::SpatialTask& task,
                                   const std::vector<task::TaskPart>& core);

}  // namespace modsynth::prove
