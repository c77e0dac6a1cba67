#include <modsynth/hardware/select_dh_modules.h>

#include <algorithm>

#include <modsynth/hardware/dh_dynamics.h>
#include <modsynth/hardware/select_modules.h>

namespace modsynth::hardware {

std::vector<JointLoad> joint_loads(const DhArmModel& model,
                                   const std::vector<control::Sample>& samples) {
    const DhInverseDynamics dynamics(model);
    return joint_loads(model.chain.dof(), samples, [&](const control::Sample& s) {
        return dynamics.torques(s.q, s.qd, s.qdd);
    });
}

ModuleSelection select_modules(const task::SpatialTask& task, const kinematics::DhChain& chain,
                               const std::vector<control::Sample>& samples, const Catalog& catalog,
                               const std::vector<PrintedDhLink>& printed) {
    const std::vector<const Actuator*> allowed = allowed_actuators(task.robot.modules, catalog);
    const int n = chain.dof();
    const bool timed =
        !samples.empty() && std::all_of(samples.begin(), samples.end(), [&](const auto& s) {
            return static_cast<int>(s.qd.size()) == n && static_cast<int>(s.qdd.size()) == n;
        });
    if (!timed) {
        ModuleSelection out;
        out.message =
            "modules not chosen: the motion carries no joint rates and accelerations (qd, qdd)";
        return out;
    }
    return choose_modules(n, allowed, [&](const std::vector<const Actuator*>& modules) {
        return joint_loads(dh_arm_model(task.robot, chain, catalog, modules, printed), samples);
    });
}

std::vector<const Actuator*> strongest_modules(const task::SpatialTask& task, int dof,
                                               const Catalog& catalog) {
    const auto allowed = allowed_actuators(task.robot.modules, catalog);
    const auto strongest = std::max_element(
        allowed.begin(), allowed.end(),
        [](const Actuator* a, const Actuator* b) { return a->peak_torque < b->peak_torque; });
    return std::vector<const Actuator*>(static_cast<std::size_t>(dof), *strongest);
}

std::optional<Catalog> spatial_catalog(const task::SpatialTask& task, std::string* note) {
    try {
        Catalog catalog = load_default_catalog();
        allowed_actuators(task.robot.modules, catalog);  // throws InputError naming the key
        return catalog;
    } catch (const CatalogError& e) {
        if (!task.robot.modules.empty()) throw;
        if (note) *note = std::string("modules not chosen: ") + e.what();
        return std::nullopt;
    }
}

double module_speed_cap(const task::SpatialTask& task, const std::optional<Catalog>& catalog) {
    double cap = std::numeric_limits<double>::infinity();
    if (!catalog || task.robot.modules.empty() || task.robot.joint_limits) return cap;
    for (const Actuator* a : allowed_actuators(task.robot.modules, *catalog))
        cap = std::min(cap, a->max_speed);
    return cap;
}

}  // namespace modsynth::hardware
