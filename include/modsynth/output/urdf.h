#pragma once
// The synthesised robot as a URDF model: revolute joints about z, each link
// a tube of the link diameter one level higher than the previous one (paper
// III-G), the module bodies as boxes, and the end-effector rod down to the
// task plane. The root link "world" is the task frame, so the tip link "ee"
// lies on the path at z = 0 for every configuration of the motion.
#include <string>

#include <modsynth/synth/solution.h>
#include <modsynth/task/task.h>

namespace modsynth::output {

/// Margin (rad) added on both sides of the motion's range of each joint to
/// give its URDF limits.
constexpr double kJointLimitMargin = 0.05;

/// The name of joint k (0-based, from the base): "joint_1", ... Other
/// outputs that address the joints (joint_trajectory.h) use it too.
std::string urdf_joint_name(int k);

/// The model of a solved solution (its robot and, for the joint limits,
/// its samples); the module sizes come from task.robot.
std::string robot_urdf(const task::Task& task, const synth::Solution& solution);

}  // namespace modsynth::output
