#pragma once
// Where a planar task's path has a corner: the motion must stop there,
// since a tool cannot turn a corner at speed without leaving the path.
// retime() is told these samples (it does not know the task), and
// retime_for() tells it.
#include <cstddef>
#include <vector>

#include <modsynth/control/joint_limits.h>
#include <modsynth/control/motion.h>
#include <modsynth/control/retime.h>
#include <modsynth/task/task.h>

namespace modsynth::control {

/// Tangent breaks of less than this (rad, about 0.6 degree) count as
/// smooth: the junctions modsynth import's arc fits make, and any drawn
/// to the precision of a file, are tangent to far better than that, and a
/// tool turning by so little slows down only as much as the acceleration
/// limits ask (retime() counts the joint path's turning).
inline constexpr double kCornerAngle = 0.01;

/// The samples at junctions of two primitives of a stroke traced one after
/// the other without a transition (the last sample of the first) where the
/// path's tangent turns by more than `angle`. Samples of other tasks'
/// motions (a primitive index out of range) are skipped.
std::vector<std::size_t> path_corners(const task::Task& task, const std::vector<Sample>& samples,
                                      double angle = kCornerAngle);

/// retime() with the task's corners (path_corners()) as stops: how a
/// planar task's motion is timed.
std::vector<Sample> retime_for(const task::Task& task, std::vector<Sample> samples,
                               const JointLimits& limits, const RetimeOptions& options = {},
                               RetimeStats* stats = nullptr);

}  // namespace modsynth::control
