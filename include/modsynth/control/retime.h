#pragma once
// Timing the certified joint path for a controller: times, joint velocities
// and accelerations within per-joint limits (formats.md "Timing a
// controller accepts"), and jerks when the limits have them. The path
// itself, the samples' q, is not touched, so the certificate of the motion
// still holds.
#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include <modsynth/control/joint_limits.h>
#include <modsynth/control/motion.h>

namespace modsynth::control {

struct RetimeOptions {
    /// The EE's speed along a traced primitive (m/s, from the samples' s):
    /// where the limits allow, the EE runs at exactly this speed (paint and
    /// glue want an even rate); where they do not, slower, and
    /// RetimeStats::slow says where. Infinity: none, the limits decide.
    double ee_speed = std::numeric_limits<double>::infinity();
    /// A cap on every joint's speed below its limit (rad/s), infinity for
    /// none.
    double joint_speed = std::numeric_limits<double>::infinity();
    /// Where the joint-space direction turns by more than corner_angle
    /// (rad) between two steps, and by more than corner_ratio times as much
    /// as at the samples beside it, the joint path has a corner (a waypoint
    /// of a travel, a sample far off the others), and the motion stops
    /// there: a controller cannot turn a corner at speed. Along a smooth
    /// path the turn changes little from one sample to the next, also where
    /// it bends sharply (a joint reversing near a stretched or folded
    /// pose): there the acceleration limits slow the motion down. Corners
    /// of the task's path are given to retime() by the caller
    /// (path_corners.h).
    double corner_angle = 0.2;
    double corner_ratio = 3.0;
    /// Steps shorter than this (rad) do not move: the motion is at rest at
    /// both ends of such a step, and it takes min_step_time.
    double still_length = 1e-9;
    double min_step_time = 1e-3;  ///< s
    /// Share of every limit the timing leaves unused, so that rounding in
    /// the passes cannot put a sample past one. The passes' constraints
    /// imply formats.md's rules exactly; this is only for the last digits.
    double margin = 1e-9;
    /// With jerk limits: timings computed, the first with the jerk
    /// constraints taken around the speeds of the timing without jerk
    /// limits, each later one around the last one's (the quickest is kept).
    /// On the shipped tasks a second pass shortens the motion by 1 to 5 %,
    /// later ones by nothing.
    int jerk_passes = 2;

    /// False (with `error` naming the field) when some value is out of range.
    bool IsValid(std::string* error) const;
};

/// A stretch of a traced primitive where the EE runs slower than
/// RetimeOptions::ee_speed although the path does not stop there: the
/// limits force it (the ramps into and out of a stop are not counted).
struct SlowStretch {
    std::size_t first = 0, last = 0;  ///< samples, both traced
    double slowest = 0.0;             ///< m/s, the least EE speed at a sample in it
    /// At the slowest sample, the joint nearest one of its limits and
    /// which: "velocity", "acceleration" or "jerk".
    int joint = 0;
    std::string limit;
};

/// What the timing found, for reports and tests.
struct RetimeStats {
    double duration = 0.0;  ///< s, the last sample's t
    int rests = 0;          ///< samples where the motion stops (ends, corners, phase changes)
    int passes = 0;         ///< timings computed (1 without jerk limits)
    std::vector<SlowStretch> slow;
    /// s the EE spends in the stretches of `slow`, and on the traced path
    /// in all.
    double slow_seconds = 0.0, traced_seconds = 0.0;
};

/// The samples with t (from 0, strictly increasing), qd and qdd set and q
/// unchanged. The path between samples is joint-linear; the parameter along
/// it is timed as TOPP-RA does (Pham and Pham 2018): a backward pass finds
/// at each sample the fastest squared path speed from which the rest of the
/// path can still be followed within the limits, and a forward pass
/// accelerates as hard as those allow. Its constraints between consecutive
/// samples are formats.md's rules themselves (in forms linear in the
/// squared speeds that imply them), so the result is the fastest timing of
/// the samples with velocities along the path's tangents that meets them.
/// With jerk limits, the path acceleration at each sample is a second
/// state, the sets the backward pass finds are polygons, and the jerk
/// rules (JointLimits::jerk) hold as well.
///
/// The motion is at rest at the first and last samples, at the samples in
/// `stops` (the task path's corners), at joint-space corners
/// (RetimeOptions::corner_angle), where the phase or the stroke changes
/// (3-joint transitions, travel) and around steps that do not move; with
/// jerk limits its accelerations are zero there too.
/// Throws std::invalid_argument when the limits or options are not valid, a
/// sample's q has another length than the limits or a stop is not a sample.
std::vector<Sample> retime(std::vector<Sample> samples, const JointLimits& limits,
                           const RetimeOptions& options = {}, RetimeStats* stats = nullptr,
                           std::span<const std::size_t> stops = {});

/// Where a timed motion breaks formats.md's rules for `limits` (velocity
/// and acceleration, the jerk rules when the limits have jerks, rest at
/// both ends), with the slack the contract's checker allows (1e-6): ""
/// when it keeps them, else a line naming the first sample and joint
/// ("samples[3]: joint 2's acceleration 12.5 rad/s^2 is over its 10
/// rad/s^2 limit"). A motion without qd and qdd keeps none of them.
std::string timing_fault(const std::vector<Sample>& samples, const JointLimits& limits);

}  // namespace modsynth::control
