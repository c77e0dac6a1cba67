#include "module_choice.h"

#include <cstdio>

#include <modsynth/hardware/select_modules.h>

namespace modsynth::app {

std::optional<hardware::Catalog> catalog_for(const task::Task& task) {
    try {
        hardware::Catalog catalog = hardware::load_default_catalog();
        hardware::allowed_actuators(task.robot, catalog);  // throws InputError naming the key
        return catalog;
    } catch (const hardware::CatalogError& e) {
        if (!task.robot.modules.empty()) throw;
        std::fprintf(stderr, "note: modules not chosen: %s\n", e.what());
        return std::nullopt;
    }
}

void choose_modules(const task::Task& task, const std::optional<hardware::Catalog>& catalog,
                    synth::Solution& solution) {
    if (solution.status != synth::Status::Solved || !catalog) return;
    solution.modules = hardware::select_modules(task, solution.robot, solution.samples, *catalog);
}

}  // namespace modsynth::app
