#pragma once
// How fast each joint may turn and accelerate: the limits the motion is
// timed with (formats.md `robot.joint_limits`).
#include <string>
#include <vector>

#include <modsynth/task/task.h>

namespace modsynth::control {

/// Per joint, rad/s and rad/s^2; both lists as long as the robot's q.
/// `jerk` (rad/s^3) is as long too, or empty: no jerk limit.
struct JointLimits {
    std::vector<double> velocity;
    std::vector<double> acceleration;
    std::vector<double> jerk{};

    int dof() const { return static_cast<int>(velocity.size()); }
};

/// The modules' limits when the task gives none: a HEBI X8-9 actuator.
/// Speed: the X8-9's top speed in the module catalog
/// (catalog/hebi-x-series.json, 3.142 rad/s = 30 rpm, after HEBI's
/// hebi_description); tests/hardware/catalog_test.cpp holds the two equal.
/// Acceleration: the datasheet gives none; 10 rad/s^2 reaches full speed
/// in a third of a second, and is a conservative figure for the sub-metre
/// tube arms modsynth builds: a 0.5 m link carrying a 0.5 kg module at its
/// end (about 0.13 kg m^2) needs some 1.3 N m for it, a small share of the
/// 9 N m the X8-9 is rated for.
inline constexpr double kDefaultJointSpeed = 3.142;
inline constexpr double kDefaultJointAcceleration = 10.0;

/// kDefaultJointSpeed and kDefaultJointAcceleration for every joint.
JointLimits default_joint_limits(int dof);

/// The task's limits for a robot with `dof` joints (one value spread over
/// every joint), or default_joint_limits() when the task has none. Throws
/// task::InputError naming `robot.joint_limits` when a per-joint list has
/// another length than dof.
JointLimits joint_limits_for(const task::Task& task, int dof);

/// False (with `error` saying which joint) when some limit is not a finite
/// positive number or the lists' lengths differ (an empty jerk list aside).
bool valid(const JointLimits& limits, std::string* error);

}  // namespace modsynth::control
