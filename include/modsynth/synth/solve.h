#pragma once
// A task's whole answer, as `modsynth solve`, the server (which runs it) and
// the library give it.
#include <modsynth/synth/solution.h>
#include <modsynth/synth/synthesizer.h>
#include <modsynth/task/task.h>

namespace modsynth::synth {

/// The synthesis, its motion timed within the speed every allowed module
/// reaches (hardware::module_speed_cap, on top of options.retime), and for
/// a solved motion the modules that carry it (module_choice.h). Throws
/// task::InputError when the task names a module the catalog lacks, and
/// std::invalid_argument when the options are not valid.
Solution solve(const task::Task& task, SynthesisOptions options, SynthesisStats* stats = nullptr);

}  // namespace modsynth::synth
