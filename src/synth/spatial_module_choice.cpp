#include <modsynth/synth/spatial_module_choice.h>

#include <modsynth/hardware/select_dh_modules.h>

namespace modsynth::synth {

void choose_modules(const task::SpatialTask& task, const std::optional<hardware::Catalog>& catalog,
                    Solution& solution) {
    if (solution.status != Status::Solved || !catalog || !solution.dh_robot) return;
    solution.modules =
        hardware::select_modules(task, *solution.dh_robot, solution.samples, *catalog);
}

}  // namespace modsynth::synth
