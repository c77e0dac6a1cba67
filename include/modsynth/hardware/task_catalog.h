#pragma once
// The catalog a task's modules are chosen from, and what it implies for the
// motion's timing before any module is chosen.
#include <optional>
#include <string>

#include <modsynth/hardware/catalog.h>
#include <modsynth/task/task.h>

namespace modsynth::hardware {

struct TaskCatalog {
    /// The shipped catalog; none when it cannot be read and the task names
    /// no modules (the answer then has no choice of modules).
    std::optional<Catalog> catalog;
    std::string note;  ///< why there is none ("" when there is one)
};

/// The shipped catalog with the task's module names checked: throws
/// task::InputError naming robot.modules[i] for a name it lacks, and
/// CatalogError when a task that names modules finds no catalog.
TaskCatalog catalog_for(const task::Task& task);

/// The joint speed every allowed module reaches: a cap for timing a task
/// that names its modules but no robot.joint_limits, so that whichever
/// module is chosen runs the motion (infinity when the task names no
/// modules, or gives joint limits, or there is no catalog).
double module_speed_cap(const task::Task& task, const std::optional<Catalog>& catalog);

}  // namespace modsynth::hardware
