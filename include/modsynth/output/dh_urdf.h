#pragma once
// A spatial arm (a DH chain, formats.md "Spatial tasks") as a URDF model:
// frame "world" is the task frame; joint 1 turns about world z at the base;
// each later joint's origin and axis come from the DH rows, so that link
// k's frame is frame k - 1 turned by q_k (hardware/dh_stack.h) and the tip
// link "ee"'s origin is the EE. Links are drawn as the chain's segments
// (cylinders of the link diameter, the tubes as cut) with the module
// housings as boxes, and carry the inertials of the spatial arm model.
#include <string>

#include <modsynth/hardware/catalog.h>
#include <modsynth/synth/solution.h>
#include <modsynth/task/spatial_task.h>

namespace modsynth::output {

/// The model of a solved spatial solution (solution.dh_robot; its samples
/// give the joint limits: the motion's range plus kJointLimitMargin, effort
/// and velocity the module's peak torque and top speed). Modules: those of
/// solution.modules when chosen, else the strongest allowed at every joint.
/// Every link has an <inertial>, and a <ros2_control> block commands the
/// joints by position, as the planar URDF does.
std::string robot_urdf(const task::SpatialTask& task, const synth::Solution& solution,
                       const hardware::Catalog& catalog);
/// The same with the catalog shipped with the program.
std::string robot_urdf(const task::SpatialTask& task, const synth::Solution& solution);

}  // namespace modsynth::output
