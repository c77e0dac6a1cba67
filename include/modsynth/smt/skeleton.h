#pragma once
// The front stage's answer and the refinement's fixed input: the discrete
// choices of a candidate robot plus a coarse point that satisfies the
// front stage's relaxation.
#include <vector>

#include <modsynth/geometry/primitive.h>

namespace modsynth::smt {

struct PrimitiveChoice {
    /// Where the point of the primitive nearest to / farthest from the base
    /// lies (paper Table I).
    geometry::CriticalPoints::Where closest = geometry::CriticalPoints::Where::Start;
    geometry::CriticalPoints::Where farthest = geometry::CriticalPoints::Where::Start;
};

struct Skeleton {
    int dof = 2;
    int elbow = 1;         ///< elbow sign of the distal pair, +1 or -1
    int base_region = -1;  ///< index into task.base_regions; -1 when unconstrained
    std::vector<PrimitiveChoice> primitives;
    // The coarse feasible point of the relaxation.
    geometry::Vec2 base = geometry::Vec2::Zero();
    std::vector<double> link_lengths;
};

}  // namespace modsynth::smt
