#include <modsynth/explanation/explain.h>

#include <algorithm>
#include <vector>

#include <modsynth/explanation/spatial_explanation.h>
#include <modsynth/run/stopwatch.h>
#include <modsynth/synth/spatial_synthesizer.h>
#include <modsynth/synth/synthesizer.h>
#include <modsynth/text/option_check.h>

namespace modsynth::explanation {

bool ExplainOptions::IsValid(std::string* error) const {
    return text::OptionCheck("ExplainOptions", error)
        .at_least("time_limit", time_limit, 0.0)
        .greater("solve_seconds", solve_seconds, 0.0)
        .greater("proof_seconds", proof_seconds, 0.0)
        .ok();
}

namespace {

std::string unproved_message(const task::Task&, const InfeasibilityProof& proof,
                             const synth::Solution& s) {
    return unproved_message(proof, s);
}

// What a builder acts on first: the changes the synthesis confirmed
// (solved), then those it did not within its time, then those after which
// the task is still infeasible; in the order found within each.
void confirmed_first(std::vector<Relaxation>& suggestions) {
    const auto rank = [](const Relaxation& r) {
        return r.status == synth::Status::Solved       ? 0
               : r.status == synth::Status::Infeasible ? 2
                                                       : 1;
    };
    std::stable_sort(suggestions.begin(), suggestions.end(),
                     [&](const Relaxation& a, const Relaxation& b) { return rank(a) < rank(b); });
}

// Prove, else solve, else suggest: one flow for both kinds of task; the
// provers, the synthesis and the relaxers are the kind's own.
template <class TaskT, class Solve>
Explanation explain_flow(const TaskT& task, const ExplainOptions& options, Solve solve) {
    text::require_valid(options);
    const run::Stopwatch clock;
    const run::Deadline deadline = run::Deadline::in(options.time_limit);
    const auto left = [&] { return std::max(0.0, deadline.remaining()); };
    const auto say = [&](run::Stage stage, const char* message) {
        if (options.progress) options.progress({stage, message, clock.seconds()});
    };
    Explanation out;
    say(run::Stage::Proofs, "proving infeasibility");
    const InfeasibilityProof proof =
        prove_infeasible(task, std::min(options.proof_seconds, left()));
    if (!proof.proved) {
        // Not proved infeasible: say what a full run finds.
        say(run::Stage::Search, "solving the task");
        const synth::Solution s = solve(left());
        out.status = s.status;
        out.message = unproved_message(task, proof, s);
        out.core = s.explanation.core;
        out.separation = s.explanation.separation;
        out.geodesic = s.explanation.geodesic;
        out.enclosure = s.explanation.enclosure;
        return out;
    }
    out.proved = true;
    out.status = synth::Status(synth::Status::Kind::Infeasible);
    out.message = proved_message(proof);
    out.core = proof.core;
    out.separation = proof.separation;
    out.geodesic = proof.geodesic;
    out.enclosure = proof.enclosure;
    if (options.proved) options.proved(out);
    say(run::Stage::Explanation, "looking for the smallest changes");
    out.suggestions = suggest_relaxations(task, proof.core, options.solve_seconds, left());
    confirmed_first(out.suggestions);
    return out;
}

}  // namespace

Explanation explain(const task::Task& task, const ExplainOptions& options) {
    return explain_flow(task, options, [&](double seconds) {
        synth::SynthesisOptions o;
        o.time_limit = seconds;
        return synth::synthesize(task, o);
    });
}

Explanation explain(const task::SpatialTask& task, const ExplainOptions& options) {
    return explain_flow(task, options, [&](double seconds) {
        synth::SpatialSynthesisOptions o;
        o.time_limit = seconds;
        return synth::synthesize(task, o);
    });
}

}  // namespace modsynth::explanation
