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

/// The joint speed every allowed module reaches: a cap for timing a task
/// that names its modules but no robot.joint_limits, so that whichever module
/// is chosen runs the motion (infinity when the task names no modules).
double module_speed_cap(const task::Task& task, const std::optional<hardware::Catalog>& catalog);

/// Sets solution.modules for a solved solution when there is a catalog. When
/// no allowed module carries some joint, the answer becomes "unknown" with
/// an explanation naming the joint, the module, the worst time and margin.
void choose_modules(const task::Task& task, const std::optional<hardware::Catalog>& catalog,
                    synth::Solution& solution);

}  // namespace modsynth::app
