#pragma once
// Timing a spatial motion as a planar one is timed (retime.h): the task's
// joint limits, or the modules' defaults, and the path's corners as stops.
#include <cstddef>
#include <vector>

#include <modsynth/control/joint_limits.h>
#include <modsynth/control/motion.h>
#include <modsynth/control/path_corners.h>
#include <modsynth/control/retime.h>
#include <modsynth/task/spatial_task.h>

namespace modsynth::control {

/// The task's limits for a chain of `dof` joints (one value spread over
/// every joint), or default_joint_limits() when the task has none. Throws
/// task::InputError naming `robot.joint_limits.<key>` when a per-joint list
/// has another length than dof.
JointLimits joint_limits_for(const task::SpatialTask& task, int dof);

/// The samples at junctions of two primitives of a stroke traced one after
/// the other without a transition (the last sample of the first) where the
/// path's tangent turns by more than `angle`.
std::vector<std::size_t> path_corners(const task::SpatialTask& task,
                                      const std::vector<Sample>& samples,
                                      double angle = kCornerAngle);

/// retime() with the task's corners as stops.
std::vector<Sample> retime_for(const task::SpatialTask& task, std::vector<Sample> samples,
                               const JointLimits& limits, const RetimeOptions& options = {},
                               RetimeStats* stats = nullptr);

}  // namespace modsynth::control
