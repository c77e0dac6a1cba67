#pragma once
// The discrete choices of a spatial design, which the spatial front stage
// hands to the initial guesses and the refinement: the joint count, the
// chain's pattern (a yaw column then pitch links, kinematics/yaw_pitch_ik.h)
// with the twist of its column and the sign of its column, and the base
// region; with a coarse point of the relaxation.
#include <vector>

#include <modsynth/geometry/vec3.h>

namespace modsynth::smt {

struct SpatialSkeleton {
    int dof = 3;
    /// Sign of alpha_1 (+pi/2 or -pi/2, whichever robot.twists allows);
    /// every other twist is 0.
    int column_twist = 1;
    /// Sign of d_1: +1 the shoulder above the base, -1 below it (a hanging
    /// arm), 0 no column (the shoulder at the base).
    int column = 1;
    /// Index in the task's base_regions, -1 when the base may be anywhere.
    int base_region = -1;
    /// A point of the relaxation: a base, d_1 and the pitch links a_2 ..
    /// a_n (n - 1 values) meeting the pattern's conditions at the sampled
    /// points.
    geometry::Vec3 base = geometry::Vec3::Zero();
    double column_length = 0.0;
    std::vector<double> links;
};

}  // namespace modsynth::smt
