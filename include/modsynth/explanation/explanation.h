#pragma once
// Explaining infeasible tasks: proofs over every allowed joint count, cores
// in task terms, a sentence a non-expert can act on, and the smallest
// changes that remove the conflict, each re-checked before it is offered.
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <modsynth/synth/solution.h>
#include <modsynth/synth/status.h>
#include <modsynth/task/part.h>
#include <modsynth/task/spatial_task.h>
#include <modsynth/task/task.h>

namespace modsynth::explanation {

struct InfeasibilityProof {
    bool proved = false;
    /// Task parts that conflict for every allowed joint count (minimal for
    /// each count on its own).
    std::vector<task::TaskPart> core;
    /// When not proved: which joint counts stayed satisfiable or undecided.
    std::string open;
    /// When proved: the proof in words, and the witnesses of an obstacle
    /// proof (then `core` is that proof's).
    std::string message;
    std::optional<prove::SeparationWitness> separation;
    std::optional<prove::GeodesicWitness> geodesic;
    std::optional<prove::EnclosureWitness> enclosure;
};

/// The provers of solve (provers.h), in the same order, then the front
/// stage over every allowed joint count, within `time_limit` seconds in all
/// (a proof not finished by then is not one).
InfeasibilityProof prove_infeasible(const task::Task& task, double time_limit);

/// What `explain` says: a proof in words ("Proved infeasible: ..."), or
/// without a proof what a full run `s` found.
std::string proved_message(const InfeasibilityProof& proof);
std::string unproved_message(const InfeasibilityProof& proof, const synth::Solution& s);

struct Relaxation {
    task::TaskPart part;  ///< the core part it changes
    std::string change;   ///< e.g. "robot.max_link_length >= 1.34 m"
    /// The task with the change applied (a spatial task for a spatial one).
    std::variant<task::Task, task::SpatialTask> relaxed;
    /// The full pipeline on the relaxed task: what it concluded, and the
    /// same in a sentence ("solved: 2 joints, links ..." or why not).
    synth::Status status;
    std::string outcome;
};

/// How the smallest changes are searched for. Each is found by bisection
/// over one number of the task, to the tolerance given here, and every
/// step of a bisection is one front-stage check.
struct RelaxationOptions {
    /// s: at most this per front-stage check; a check that takes longer
    /// counts as "still conflicting", so a suggestion is never unproved.
    double check_seconds = 5.0;
    /// m: the longest link a suggestion may ask for (robot.max_link_length
    /// is bisected up to this), far beyond any modular arm.
    double longest_link = 50.0;
    /// m: how far a base region may be grown on every side, or the path
    /// moved, in a suggestion.
    double farthest_move = 20.0;
    /// m: bisection tolerances: link lengths and moves (then rounded up to
    /// whole centimetres), the shortest link, the tube diameter and an
    /// obstacle's radius (then rounded down to whole millimetres).
    double length_tolerance = 0.005;
    double min_length_tolerance = 0.002;
    double diameter_tolerance = 0.0005;
    double radius_tolerance = 0.002;
    /// m: the thinnest tube and the smallest obstacle a suggestion may ask for.
    double thinnest_tube = 1e-4;
    double smallest_radius = 1e-3;

    /// False (with `error` naming the field) when some value is out of range.
    bool IsValid(std::string* error) const;
};

/// For each part of the core, the smallest change of that part alone that
/// makes the front stage satisfiable (found by bisection; one relaxer per
/// kind of part), re-checked, and then tried with the full pipeline for
/// `solve_seconds`. Everything ends within `time_limit` seconds: the
/// bisections stop there and the suggestions found so far are returned.
std::vector<Relaxation> suggest_relaxations(const task::Task& task,
                                            const std::vector<task::TaskPart>& core,
                                            double solve_seconds, double time_limit = 1e6,
                                            const RelaxationOptions& options = {});

}  // namespace modsynth::explanation
