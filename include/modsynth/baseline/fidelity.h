#pragma once
// How faithfully a joint-space motion performs a task, measured the same way
// for any method: the EE is sampled densely along the joint-linear motion
// and compared with the true path both ways, and the path is checked against
// the robot's obstacle-free reachable space. These are sampled measurements
// for comparing methods, not certificates (verify/ certifies).
#include <vector>

#include <modsynth/geometry/vec.h>
#include <modsynth/kinematics/robot.h>
#include <modsynth/task/task.h>

namespace modsynth::baseline {

struct FidelityOptions {
    double max_joint_step = 0.002;  ///< rad between EE samples of the motion
    double path_spacing = 0.002;    ///< m between samples of the true path
    /// Three joints: first-joint angles tried per path sample when asking
    /// whether the arm can reach it at all.
    int proximal_steps = 720;

    /// False (with `error` naming the field) when some value is out of range.
    bool IsValid(std::string* error) const;
};

struct Fidelity {
    /// Farthest (and mean) distance from the executed EE to the true path, m.
    double max_deviation = 0.0;
    double mean_deviation = 0.0;
    geometry::Vec2 worst_point = geometry::Vec2::Zero();  ///< EE there
    /// Farthest a point of the true path lies from the EE's trail, m.
    double coverage_gap = 0.0;
    double path_length = 0.0;
    /// Length of path outside the obstacle-free reachable space (some pose
    /// of the arm puts the EE there with every link clear), and those samples.
    double outside_length = 0.0;
    std::vector<geometry::Vec2> outside_points;
    /// Worst pose clearance along the executed motion (m; < 0: a collision).
    double min_clearance = 0.0;
    std::vector<geometry::Vec2> trail;  ///< the EE at every sample of the motion

    bool whole_path_reachable() const { return outside_points.empty(); }
};

/// `waypoints`: joint vectors the robot moves linearly between. Throws
/// std::invalid_argument when the options are not valid.
Fidelity measure_fidelity(const task::Task& task, const kinematics::Robot& robot,
                          const std::vector<std::vector<double>>& waypoints,
                          const FidelityOptions& options = {});

}  // namespace modsynth::baseline
