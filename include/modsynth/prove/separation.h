#pragma once
// Proof by separation: a cycle of overlapping no-go discs closes a wall, and
// every base region lies on the other side of it from a point of the path.
// An arm is a connected tube from its base to its end-effector, so it would
// have to cross the wall; the polygon through the cycle's centres lies
// inside the discs, so no arm of any joint count or link lengths can.
#include <modsynth/prove/wall_witness.h>
#include <modsynth/task/task.h>

#include <optional>
#include <vector>

namespace modsynth::prove {

/// A wall for every base region, using only the listed obstacles (each
/// wall the shortest such cycle found); nullopt when there is none, or when
/// the task has no base regions (the base could stand anywhere).
std::optional<SeparationWitness> prove_separation(const task::Task& task,
                                                  const std::vector<int>& obstacles);

/// Whether one wall (cycle around the path point) keeps every free position
/// of its base region on the other side: decided on the polygon through the
/// centres, a region cell at a time where the polygon crosses the region.
bool wall_separates(const task::Task& task, const Wall& wall);

}  // namespace modsynth::prove
