#pragma once
// The actuator modules of a solved spatial motion
// (hardware/select_dh_modules.h), as part of the answer. A motion no allowed
// module carries stays "solved": the contract's guarantees are about the
// motion, and hold; the choice names the overloaded joint.
#include <optional>

#include <modsynth/hardware/catalog.h>
#include <modsynth/synth/solution.h>
#include <modsynth/task/spatial_task.h>

namespace modsynth::synth {

/// Sets solution.modules for a solved spatial solution when there is a
/// catalog; the status is left as it is.
void choose_modules(const task::SpatialTask& task, const std::optional<hardware::Catalog>& catalog,
                    Solution& solution);

}  // namespace modsynth::synth
