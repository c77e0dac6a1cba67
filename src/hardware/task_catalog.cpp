#include <modsynth/hardware/task_catalog.h>

#include <algorithm>
#include <limits>

#include <modsynth/hardware/select_modules.h>

namespace modsynth::hardware {

TaskCatalog catalog_for(const task::Task& task) {
    TaskCatalog out;
    try {
        out.catalog = load_default_catalog();
        allowed_actuators(task.robot, *out.catalog);  // throws InputError naming the key
    } catch (const CatalogError& e) {
        if (!task.robot.modules.empty()) throw;
        out.catalog.reset();
        out.note = std::string("modules not chosen: ") + e.what();
    }
    return out;
}

double module_speed_cap(const task::Task& task, const std::optional<Catalog>& catalog) {
    double cap = std::numeric_limits<double>::infinity();
    if (!catalog || task.robot.modules.empty() || task.robot.joint_limits) return cap;
    for (const Actuator* a : allowed_actuators(task.robot, *catalog))
        cap = std::min(cap, a->max_speed);
    return cap;
}

}  // namespace modsynth::hardware
