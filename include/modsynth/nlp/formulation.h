#pragma once
// The refinement problem (paper eq. 1) for a 2-joint robot with the
// skeleton fixed: variables are the base, the link lengths, the elbow
// position at every chosen point of the path and, per obstacle constraint, a
// separating direction; the objective is the total link length.
#include <vector>

#include <modsynth/kinematics/robot.h>
#include <modsynth/nlp/quadratic_program.h>
#include <modsynth/smt/skeleton.h>
#include <modsynth/task/task.h>

namespace modsynth::nlp {

/// How obstacles enter the problem.
enum class SweptVolume {
    /// SV^over (paper III-B): during primitive j the whole arm stays inside
    /// conv(disc(base, r_1) and primitive j); one separating line per
    /// obstacle and primitive keeps every obstacle out. Sound without any
    /// sampling, but conservative.
    Over,
    /// The arm itself at each chosen point: one separating line per link,
    /// point and nearby obstacle. Exact at those points; the certified
    /// verification covers the gaps and feeds violations back as new points.
    Sampled,
};

struct PathPoint {
    int primitive = 0;
    double s = 0.0;  ///< arc length along the primitive
};

struct Margins {
    double clearance = 0.003;  ///< m beyond radius + diameter/2
    double self = 0.002;       ///< m beyond the diameter (EE to link 1)
};

struct TwoLinkProblem {
    const task::Task* task = nullptr;
    smt::Skeleton skeleton;     ///< elbow sign and base region are fixed
    kinematics::Robot start;    ///< initial guess
    std::vector<PathPoint> points;
    SweptVolume swept = SweptVolume::Sampled;
    Margins margins;
    /// Sampled: obstacles farther than this from a link in the initial guess
    /// are left out at that point (the verification adds them back if needed).
    double obstacle_horizon = 0.10;
};

struct Formulation {
    QuadraticProgram program;
    int base_x = -1, base_y = -1;
    int r1 = -1, r2 = -1;
    int elbow = 1;
    double link_diameter = 0.0;
};

/// Builds the problem; the initial point comes from the start robot's IK
/// (points it cannot reach get the nearest feasible elbow).
Formulation formulate_two_link(const TwoLinkProblem& problem);

kinematics::Robot robot_from(const Formulation& f, const std::vector<double>& x);

}  // namespace modsynth::nlp
