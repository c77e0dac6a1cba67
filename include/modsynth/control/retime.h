#pragma once
// Timing the certified joint path for a controller: times, joint velocities
// and accelerations within per-joint limits (formats.md "Timing a
// controller accepts"). The path itself, the samples' q, is not touched, so
// the certificate of the motion still holds.
#include <limits>
#include <string>
#include <vector>

#include <modsynth/control/joint_limits.h>
#include <modsynth/control/motion.h>

namespace modsynth::control {

struct RetimeOptions {
    /// Caps on top of the joint limits, infinity for none: the EE's speed
    /// along a traced primitive (m/s, from the samples' s) and every
    /// joint's speed (rad/s).
    double ee_speed = std::numeric_limits<double>::infinity();
    double joint_speed = std::numeric_limits<double>::infinity();
    /// Where the joint-space direction turns by more than this between two
    /// steps (rad), the path has a corner, and the motion stops there: a
    /// controller cannot turn a corner at speed without leaving the path.
    /// Along the smooth parts of a path planned in 0.01 rad steps the
    /// direction turns by far less from one step to the next.
    double corner_angle = 0.2;
    /// Steps shorter than this (rad) do not move: the motion is at rest at
    /// both ends of such a step, and it takes min_step_time.
    double still_length = 1e-9;
    double min_step_time = 1e-3;  ///< s
    /// Share of the acceleration limits the passes leave unused, for the
    /// difference between their model of a step and the rules the result
    /// must meet; where it is not enough, the speeds are lowered locally.
    double acceleration_margin = 0.01;

    /// False (with `error` naming the field) when some value is out of range.
    bool IsValid(std::string* error) const;
};

/// What the timing found, for reports and tests.
struct RetimeStats {
    double duration = 0.0;  ///< s, the last sample's t
    int rests = 0;          ///< samples where the motion stops (ends and corners)
    int passes = 0;         ///< forward/backward passes until every step was consistent
};

/// The samples with t (from 0, strictly increasing), qd and qdd set and q
/// unchanged. The path between samples is joint-linear; the parameter along
/// it is timed by a forward and a backward pass (TOPP on the squared path
/// speed), under the joint velocity limits, the joint acceleration limits
/// (the path's acceleration and its turning both count) and the caps of
/// `options`. The motion is at rest at the first and last samples, at
/// corners, at both ends of every transition and around steps that do not
/// move. Consecutive samples are consistent as formats.md asks: for every
/// joint k, |qd_k(i+1) - qd_k(i)| <= A_k dt and
/// |(q_k(i+1) - q_k(i)) / dt - (qd_k(i) + qd_k(i+1)) / 2| <= A_k dt / 4.
/// Throws std::invalid_argument when the limits or options are not valid or
/// a sample's q has another length than the limits.
std::vector<Sample> retime(std::vector<Sample> samples, const JointLimits& limits,
                           const RetimeOptions& options = {}, RetimeStats* stats = nullptr);

}  // namespace modsynth::control
