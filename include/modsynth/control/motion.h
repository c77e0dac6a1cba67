#pragma once
// The control: joint angles over time (formats.md "samples"), computed from
// the exact inverse kinematics along each primitive.
#include <optional>
#include <string>
#include <vector>

#include <modsynth/kinematics/robot.h>
#include <modsynth/task/task.h>

namespace modsynth::control {

enum class Phase { Trace, Transition };

struct Sample {
    double t = 0.0;
    Phase phase = Phase::Trace;
    int primitive = 0;
    double s = 0.0;  ///< arc length along the primitive (trace samples)
    std::vector<double> q;
};

struct MotionOptions {
    double max_joint_step = 0.01;  ///< rad between consecutive samples
    double max_ee_step = 0.002;    ///< m of path between consecutive trace samples
    double ee_speed = 0.05;        ///< m/s along the path
    double joint_speed = 1.0;      ///< rad/s, the limit of every joint
};

/// The configuration that puts the EE at arc length s of primitive j, on the
/// robot's elbow branch, unwrapped next to `previous` when given.
/// std::nullopt when the point is out of reach.
std::optional<std::vector<double>> configuration_at(const task::Task& task,
                                                    const kinematics::Robot& robot, int j,
                                                    double s,
                                                    const std::vector<double>* previous);

/// Samples the whole motion of a 2-joint robot: every primitive traced from
/// its start to its end with no joint moving more than max_joint_step and
/// the EE no more than max_ee_step between samples. Times are not set.
/// std::nullopt (with `where` naming the point) when some point is out of reach.
std::optional<std::vector<Sample>> plan_motion(const task::Task& task,
                                               const kinematics::Robot& robot,
                                               const MotionOptions& options,
                                               std::string* where = nullptr);

/// Inserts a sample midway (by arc length) between samples i and i + 1 of
/// the same trace, for each i in `pairs`. Returns false when a midpoint is
/// out of reach.
bool refine_motion(const task::Task& task, const kinematics::Robot& robot,
                   std::vector<Sample>& samples, const std::vector<int>& pairs);

/// Sets t: each step takes the longer of path length / ee_speed and
/// largest joint change / joint_speed.
void assign_times(std::vector<Sample>& samples, const MotionOptions& options);

}  // namespace modsynth::control
