#pragma once
// What retime() times: the joint-linear path through the samples,
// parametrised by its length in joint space, with the derivatives along it
// the reported velocities and accelerations are built from, and where the
// motion must stop. Internal to the control library.
#include <cstddef>
#include <limits>
#include <span>
#include <vector>

#include <modsynth/control/joint_limits.h>
#include <modsynth/control/motion.h>
#include <modsynth/control/retime.h>

namespace modsynth::control::retime_detail {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

struct Path {
    using Vec = std::vector<double>;

    Path(const std::vector<Sample>& samples, const RetimeOptions& options,
         std::span<const std::size_t> stops);

    std::size_t n = 0;  ///< samples
    int joints = 0;
    Vec length;               ///< per step: its length in joint space (rad)
    std::vector<Vec> dir;     ///< per step: unit direction (zero when still)
    std::vector<char> still;  ///< per step: does not move
    Vec ee_travel;            ///< per step: m of path the EE traces (0 off the path)
    std::vector<char> rest;   ///< per sample: the motion stops there
    /// Per sample, dq/dsigma and d2q/dsigma2 of the parabola through it and
    /// its neighbours (zero at rests): qd = tangent sqrt(x) and, with jerk
    /// limits, qdd = tangent u + curve x for squared path speed x and path
    /// acceleration u.
    std::vector<Vec> tangent, curve;

    /// m of path per rad of joint path at sample i, weighted from the
    /// steps beside it as the tangent is; 0 unless both are traced and i is
    /// not a rest. The EE's speed there is this times the path speed.
    double ee_rate(std::size_t i) const;

    /// The tangent a step starts and ends with: at a rest, where the
    /// direction may turn, the step's own.
    const Vec& tail(std::size_t i) const { return rest[i] ? dir[i] : tangent[i]; }
    const Vec& head(std::size_t i) const { return rest[i + 1] ? dir[i] : tangent[i + 1]; }
};

/// Fills stats.slow, slow_seconds and traced_seconds from the timed samples
/// (nothing when options.ee_speed is infinite).
void find_slow_stretches(const Path& path, const std::vector<Sample>& samples,
                         const JointLimits& limits, const RetimeOptions& options,
                         RetimeStats& stats);

}  // namespace modsynth::control::retime_detail
