#pragma once
// Starting a solve where a related one ended: a later refinement round adds
// points to the previous round's program, and its old part starts from the
// last solution, multipliers included.
#include <vector>

#include <modsynth/nlp/quadratic_program.h>
#include <modsynth/nlp/solver.h>

namespace modsynth::nlp {

/// A primal-dual point to start from, aligned with the program solved.
struct WarmStart {
    std::vector<double> x, lambda, z_lower, z_upper;
};

/// A solution of `from` as a start of `to`, matched by variable key and by
/// constraint key (key.h; the k-th constraint of a key to the k-th). What
/// `to` adds, and whatever has no key, starts at its own start values with
/// zero multipliers.
WarmStart carry_over(const QuadraticProgram& from, const SolverResult& solved,
                     const QuadraticProgram& to);

}  // namespace modsynth::nlp
