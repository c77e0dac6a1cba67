#pragma once
// A finite-difference check of a QuadraticProgram's derivatives, for every
// NLP modsynth builds (the refinement and the baseline's design): central
// differences of the objective, the constraints and the Lagrangian's
// gradient against the exact gradient, Jacobian and Hessian at a random
// point near the start.
#include <modsynth/nlp/quadratic_program.h>

namespace modsynth::testing {

struct DerivativeErrors {
    double gradient = 0.0;  ///< largest absolute error of the objective's gradient
    double jacobian = 0.0;  ///< ... of any Jacobian entry
    double hessian = 0.0;   ///< ... of any entry of the Lagrangian's Hessian
};

/// `seed` picks the point (start + up to 0.1 per variable) and the
/// multipliers of the Lagrangian.
DerivativeErrors derivative_errors(const nlp::QuadraticProgram& qp, unsigned seed);

/// Checks that every error is below `tolerance` (Catch2 CHECKs).
void check_derivatives(const nlp::QuadraticProgram& qp, unsigned seed, double tolerance = 1e-6);

}  // namespace modsynth::testing
