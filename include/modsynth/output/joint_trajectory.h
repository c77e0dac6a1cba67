#pragma once
// The control as a ROS 2 trajectory_msgs/msg/JointTrajectory in YAML, the
// form `ros2 topic pub` and a FollowJointTrajectory client take: joint
// names as in the URDF (urdf_joint_name()), and per sample the positions,
// velocities and accelerations with its time_from_start {sec, nanosec}.
#include <string>

#include <modsynth/synth/solution.h>

namespace modsynth::output {

/// The message of a solved solution whose samples are timed (carry qd and
/// qdd). Throws std::invalid_argument when they are not.
std::string joint_trajectory_yaml(const synth::Solution& solution);

}  // namespace modsynth::output
