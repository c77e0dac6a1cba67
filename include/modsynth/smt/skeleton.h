#pragma once
// The front stage's answer and the refinement's fixed input: the discrete
// choices of a candidate robot plus a coarse point that satisfies the
// front stage's relaxation. Where each primitive's critical points lie
// (paper Table I) is not part of it: they depend on the base, which the
// refinement moves, so they are recomputed for every candidate robot
// (synth's add_critical_points).
#include <vector>

#include <modsynth/geometry/vec.h>

namespace modsynth::smt {

struct Skeleton {
    int dof = 2;
    int elbow = 1;         ///< elbow sign of the distal pair, +1 or -1
    int base_region = -1;  ///< index into task.base_regions; -1 when unconstrained
    // The coarse feasible point of the relaxation.
    geometry::Vec2 base = geometry::Vec2::Zero();
    std::vector<double> link_lengths;
};

}  // namespace modsynth::smt
