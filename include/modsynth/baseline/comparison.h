#pragma once
// modsynth and the discretized baseline on one task, in one run, measured
// the same way.
#include <optional>

#include <modsynth/baseline/baseline.h>
#include <modsynth/synth/synthesizer.h>

namespace modsynth::baseline {

struct Comparison {
    synth::Solution solution;
    double solve_seconds = 0.0;
    /// Measured over the solution's joint-linear motion; solved only.
    std::optional<Fidelity> fidelity;
    BaselineResult baseline;
};

Comparison compare_methods(const task::Task& task, const synth::SynthesisOptions& ours,
                           const BaselineOptions& theirs);

}  // namespace modsynth::baseline
