#pragma once
// The discretized design of the paper's comparison (IV-B, after its ref.
// [6]): a robot synthesised from N points of the path alone. Each point gets
// its own pose, with every joint free; the poses keep their elbows on one
// side from point to point (elbow consistency, straight poses allowed), every
// link clear of the obstacles and the EE clear of the lower links at each
// point, and nothing at all between the points. Objective: the total link
// length, plus a small cost on the motion of the joints between
// consecutive poses. This is the method modsynth is measured against; it is
// not used to solve tasks.
#include <string>
#include <vector>

#include <modsynth/geometry/vec.h>
#include <modsynth/kinematics/robot.h>
#include <modsynth/nlp/solver.h>
#include <modsynth/task/task.h>

namespace modsynth::baseline {

struct PathSample {
    int primitive = 0;
    double s = 0.0;  ///< arc length along the primitive
    geometry::Vec2 point = geometry::Vec2::Zero();
};

/// `count` >= 2 points equidistant by arc length along the whole path, its
/// start and its end included.
std::vector<PathSample> equidistant_points(const task::Task& task, int count);

struct DesignOptions {
    double time_limit = 60.0;  ///< seconds, wall clock
    /// Weight (1/m) of the squared distance each joint moves between
    /// consecutive poses, beside the total length (weight 1).
    double smoothness_weight = 1.0;
    /// m beyond radius + diameter/2 at each point, and m beyond the
    /// diameter from the EE to the lower links: the refinement's own
    /// margins (nlp::Margins), so both methods are held to the same rule.
    double clearance_margin = 0.003;
    double self_margin = 0.002;
    /// The initial links are this share of the farthest point's distance
    /// from the initial base, each (two joints: together just over the
    /// reach; three: enough to fold the proximal link aside).
    double start_reach_share_two = 0.55;
    double start_reach_share_three = 0.4;
    /// rad: three joints start with link 1 turned this far off the line to
    /// each point, towards the side of its elbow, so the start is not the
    /// singular straight pose.
    double start_turn = 0.4;
    /// Largest constraint violation (m, m^2) a solution Ipopt calls usable
    /// may keep to count as a design.
    double feasibility_tolerance = 1e-6;
    /// Ipopt's options for every start; its time_limit is replaced by what
    /// is left of the design's own.
    nlp::SolverOptions solver;

    /// False (with `error` naming the field) when some value is out of range.
    bool IsValid(std::string* error) const;
};

struct PointDesign {
    bool found = false;
    kinematics::Robot robot;  ///< elbow: the sign of the distal pair
    /// One joint-angle vector per point, each q in (-pi, pi].
    std::vector<std::vector<double>> poses;
    /// The elbow sign of each consecutive link pair (dof - 1 entries).
    std::vector<int> elbows;
    int nlp_solves = 0;
    std::string message;  ///< what was tried when nothing was found
};

/// The program design_for_points() minimises from one start: `dof` joints,
/// the base in base region `region` (-1: anywhere) and `elbows` the side of
/// each consecutive link pair (dof - 1 signs). Exposed so that its
/// derivatives can be checked like the refinement's.
nlp::QuadraticProgram design_program(const task::Task& task, const std::vector<PathSample>& points,
                                     int dof, int region, const std::vector<int>& elbows,
                                     const DesignOptions& options);

/// Tries the allowed joint counts fewest first; for each, every base region
/// and every elbow pattern, keeping the shortest robot found. Throws
/// std::invalid_argument when the options are not valid.
PointDesign design_for_points(const task::Task& task, const std::vector<PathSample>& points,
                              const DesignOptions& options);

}  // namespace modsynth::baseline
