#include "module_choice.h"

#include <algorithm>
#include <cstdio>
#include <limits>

#include <modsynth/hardware/select_modules.h>

#include "command.h"

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

double module_speed_cap(const task::Task& task, const std::optional<hardware::Catalog>& catalog) {
    double cap = std::numeric_limits<double>::infinity();
    if (!catalog || task.robot.modules.empty() || task.robot.joint_limits) return cap;
    for (const hardware::Actuator* a : hardware::allowed_actuators(task.robot, *catalog))
        cap = std::min(cap, a->max_speed);
    return cap;
}

void choose_modules(const task::Task& task, const std::optional<hardware::Catalog>& catalog,
                    synth::Solution& solution) {
    if (solution.status != synth::Status::Solved || !catalog) return;
    solution.modules = hardware::select_modules(task, solution.robot, solution.samples, *catalog);
    if (!solution.modules->checked || solution.modules->carried()) return;
    // A motion no allowed module carries is not an answer a person can build,
    // however certified its geometry: it is "unknown", and the explanation
    // names the joint, the module, the worst time and the margin, and the
    // task parts that would change it.
    std::vector<std::string> core;
    if (!task.robot.modules.empty()) core.push_back("robot.modules");
    if (task.robot.payload > 0.0) core.push_back("robot.payload");
    if (task.robot.gravity) core.push_back("robot.gravity");
    if (task.robot.joint_limits) core.push_back("robot.joint_limits");
    const std::string why = solution.modules->message;
    synth::Solution overloaded;
    overloaded.task_name = solution.task_name;
    overloaded.status = synth::Status(synth::Status::Unknown, "modules", "a joint is overloaded");
    overloaded.explanation.message =
        "The certified robot (" + robot_summary(solution.robot) +
        ") overloads its modules: " + why +
        ". Allow a stronger module (robot.modules), carry a lighter payload (robot.payload) "
        "or move more slowly (robot.joint_limits).";
    overloaded.explanation.core = std::move(core);
    solution = std::move(overloaded);
}

}  // namespace modsynth::app
