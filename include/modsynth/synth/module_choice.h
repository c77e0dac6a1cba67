#pragma once
// The actuator modules of a solved motion (hardware/select_modules.h), as
// part of the answer. A motion no allowed module carries is still
// "solved": the contract's guarantees are about the motion, and hold; the
// choice names the overloaded joint, and the answer carries a warning.
#include <optional>
#include <string>

#include <modsynth/hardware/catalog.h>
#include <modsynth/synth/solution.h>
#include <modsynth/task/task.h>

namespace modsynth::synth {

/// Sets solution.modules for a solved solution when there is a catalog;
/// the status is left as it is.
void choose_modules(const task::Task& task, const std::optional<hardware::Catalog>& catalog,
                    Solution& solution);

/// When some joint is overloaded: a sentence naming the joint, the allowed
/// module with the most room, when the load is worst and by how much it
/// exceeds the rating, and the task parts that would change it; "" when
/// every joint is carried or no modules were chosen.
std::string overload_warning(const Solution& solution);

}  // namespace modsynth::synth
