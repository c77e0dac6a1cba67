#pragma once
// Explaining infeasible tasks: proofs over every allowed joint count, cores
// in task terms, a sentence a non-expert can act on, and the smallest
// changes that remove the conflict, each re-checked before it is offered.
#include <optional>
#include <string>
#include <vector>

#include <modsynth/synth/solution.h>
#include <modsynth/synth/status.h>
#include <modsynth/task/task.h>

namespace modsynth::synth {

struct InfeasibilityProof {
    bool proved = false;
    /// Task parts that conflict for every allowed joint count (minimal for
    /// each count on its own).
    std::vector<std::string> core;
    /// When not proved: which joint counts stayed satisfiable or undecided.
    std::string open;
    /// When proved: the proof in words, and the witnesses of an obstacle
    /// proof (then `core` is that proof's).
    std::string message;
    std::optional<SeparationWitness> separation;
    std::optional<GeodesicWitness> geodesic;
};

/// The front stage over every allowed joint count, within `time_limit`
/// seconds in all (a proof not finished by then is not one).
InfeasibilityProof prove_infeasible(const task::Task& task, double time_limit);

/// Among per-joint-count cores, one that conflicts for all of them when
/// there is such (checked with the front stage), else their union.
std::vector<std::string> common_core(const task::Task& task,
                                     const std::vector<std::vector<std::string>>& cores,
                                     double time_limit);

/// One sentence naming what conflicts, in the task's terms and units.
std::string describe_conflict(const task::Task& task, const std::vector<std::string>& core);

/// What one task part is, in words and numbers: "trajectory[2]: a line from
/// (0.40, 0.10) to (0.55, 0.10)".
std::string describe_part(const task::Task& task, const std::string& part);

struct Relaxation {
    std::string part;    ///< the core part it changes
    std::string change;  ///< e.g. "robot.max_link_length >= 1.34 m"
    task::Task relaxed;  ///< the task with the change applied
    /// The full pipeline on the relaxed task: what it concluded, and the
    /// same in a sentence ("solved: 2 joints, links ..." or why not).
    Status status;
    std::string outcome;
};

/// For each part of the core, the smallest change of that part alone that
/// makes the front stage satisfiable (found by bisection), re-checked, and
/// then tried with the full pipeline for `solve_seconds`. Everything ends
/// within `time_limit` seconds: the bisections stop there and the
/// suggestions found so far are returned.
std::vector<Relaxation> suggest_relaxations(const task::Task& task,
                                            const std::vector<std::string>& core,
                                            double solve_seconds, double time_limit = 1e6);

}  // namespace modsynth::synth
