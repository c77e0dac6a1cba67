#pragma once
// The module catalog for solve and export, and the modules chosen from it
// for a solved motion (hardware/select_modules.h).
#include <optional>

#include <modsynth/hardware/catalog.h>
#include <modsynth/synth/solution.h>
#include <modsynth/task/task.h>

namespace modsynth::app {

/// The catalog shipped with the program. A task that names modules needs
/// it, and its names are checked here (task::InputError naming
/// robot.modules[i]); without a catalog a task that names none goes on
/// without a choice of modules, and a note on stderr says why.
std::optional<hardware::Catalog> catalog_for(const task::Task& task);

/// Sets solution.modules for a solved solution when there is a catalog.
void choose_modules(const task::Task& task, const std::optional<hardware::Catalog>& catalog,
                    synth::Solution& solution);

}  // namespace modsynth::app
