#pragma once
// A sparse LDLᵀ factorization for the KKT systems of an interior-point
// refinement, whose factor lives in memory the caller owns.
//
// Ipopt factorizes a saddle-point matrix [W J'; J -δ] about twice per
// iteration. For the few hundred to few thousand rows of a refinement, a
// general multifrontal solver spends most of each call on bookkeeping, not
// on arithmetic. This one is a plain up-looking LDLᵀ with a pivot order
// fixed before the numbers are known, made to hold on such matrices: a row
// whose diagonal is negligible (a constraint row) is paired with a
// neighbour, and the pair is eliminated as one 2×2 pivot, whose determinant
// is about −a² whatever the neighbour's own diagonal. The inertia (the
// number of negative eigenvalues) comes out of D, as Ipopt needs it.
//
// No pivoting happens during the numeric phase. A pivot that is still
// negligible is replaced by a small one of the same sign and counted in
// `Factorization::regularized`; the solve is then of a nearby matrix, and
// the caller's iterative refinement makes up the difference.
#include <cstddef>
#include <span>

namespace modsynth::nlp::ldl {

/// A symmetric n×n matrix given by the entries of one triangle, in any
/// order; an entry given twice is summed. Indices start at `base` (1 for
/// Fortran callers).
struct SymmetricTriplets {
    int n = 0;
    std::span<const int> rows, cols;
    std::span<const double> values;  // empty when only the pattern is known
    int base = 0;
};

/// Sizes a factorization needs in the caller's arrays.
struct Workspace {
    std::size_t ints = 0, reals = 0;
};

/// The elimination order: `3n` ints (order, position of each row, partner
/// of each row), written by `choose_order` and kept by the caller between
/// factorizations of matrices with the same pattern.
std::size_t order_size(int n);

/// An elimination order for the pattern alone (no row is paired yet), and
/// the workspace a factorization in that order needs.
Workspace choose_order(const SymmetricTriplets& pattern, std::span<int> order);

struct Factorization {
    enum class Status { Ok, NeedInts, NeedReals, BadIndex };
    Status status = Status::Ok;
    Workspace needed;        // when status is NeedInts or NeedReals
    int negative = 0;        // eigenvalues of the matrix below zero
    int regularized = 0;     // pivots replaced because they were negligible
    bool reordered = false;  // the order was recomputed from these values
};

/// Factorizes `matrix` (values required) into `ints` and `reals`. The order
/// is reused while every negligible diagonal has its partner, and
/// recomputed (with pairs) otherwise.
Factorization factorize(const SymmetricTriplets& matrix, std::span<int> order, std::span<int> ints,
                        std::span<double> reals);

/// True when Ipopt's `linear_solver ma27` gets this factorization: the
/// library that holds it (libhsl.so, see src/nlp/ma27_interface.cpp) is
/// loaded under the name Ipopt's loader asks for.
bool serves_as_ma27();

/// Solves with a factorization `factorize` wrote: `rhs` (n values) is
/// overwritten with the solution; `work` holds at least n values.
void solve(std::span<const int> ints, std::span<const double> reals, std::span<double> rhs,
           std::span<double> work);

}  // namespace modsynth::nlp::ldl
