#pragma once
// Minimising a QuadraticProgram or a SmoothProgram. The implementation
// adapts Ipopt; its headers stay out of this interface.
#include <string>
#include <vector>

#include <modsynth/nlp/progress_watch.h>
#include <modsynth/nlp/quadratic_program.h>
#include <modsynth/nlp/smooth_program.h>
#include <modsynth/run/deadline.h>

namespace modsynth::nlp {

struct SolverOptions {
    /// Seconds of CPU time (Ipopt's max_cpu_time); callers shorten it to
    /// what is left of their own budget.
    double time_limit = 10.0;
    /// The caller's deadline on the wall clock, checked after each
    /// iteration (the CPU-time limit above is Ipopt's own measure).
    run::Deadline deadline;
    /// When a solve is doomed (diverging duals, a stalled primal
    /// infeasibility) and is stopped before its limits.
    ProgressWatchOptions watch;
    /// Ipopt iterations; the refinement converges in tens on every task
    /// shipped, so 500 only stops a run that is going nowhere.
    int max_iterations = 500;
    /// Ipopt's tol: relative optimality error at which it stops (scaled
    /// like lengths in m, so 1e-8 is far below a task's tolerances).
    double tolerance = 1e-8;
    /// Ipopt's constr_viol_tol, m or m^2: every constraint here is a
    /// length or a product of lengths, and the verifier adds the margins.
    double constraint_tolerance = 1e-9;
    /// Ipopt's acceptable_tol and acceptable_constr_viol_tol: a point this
    /// good is accepted as a solution after acceptable_iterations such
    /// iterations in a row. The verifier decides whether it is good enough:
    /// a robot is certified with margins, never on the NLP's word, and the
    /// last digits of the link lengths cost far more iterations (degenerate
    /// directions: free separating lines, transition bisectors) than they
    /// are worth. On planted 2- and 3-joint suites, 1e-5 m after one
    /// iteration answers with the same total link length to 1e-4 m in
    /// three quarters of the time.
    double acceptable_tolerance = 1e-5;
    double acceptable_constraint_tolerance = 1e-5;
    int acceptable_iterations = 1;
    /// A warm start's pushes away from bounds (Ipopt's warm_start_*_push
    /// and _frac) and its initial barrier parameter (mu_init).
    double warm_push = 1e-3;
    double warm_mu = 1e-3;
    /// Ipopt's print_level, 0 (silent) to 12.
    int print_level = 0;
    /// What factorizes Ipopt's KKT systems: modsynth's block LDLᵀ
    /// (nlp/block_ldl.h, which Ipopt loads as MA27), or Ipopt's MUMPS. The
    /// block LDLᵀ gives way to MUMPS where Ipopt cannot load it.
    enum class LinearSolver { BlockLdl, Mumps };
    LinearSolver linear_solver = LinearSolver::BlockLdl;
    /// On failure, how many of the most violated constraints (at the last
    /// iterate) SolverResult::message names.
    int reported_violations = 3;

    /// False (with `error` naming the field) when some value is out of range.
    bool IsValid(std::string* error) const;
};

struct SolverResult {
    enum class Status { Optimal, Acceptable, Infeasible, Failed };
    Status status = Status::Failed;
    std::vector<double> x;
    /// Multipliers at x: of the constraints, and of the variables' lower
    /// and upper bounds (for a warm start of a related program).
    std::vector<double> lambda, z_lower, z_upper;
    double objective = 0.0;
    int iterations = 0;
    std::string message;
    bool usable() const { return status == Status::Optimal || status == Status::Acceptable; }
};

/// Throws std::invalid_argument when the options are not valid. When no
/// usable point is found, the message gives Ipopt's status and the
/// constraints worst violated at its last iterate, by label. With `warm`,
/// Ipopt starts from its primal and dual point (sizes must match the
/// program's, or std::invalid_argument).
struct WarmStart;  // warm_start.h
SolverResult minimize(const QuadraticProgram& program, const SolverOptions& options,
                      const WarmStart* warm = nullptr);
/// The same with Ipopt's limited-memory approximation of the second
/// derivatives.
SolverResult minimize(const SmoothProgram& program, const SolverOptions& options,
                      const WarmStart* warm = nullptr);

}  // namespace modsynth::nlp
