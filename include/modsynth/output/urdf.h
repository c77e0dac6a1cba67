#pragma once
// The synthesised robot as a URDF model: revolute joints about z, each link
// a tube of the link diameter one level higher than the previous one (paper
// III-G), the module bodies as boxes, and the end-effector rod down to the
// task plane, with the masses of the module catalog. The root link "world" is the task frame, so
// the tip link "ee" lies on the path at z = 0 for every configuration of the motion.
#include <string>

#include <modsynth/hardware/catalog.h>
#include <modsynth/synth/solution.h>
#include <modsynth/task/task.h>

namespace modsynth::output {

/// Margin (rad) added on both sides of the motion's range of each joint to
/// give its URDF limits.
constexpr double kJointLimitMargin = 0.05;

/// The name of joint k (0-based, from the base): "joint_1", ... Other
/// outputs that address the joints (joint_trajectory.h) use it too.
std::string urdf_joint_name(int k);
/// The robot's name in a URDF: the task's, with anything but letters,
/// digits and '-' as '_' ("modsynth_arm" when empty).
std::string urdf_robot_name(const std::string& task_name);
/// The <ros2_control> block of an arm of `dof` joints: each commanded by
/// position, reporting position and velocity, starting at the motion's
/// first pose.
std::string ros2_control_block(const std::string& task_name, const synth::Solution& solution,
                               int dof);

/// The model of a solved solution (its robot and, for the joint limits,
/// its samples); the module sizes come from task.robot, the masses and
/// ratings from the catalog: the modules of solution.modules when chosen,
/// else the strongest allowed module (task robot.modules) at every joint.
/// Each link has an <inertial>, each joint <limit> with the module's peak
/// torque and top speed, and a <ros2_control> block commands the joints by
/// position (state: position and velocity).
std::string robot_urdf(const task::Task& task, const synth::Solution& solution,
                       const hardware::Catalog& catalog);
/// The same with the catalog shipped with the program
/// (hardware::load_default_catalog; throws hardware::CatalogError).
std::string robot_urdf(const task::Task& task, const synth::Solution& solution);

}  // namespace modsynth::output
