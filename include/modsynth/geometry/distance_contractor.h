#pragma once
// An HC4 contractor (forward-backward propagation over the expression tree)
// for the constraint |a - b| = r between two points of the plane given as
// interval boxes and a length r >= 0: it narrows each interval to a hull of
// the values some solution of the constraint inside the boxes can take.
// Nothing that satisfies the constraint is ever removed.
#include <modsynth/geometry/interval.h>

namespace modsynth::geometry {

struct IntervalPoint {
    Interval x;
    Interval y;
    bool is_empty() const { return x.is_empty() || y.is_empty(); }
};

/// Narrows a, b and r to (a hull of) the solutions of |a - b| = r with
/// r >= 0. False when there is none in the boxes: then the arguments are
/// left in an unspecified state.
bool contract_distance(IntervalPoint& a, IntervalPoint& b, Interval& r);

/// Narrows x to the solutions of x^2 in s (both signs of the root): the
/// backward step of sqr. False when there is none.
bool contract_sqr(Interval& x, const Interval& s);

}  // namespace modsynth::geometry
