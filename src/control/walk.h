#pragma once
// How both motion planners walk a parameter (arc length along a primitive,
// an angle or a sweep's fraction in a transition) from one value to
// another: each step as long as the arm's limits allow, a sample per step.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

#include <modsynth/control/sample.h>
#include <modsynth/run/deadline.h>

namespace modsynth::control {

/// The largest change of one joint from a to b.
inline double largest_change(const std::vector<double>& a, const std::vector<double>& b) {
    double m = 0.0;
    for (std::size_t k = 0; k < a.size(); ++k) m = std::max(m, std::abs(b[k] - a[k]));
    return m;
}

/// The longest trace step on a primitive: the planning step, and on a turn
/// at most a quarter of it, since a reader unwrapping progress as an angle
/// takes half a turn or more for a step back (a flag's 0.44 mm dot, 2.8 mm
/// round, stepped at 2 mm would seem to go backwards).
template <class Primitive>
double trace_step_limit(const Primitive& p, double max_ee_step) {
    return std::min(max_ee_step, 0.5 * geometry::half_turn_length(p));
}

struct WalkLimits {
    std::size_t max_samples = 0;  ///< planning gives up past this many samples
    run::Deadline deadline;       ///< or past this
    int step_attempts = 60;       ///< shorter tries of one step before it fails
};

/// Where a walk stopped short of its end.
struct WalkStop {
    double at = 0.0;       ///< the parameter that could not be reached
    bool gave_up = false;  ///< at the sample cap or the deadline, not out of reach
};

/// Walks from `from` to `to` (either way), the first step at most
/// `first_step`, every step at most `max_step`, appending a sample per step
/// (the one at `from` excluded) tagged `phase`, `primitive` and `stroke`.
/// `config_at(u, previous q)` is the pose at u (none: out of reach);
/// `shrink(last q, next q)` is nothing when the step fits the limits, else
/// the factor the step is shortened by. What is left after a full step,
/// when less than another, is shared with it: a last step of a few
/// nanometres would point the joint path anywhere, a kink that is only
/// rounding. Returns where it stopped, or nothing when it reached `to`.
template <class ConfigAt, class Shrink>
std::optional<WalkStop> walk(double from, double to, double first_step, double max_step,
                             const WalkLimits& limits, Phase phase, int primitive, int stroke,
                             std::vector<Sample>& out, ConfigAt config_at, Shrink shrink) {
    const double dir = to >= from ? 1.0 : -1.0;
    double u = from, du = 0.5 * std::min(first_step, max_step);
    while (dir * (to - u) > 1e-12) {
        if (out.size() >= limits.max_samples ||
            (out.size() % 1024 == 0 && limits.deadline.expired()))
            return WalkStop{u, true};
        du = std::min(2.0 * du, max_step);
        std::optional<std::vector<double>> next;
        double candidate = u;
        for (int attempt = 0; attempt < limits.step_attempts; ++attempt) {
            const double left = dir * (to - u);
            candidate = left <= du ? to : u + dir * (left < 2.0 * du ? 0.5 * left : du);
            next = config_at(candidate, &out.back().q);
            if (!next) break;
            const std::optional<double> factor = shrink(out.back().q, *next);
            if (!factor) break;
            du *= *factor;
            next.reset();
            if (du < 1e-10) break;
        }
        if (!next) return WalkStop{candidate, false};
        u = candidate;
        out.push_back({0.0, phase, primitive, u, *next, stroke});
    }
    return std::nullopt;
}

}  // namespace modsynth::control
