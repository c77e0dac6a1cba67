#pragma once
// A task's whole answer, as `modsynth solve`, the server (which runs it) and
// the library give it.
#include <modsynth/synth/solution.h>
#include <modsynth/synth/spatial_synthesizer.h>
#include <modsynth/synth/synthesizer.h>
#include <modsynth/task/spatial_task.h>
#include <modsynth/task/task.h>

namespace modsynth::synth {

/// The synthesis, its motion timed within the speed every allowed module
/// reaches (hardware::module_speed_cap, on top of options.retime), and for
/// a solved motion the modules that carry it (module_choice.h). Throws
/// task::InputError when the task names a module the catalog lacks, and
/// std::invalid_argument when the options are not valid.
Solution solve(const task::Task& task, SynthesisOptions options, SynthesisStats* stats = nullptr);

/// The same for a spatial task (formats.md "Spatial tasks"): the spatial
/// synthesis, timed within the modules' speed, with the modules of a DH
/// chain (spatial_module_choice.h). A note on a missing catalog goes to
/// stats->notes, as in the plane.
Solution solve(const task::SpatialTask& task, SpatialSynthesisOptions options,
               SynthesisStats* stats = nullptr);

}  // namespace modsynth::synth
