#pragma once
// The motion of the discretized baseline: RRT (OMPL) in joint space from
// each designed pose to the next, biased towards the next one, checked
// against the obstacles and self-collision, then shortcut greedily. OMPL
// stays out of this interface.
#include <string>
#include <vector>

#include <modsynth/kinematics/robot.h>
#include <modsynth/task/task.h>

namespace modsynth::baseline {

struct PlannerOptions {
    unsigned seed = 0;
    /// Chance that a sample is the next pose itself.
    double goal_bias = 0.1;
    /// Longest RRT step (rad, sum over the joints); 0: OMPL's default.
    double range = 0.0;
    /// Joint-space resolution (rad) at which motions are checked.
    double resolution = 0.005;
    int max_iterations = 20000;  ///< per pair of poses
    double time_limit = 60.0;    ///< seconds, wall clock, for the whole motion
    bool shortcut = true;

    /// False (with `error` naming the field) when some value is out of range.
    bool IsValid(std::string* error) const;
};

struct PlannedMotion {
    bool complete = false;
    /// Joint-space waypoints, unwrapped so that consecutive ones differ by
    /// the way the robot turns; a robot moves linearly between them.
    std::vector<std::vector<double>> waypoints;
    int failed_pair = -1;  ///< from pose failed_pair to the next, when not complete
    int iterations = 0;
    std::string message;
};

/// Plans through `poses` in order (each a valid joint vector of `robot`).
/// Throws std::invalid_argument when the options are not valid.
PlannedMotion plan_rrt(const task::Task& task, const kinematics::Robot& robot,
                       const std::vector<std::vector<double>>& poses,
                       const PlannerOptions& options);

}  // namespace modsynth::baseline
