#pragma once
// The front stage (Z3 over nonlinear real arithmetic): a coarse, sound
// relaxation of the synthesis problem for one joint count. Its variables are
// the base and the link lengths; Booleans carry the discrete skeleton. Every
// constraint family is guarded by an assumption literal named after the
// task part it comes from, so an unsat answer is a proof of infeasibility
// whose core reads as an explanation.
#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include <modsynth/smt/skeleton.h>
#include <modsynth/task/task.h>

namespace modsynth::smt {

struct FrontStageOptions {
    double time_limit = 10.0;  ///< seconds per check
    /// Seconds for the refined level of a check (see front_stage.cpp).
    double refined_time_limit = 2.0;
    int samples_per_primitive = 8;
    unsigned seed = 0;
    /// No work past this instant: encoding stops (the check then answers
    /// Unknown), every check's timeout ends here, and core minimisation
    /// returns the core it has.
    std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
};

class FrontStage {
public:
    enum class Result { Sat, Unsat, Unknown };

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
    std::vector<std::string> minimal_core();
    /// True when these task parts alone are proved to conflict (unsat with
    /// only their literals assumed); false when satisfiable or undecided.
    bool conflicts(const std::vector<std::string>& parts);
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
