#pragma once
// A synthesised robot: what the solution's "robot" object holds, plus the
// elbow branch its motion uses.
#include <vector>

#include <modsynth/geometry/vec.h>

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
    double total_length() const {
        double sum = 0.0;
        for (double r : link_lengths) sum += r;
        return sum;
    }
};

}  // namespace modsynth::kinematics
