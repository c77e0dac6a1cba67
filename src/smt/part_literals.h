#pragma once
// What both front stages do with Z3 besides their own encodings: one
// assumption literal per task part (named as the part, so that an SMT-LIB
// script reads as the task does), checks whose timeout ends at the run's
// deadline and that a cancelled run interrupts, and the deletion that
// shrinks a conflict to a minimal core. Z3 stays inside the smt stage: this
// header is not public.
#include <z3++.h>

#include <map>
#include <string>
#include <vector>

#include <modsynth/run/deadline.h>
#include <modsynth/task/part.h>

namespace modsynth::smt {

class PartLiterals {
public:
    explicit PartLiterals(z3::context& ctx) : ctx_(ctx) {}

    /// The part's literal, made on first use.
    z3::expr literal(const task::TaskPart& part);
    /// `e` guarded by the literals of `parts`: it holds when they are all
    /// assumed.
    z3::expr guarded(std::initializer_list<task::TaskPart> parts, const z3::expr& e);
    /// Every literal made so far, in the order they were made.
    z3::expr_vector all() const;
    /// The literals of those parts that have one.
    z3::expr_vector of(const std::vector<task::TaskPart>& parts) const;
    /// The parts of `literals`, in the order their literals were made (the
    /// task's order), not Z3's.
    std::vector<task::TaskPart> parts_of(const std::vector<z3::expr>& literals) const;
    /// The solver's assertions as an SMT-LIB2 script that ends with a
    /// check-sat-assuming over every part, so that running the file alone
    /// (z3 FILE) answers as the front stage does.
    std::string script(z3::solver& solver) const;

private:
    z3::context& ctx_;
    std::vector<task::TaskPart> parts_;
    std::map<task::TaskPart, z3::expr> literal_of_;
};

/// Core tracking on, and a timeout of `seconds` that ends at the deadline
/// whatever the per-check budget.
void set_timeout(z3::context& ctx, z3::solver& solver, double seconds,
                 const run::Deadline& deadline);

/// solver.check(assumptions), interrupted when the deadline's cancel token
/// is cancelled while it runs (an unknown answer then).
z3::check_result check(z3::context& ctx, z3::solver& solver, const z3::expr_vector& assumptions,
                       const run::Deadline& deadline);

struct CoreBudget {
    double seconds = 10.0;       ///< for re-establishing the conflict
    double trial_seconds = 0.5;  ///< each trial, at least ...
    double trial_factor = 4.0;   ///< ... or this times what the conflict took
};

/// The conflict among `assumptions`, shrunk by deletion: each literal whose
/// absence keeps the conflict is dropped (a trial's own smaller core is
/// taken whole). An undecided trial keeps its literal, so that the result
/// stays a conflict; at the deadline the core found so far is returned.
/// Empty when the assumptions are not (or no longer) in conflict.
std::vector<z3::expr> minimal_core(z3::context& ctx, z3::solver& solver,
                                   const z3::expr_vector& assumptions, const CoreBudget& budget,
                                   const run::Deadline& deadline);

}  // namespace modsynth::smt
