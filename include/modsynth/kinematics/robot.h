#pragma once
// A synthesised robot: what the solution's "robot" object holds, plus the
// elbow branch its motion uses.
#include <vector>

#include <modsynth/geometry/vec.h>
#include <modsynth/kinematics/chain_layout.h>

namespace modsynth::kinematics {

struct Robot {
    geometry::Vec2 base = geometry::Vec2::Zero();
    std::vector<double> link_lengths;  ///< r_1 .. r_n, n = dof
    double link_diameter = 0.0;
    /// Elbow sign of the distal pair (kinematics::elbow_sign), one for the
    /// whole motion: with two joints the arm cannot change branch at a
    /// transition point (paper III-F-2a).
    int elbow = 1;
    /// Three joints only: q_1 while each primitive is traced. The proximal
    /// link stays still during a primitive (paper III-A) and sweeps between
    /// these angles, the short way round, at the transition points.
    std::vector<double> proximal_angles;

    int dof() const { return static_cast<int>(link_lengths.size()); }
    /// Three joints: a proximal link that stands still while tracing.
    bool has_proximal_link() const { return kinematics::has_proximal_link(dof()); }

    /// The point the distal pair of links turns about (paper III-A): the base
    /// with two joints; with three, the end of the proximal link at absolute
    /// angle q1.
    geometry::Vec2 distal_origin(double q1) const {
        return has_proximal_link() ? geometry::Vec2(base + link_lengths[0] * geometry::unit(q1))
                                   : base;
    }
    /// The same while primitive j is traced, the proximal link still at
    /// proximal_angles[j].
    geometry::Vec2 tracing_origin(int j) const {
        return has_proximal_link() ? distal_origin(proximal_angles.at(j)) : base;
    }
    double total_length() const {
        double sum = 0.0;
        for (double r : link_lengths) sum += r;
        return sum;
    }
};

}  // namespace modsynth::kinematics
