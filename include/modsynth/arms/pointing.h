#pragma once
// The free numbers of a design (kinematics::ArmDesign::along) that the
// task's tool axes fix: at the ends of a primitive traced with a tool_axis,
// a family that can point its tool (arms::Family::pointing_along) points it
// at the wanted direction there, so that the refinement does not move them
// and the transitions sweep from the direction one primitive ends with to
// the one the next starts with.
#include <optional>
#include <vector>

#include <modsynth/arms/family.h>
#include <modsynth/task/spatial_task.h>

namespace modsynth::arms {

/// Per primitive (task order), per value of ArmDesign::along (the start
/// values then the end values): the value a tool axis fixes, or nothing.
using AlongPins = std::vector<std::vector<std::optional<double>>>;

/// Empty when the family fixes nothing for this task.
AlongPins along_pins(const Family& family, const task::SpatialTask& task, int dof, int variant);

/// Sets the pinned values in `along` (sized as ArmDesign::along) for the
/// primitives of strokes `first` to `last` (every stroke by default), each
/// moved by whole turns next to the value before it along the stroke, so
/// that no sweep turns the long way round.
void pin_along(const AlongPins& pins, const task::SpatialTask& task,
               std::vector<std::vector<double>>& along, int first = 0, int last = -1);

}  // namespace modsynth::arms
