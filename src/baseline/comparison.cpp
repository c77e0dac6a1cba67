#include <modsynth/baseline/comparison.h>

#include <modsynth/run/stopwatch.h>

namespace modsynth::baseline {

Comparison compare_methods(const task::Task& task, const synth::SynthesisOptions& ours,
                           const BaselineOptions& theirs) {
    Comparison c;
    const run::Stopwatch t0;
    c.solution = synth::synthesize(task, ours);
    c.solve_seconds = t0.seconds();
    if (c.solution.status == synth::Status::Solved) {
        std::vector<std::vector<double>> waypoints;
        for (const auto& sample : c.solution.samples) waypoints.push_back(sample.q);
        c.fidelity = measure_fidelity(task, c.solution.robot, waypoints, theirs.fidelity);
    }
    c.baseline = run_baseline(task, theirs);
    return c;
}

}  // namespace modsynth::baseline
