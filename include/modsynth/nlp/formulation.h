#pragma once
// The refinement problem (paper eq. 1) with the skeleton fixed. Variables:
// the base, the link lengths, for three joints the end of the proximal link
// during each primitive and at poses inside each transition, the elbow of
// the distal pair at every chosen point and, per clearance constraint, a
// separating direction. Objective: the total link length. Every constraint
// is bilinear, so derivatives are exact.
#include <vector>

#include <modsynth/kinematics/robot.h>
#include <modsynth/nlp/quadratic_program.h>
#include <modsynth/smt/skeleton.h>
#include <modsynth/task/task.h>

namespace modsynth::nlp {

/// How obstacles enter the problem.
enum class SweptVolume {
    /// SV^over (paper III-B): during primitive j the distal pair stays
    /// inside conv(disc(o_j, r_a) and primitive j), o_j the point it turns
    /// about (the base, or with three joints the end of the proximal link,
    /// which is static during j) and r_a its first link; one separating line
    /// per obstacle and primitive keeps every obstacle out. Sound without
    /// any sampling, but conservative.
    Over,
    /// The arm itself at each chosen point: one separating line per link,
    /// point and nearby obstacle. Exact at those points; the certified
    /// verification covers the gaps and feeds violations back as new points.
    Sampled,
    /// SV^app (paper III-D): the elbow's arc e_j during primitive j is
    /// taken from the elbows at the chosen points of j (the angularly
    /// extreme two are its ends); link a sweeps the pentagon o_j, e_j.p1,
    /// two tangent corners, e_j.p2 (a sector's over-approximation), link b
    /// the hull of the arc's quadrilateral and primitive j. One separating
    /// line per obstacle, primitive and polygon (eqs. 3 and 4). Not sound:
    /// the elbow may leave e_j between the points, so the certified
    /// verification decides.
    App,
};

struct PathPoint {
    int primitive = 0;
    double s = 0.0;  ///< arc length along the primitive
};

struct Margins {
    double clearance = 0.003;  ///< m beyond radius + diameter/2
    double self = 0.002;       ///< m beyond the diameter (EE to lower links)
};

struct ArmProblem {
    const task::Task* task = nullptr;
    smt::Skeleton skeleton;   ///< joint count, elbow sign and base region are fixed
    kinematics::Robot start;  ///< initial guess (with proximal angles for 3 joints)
    std::vector<PathPoint> points;
    SweptVolume swept = SweptVolume::Sampled;
    /// With Over or App: the swept volume alone keeps obstacles off the
    /// links while primitives are traced (the paper's eq. 1), no separating
    /// line per link and point. Proximal poses and transitions keep theirs.
    bool swept_only = false;
    Margins margins;
    /// Clearance constraints whose parts are farther apart than this in the
    /// initial guess are left out (the verification adds them back if needed).
    double horizon = 0.10;
    /// Three joints: 2^depth - 1 proximal poses inside each transition.
    /// Seven poses (depth 3) keep the sweeps of the shipped tasks within
    /// reach between poses; synth raises the depth when planning or
    /// verifying a transition fails (SynthesisOptions::max_transition_depth).
    int transition_depth = 3;
};

struct Formulation {
    QuadraticProgram program;
    int dof = 2;
    int base_x = -1, base_y = -1;
    std::vector<int> r;                         ///< link length variables
    std::vector<std::pair<int, int>> proximal;  ///< 3 joints: end of link 1 per primitive
    int elbow = 1;
    double link_diameter = 0.0;
};

/// Builds the problem; the initial point comes from the start robot's IK
/// (points it cannot reach get a nearby elbow on the requested side).
Formulation formulate(const ArmProblem& problem);

kinematics::Robot robot_from(const Formulation& f, const std::vector<double>& x);

}  // namespace modsynth::nlp
