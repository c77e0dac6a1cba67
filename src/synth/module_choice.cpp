#include <modsynth/synth/module_choice.h>

#include <modsynth/hardware/select_modules.h>

namespace modsynth::synth {

void choose_modules(const task::Task& task, const std::optional<hardware::Catalog>& catalog,
                    Solution& solution) {
    if (solution.status != Status::Solved || !catalog) return;
    solution.modules = hardware::select_modules(task, solution.robot, solution.samples, *catalog);
}

std::string overload_warning(const Solution& solution) {
    if (!solution.modules || !solution.modules->checked || solution.modules->carried()) return "";
    return "the certified robot overloads its modules: " + solution.modules->message +
           ". Allow a stronger module (robot.modules), carry a lighter payload (robot.payload) "
           "or move more slowly (robot.joint_limits).";
}

}  // namespace modsynth::synth
