#pragma once
// Changes of the task that break an obstacle proof (obstacle_proof.h): the
// moves a person can make when obstacles wall the path off. Each is applied
// to a copy of the task, and offered only when the proof no longer holds on
// that copy; whether the changed task is then feasible is for the caller
// to check (explanation.h re-checks every suggestion with the front stage).
#include <modsynth/prove/obstacle_proof.h>
#include <modsynth/task/part.h>
#include <modsynth/task/task.h>

#include <string>
#include <vector>

namespace modsynth::explanation {

struct WallChange {
    task::TaskPart part;  ///< the task part it changes (obstacles[3], base_regions)
    std::string change;   ///< in words and numbers
    task::Task changed;   ///< the task with the change applied
};

/// How much beyond the tube's diameter a widened gap is made (m): rounding
/// must not leave it closed, and a tube needs some room to pass.
constexpr double kGapMargin = 0.002;

/// The candidates of one kind of change, best first; every one breaks the
/// proof. The first kind removes one obstacle (the smallest whose removal
/// breaks the proof); the second widens the gap between two overlapping
/// no-go discs to at least link_diameter + kGapMargin, by moving one of the
/// obstacles away from the other, or by shrinking both; the third moves a
/// base region (keeping its size): inside the wall, to the path's side of
/// it, or along the detour to where the rest of the way is within reach.
/// At most `per_kind` candidates of each kind.
std::vector<std::vector<WallChange>> wall_changes(const task::Task& task, const prove::Proof& proof,
                                                  std::size_t per_kind = 3);

}  // namespace modsynth::explanation
