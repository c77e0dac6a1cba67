#pragma once
// The pipeline: Z3 front stage (skeleton, proof of infeasibility), Ipopt
// refinement with counterexamples from the certified verification, control.
#include <functional>
#include <string>

#include <modsynth/control/motion.h>
#include <modsynth/synth/solution.h>
#include <modsynth/task/task.h>

namespace modsynth::synth {

struct SynthesisOptions {
    double time_limit = 60.0;  ///< seconds, wall clock, for the whole run
    unsigned seed = 0;         ///< varies the initial guesses deterministically
    control::MotionOptions motion;
    /// Called with one line per stage event (may be empty).
    std::function<void(const std::string&)> progress;
};

/// Statistics of one run, kept out of the solution so that solutions stay
/// byte-identical across runs.
struct SynthesisStats {
    double front_seconds = 0.0;
    double refine_seconds = 0.0;
    double verify_seconds = 0.0;
    int skeletons = 0;
    int nlp_solves = 0;
    int counterexamples = 0;
};

Solution synthesize(const task::Task& task, const SynthesisOptions& options,
                    SynthesisStats* stats = nullptr);

}  // namespace modsynth::synth
