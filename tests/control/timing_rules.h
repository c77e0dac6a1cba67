#pragma once
// formats.md "Timing a controller accepts", checked as the reference
// checker does: the test's own reading of the rules, not retime()'s.
#include <cmath>
#include <string>
#include <vector>

#include <modsynth/control/joint_limits.h>
#include <modsynth/control/motion.h>
#include <modsynth/text/format.h>

namespace modsynth::testing {

/// "" when the samples are timed as formats.md asks, else the first broken
/// rule.
inline std::string timing_violation(const std::vector<control::Sample>& s,
                                    const control::JointLimits& limits) {
    using text::format;
    const std::size_t n = limits.velocity.size();
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (s[i].qd.size() != n || s[i].qdd.size() != n)
            return format("samples[%zu]: no qd/qdd for %zu joints", i, n);
        for (std::size_t k = 0; k < n; ++k) {
            if (std::abs(s[i].qd[k]) > limits.velocity[k] * (1 + 1e-6))
                return format("samples[%zu].qd[%zu] = %g beyond the limit", i, k, s[i].qd[k]);
            if (std::abs(s[i].qdd[k]) > limits.acceleration[k] * (1 + 1e-6))
                return format("samples[%zu].qdd[%zu] = %g beyond the limit", i, k, s[i].qdd[k]);
            if ((i == 0 || i + 1 == s.size()) && std::abs(s[i].qd[k]) > 1e-6)
                return format("samples[%zu] is not at rest", i);
        }
        if (i == 0) continue;
        const double dt = s[i].t - s[i - 1].t;
        if (!(dt > 0.0)) return format("samples[%zu].t does not increase", i);
        for (std::size_t k = 0; k < n; ++k) {
            const double a = limits.acceleration[k];
            if (std::abs(s[i].qd[k] - s[i - 1].qd[k]) > a * dt + 1e-6)
                return format("samples[%zu]: qd[%zu] changes faster than the limit", i, k);
            const double mean = (s[i].q[k] - s[i - 1].q[k]) / dt;
            if (std::abs(mean - 0.5 * (s[i].qd[k] + s[i - 1].qd[k])) > a * dt / 4 + 1e-6)
                return format("samples[%zu]: qd[%zu] disagrees with the positions", i, k);
        }
    }
    return "";
}

/// "" when the accelerations agree with the jerk limits as the velocities
/// do with the acceleration limits (formats.md `robot.joint_limits.jerk`):
/// finite differences of qdd over t within J, qd consistent with qdd, and
/// qdd zero at both ends; else the first broken rule.
inline std::string jerk_violation(const std::vector<control::Sample>& s,
                                  const std::vector<double>& jerk) {
    using text::format;
    for (std::size_t i = 0; i < s.size(); ++i) {
        for (std::size_t k = 0; k < jerk.size(); ++k) {
            if ((i == 0 || i + 1 == s.size()) && std::abs(s[i].qdd[k]) > 1e-6)
                return format("samples[%zu]: qdd is not 0 at an end", i);
            if (i == 0) continue;
            const double dt = s[i].t - s[i - 1].t;
            const double j = jerk[k];
            if (std::abs(s[i].qdd[k] - s[i - 1].qdd[k]) / dt > j * (1 + 1e-6) + 1e-6 / dt)
                return format("samples[%zu]: qdd[%zu] changes at %g rad/s^3, beyond %g", i, k,
                              (s[i].qdd[k] - s[i - 1].qdd[k]) / dt, j);
            const double mean = (s[i].qd[k] - s[i - 1].qd[k]) / dt;
            if (std::abs(mean - 0.5 * (s[i].qdd[k] + s[i - 1].qdd[k])) > j * dt / 4 + 1e-6)
                return format("samples[%zu]: qdd[%zu] disagrees with qd", i, k);
        }
    }
    return "";
}

}  // namespace modsynth::testing
