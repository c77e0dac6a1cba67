#pragma once
// The front stage (Z3 over nonlinear real arithmetic): a coarse, sound
// relaxation of the synthesis problem for one joint count. Its variables are
// the base and the link lengths; Booleans carry the discrete skeleton. Every
// constraint family is guarded by an assumption literal named after the
// task part it comes from, so an unsat answer is a proof of infeasibility
// whose core reads as an explanation.
#include <memory>
#include <string>
#include <vector>

#include <modsynth/run/deadline.h>
#include <modsynth/smt/skeleton.h>
#include <modsynth/task/part.h>
#include <modsynth/task/task.h>

namespace modsynth::smt {

struct FrontStageOptions {
    /// Seconds of Z3 time per check of the reach-only relaxation, which
    /// nlsat decides in milliseconds on every task shipped: 10 s leaves room
    /// for hard cases while a run still tries every joint count in a minute.
    double time_limit = 10.0;
    /// Seconds for the refined level of a check (inner radius, exact
    /// critical points), which can take nlsat seconds even when switched
    /// off: past 2 s the coarse model is used instead.
    double refined_time_limit = 2.0;
    /// Paths of more primitives than this skip the refined level: it grows
    /// faster than the path (about 0.45 s at 160 primitives, 1.8 s at 640,
    /// near its time limit) and, on a task the coarse level finds
    /// satisfiable, mostly improves the start the refinement gets. A task
    /// that only the refined level proves infeasible answers unknown past
    /// this size.
    int refined_max_primitives = 150;
    /// Whether checks after a skeleton was blocked run the refined level
    /// too. Its unsat answer is then no proof, only the end of the
    /// skeletons, and the coarse model names the next skeleton as well: a
    /// second refined check cost 0.15 s on a 40-primitive path.
    bool refine_after_block = false;
    /// Intervals sampled along each primitive for the reach atoms. More
    /// samples tighten the relaxation (every one is sound); 8 catch the
    /// far side of every arc of the shipped tasks.
    int samples_per_primitive = 8;
    /// Sampled points over the whole path: a long path gets fewer per
    /// primitive (never fewer than its ends), which keeps the encoding, and
    /// the time Z3 takes to build and tear it down, within a time limit.
    /// 2000: paths up to 250 primitives keep every sample; at 640 primitives
    /// the front stage takes 0.4 s instead of 0.75 s (4000), for the same
    /// skeletons on the planted tasks of `scripts/bench --scale`.
    int encoded_points = 2000;
    /// Seconds for each check while a core is minimised: the larger of
    /// these and this factor times what the conflict itself took (within
    /// the time limit). An undecided check keeps its literal in the core.
    double core_trial_seconds = 0.5;
    double core_trial_factor = 4.0;
    /// Up to this many primitives every pair gets its span constraint;
    /// beyond, each primitive gets the span to its farthest partner only,
    /// which keeps the encoding linear in the path.
    int all_span_pairs = 64;
    /// Convex-hull vertices searched for farthest partners: any sampled
    /// point gives a sound span, so a subsample bounds the work.
    int hull_probe = 256;
    /// m (m^2 for squared atoms): every constraint is loosened by this much
    /// so that the decimal rounding of task numbers never makes the
    /// relaxation unsound; far below any length a task states.
    double slack = 1e-7;
    /// No work past this instant: encoding stops (the check then answers
    /// Unknown), every check's timeout ends here, and core minimisation
    /// returns the core it has.
    run::Deadline deadline;

    /// False (with `error` naming the field) when some value is out of range.
    bool IsValid(std::string* error) const;
};

class FrontStage {
public:
    enum class Result { Sat, Unsat, Unknown };

    /// Throws std::invalid_argument when the options are not valid.
    FrontStage(const task::Task& task, int dof, const FrontStageOptions& options = {});
    ~FrontStage();
    FrontStage(const FrontStage&) = delete;
    FrontStage& operator=(const FrontStage&) = delete;

    /// Looks for a skeleton not blocked so far.
    Result check();
    /// After Sat: the skeleton and the coarse point of the relaxation.
    Skeleton skeleton() const;
    /// Excludes the discrete choices of this skeleton (elbow, base region)
    /// from later checks.
    void block(const Skeleton& skeleton);
    /// True once a skeleton was blocked: an Unsat then means the skeletons
    /// are exhausted, not that the task is infeasible.
    bool exhausted_by_blocking() const;
    /// After Unsat (before any block): the task parts whose constraints
    /// conflict, as named in formats.md, shrunk to a minimal set by deletion.
    /// Empty if the conflict cannot be re-established.
    std::vector<task::TaskPart> minimal_core();
    /// True when these task parts alone are proved to conflict (unsat with
    /// only their literals assumed); false when satisfiable or undecided.
    bool conflicts(const std::vector<task::TaskPart>& parts);
    /// The encoding as an SMT-LIB2 script (assumption literals as named
    /// Booleans), for regression suites.
    std::string smtlib() const;
    /// Why the last check answered Unknown.
    std::string reason_unknown() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace modsynth::smt
