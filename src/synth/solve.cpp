#include <modsynth/synth/solve.h>

#include <algorithm>

#include <modsynth/hardware/select_dh_modules.h>
#include <modsynth/hardware/task_catalog.h>
#include <modsynth/synth/module_choice.h>
#include <modsynth/synth/spatial_module_choice.h>

namespace modsynth::synth {

Solution solve(const task::Task& task, SynthesisOptions options, SynthesisStats* stats) {
    SynthesisStats local;
    SynthesisStats& s = stats ? *stats : local;
    const hardware::TaskCatalog catalog = hardware::catalog_for(task);
    if (!catalog.note.empty()) s.notes.push_back(catalog.note);
    options.retime.joint_speed =
        std::min(options.retime.joint_speed, hardware::module_speed_cap(task, catalog.catalog));
    Solution solution = synthesize(task, options, &s);
    choose_modules(task, catalog.catalog, solution);
    return solution;
}

Solution solve(const task::SpatialTask& task, SpatialSynthesisOptions options,
               SynthesisStats* stats) {
    SynthesisStats local;
    SynthesisStats& s = stats ? *stats : local;
    std::string note;
    const std::optional<hardware::Catalog> catalog = hardware::spatial_catalog(task, &note);
    if (!note.empty()) s.notes.push_back(note);
    options.retime.joint_speed =
        std::min(options.retime.joint_speed, hardware::module_speed_cap(task, catalog));
    Solution solution = synthesize(task, options, &s);
    choose_modules(task, catalog, solution);
    return solution;
}

}  // namespace modsynth::synth
