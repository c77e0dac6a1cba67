#include <modsynth/control/retime.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include <modsynth/text/format.h>
#include <modsynth/text/option_check.h>

#include "jerk_timing.h"
#include "retime_path.h"

namespace modsynth::control {
namespace {

using Vec = std::vector<double>;
using retime_detail::kInf;
using retime_detail::Path;

/// A constraint p x + q u <= r on a step's squared path speed at its start
/// (x) and its path acceleration (u).
struct Row {
    double p, q, r;
};

/// formats.md's rules between samples i and i + 1 with the velocities
/// qd = tangent * sqrt(x) and a constant path acceleration u over the step
/// (x at the end is x + 2 length u, the step takes 2 length / (sqrt(x) +
/// sqrt(x_end))), in forms linear in x and u that imply them:
/// - |qd_k(i+1) - qd_k(i)| <= A_k dt. Exactly, (qd(i+1) - qd(i)) / dt =
///   ta u + tau w with tau = (tb - ta) / length and w = b (a + b) / 2 for
///   the speeds a, b at the ends, a number between x and x_end: the rule
///   holds when it holds with w = x and with w = x_end.
/// - |(q(i+1) - q(i)) / dt - (qd(i) + qd(i+1)) / 2| <= A_k dt / 4. Times
///   2 (a + b) / length this is |e x + f x_end + (e + f) a b| <= A_k length
///   with e = d - ta, f = d - tb (d the step's direction); a b lies between
///   x and x_end, so again both ends suffice.
void step_rows(const Path& p, std::size_t i, const Vec& amax, std::vector<Row>& rows) {
    const double len = p.length[i];
    const Vec& ta = p.tail(i);
    const Vec& tb = p.head(i);
    for (int k = 0; k < p.joints; ++k) {
        const double tau = (tb[k] - ta[k]) / len;
        const double a = amax[k];
        const double q0 = ta[k], q1 = 2.0 * tb[k] - ta[k];
        rows.push_back({tau, q0, a});
        rows.push_back({-tau, -q0, a});
        rows.push_back({tau, q1, a});
        rows.push_back({-tau, -q1, a});
        const double e = p.dir[i][k] - ta[k], f = p.dir[i][k] - tb[k];
        const double px = 2.0 * (e + f);
        const double qa = 2.0 * len * f, qb = 2.0 * len * (e + 2.0 * f);
        rows.push_back({px, qa, a * len});
        rows.push_back({-px, -qa, a * len});
        rows.push_back({px, qb, a * len});
        rows.push_back({-px, -qb, a * len});
    }
}

/// The largest x in [0, cap] for which some u meets every row (Fourier-
/// Motzkin: u eliminated pairwise). 0 always qualifies (u = 0 keeps a step
/// at rest), so the answer is at least 0.
double largest_x(const std::vector<Row>& rows, double cap) {
    double hi = cap;
    // u >= al x + be (from q < 0) and u <= au x + bu (from q > 0).
    thread_local std::vector<std::pair<double, double>> lower, upper;
    lower.clear();
    upper.clear();
    for (const Row& c : rows) {
        if (c.q == 0.0) {
            if (c.p > 0.0) hi = std::min(hi, c.r / c.p);
            continue;
        }
        (c.q > 0.0 ? upper : lower).push_back({-c.p / c.q, c.r / c.q});
    }
    for (const auto& [al, be] : lower) {
        for (const auto& [au, bu] : upper) {
            const double coef = al - au;
            if (coef > 0.0) hi = std::min(hi, (bu - be) / coef);
        }
    }
    return std::max(hi, 0.0);
}

/// The largest u that meets every row at x (and at least the largest
/// lower bound, should rounding leave none).
double largest_u(const std::vector<Row>& rows, double x) {
    double lo = -kInf, hi = kInf;
    for (const Row& c : rows) {
        if (c.q == 0.0) continue;
        const double bound = (c.r - c.p * x) / c.q;
        if (c.q > 0.0) {
            hi = std::min(hi, bound);
        } else {
            lo = std::max(lo, bound);
        }
    }
    return hi >= lo ? hi : lo;
}

/// Squared path speed caps per sample: rests, joint speeds of the reported
/// velocity, and the EE speed along traced steps.
Vec speed_caps(const Path& p, const Vec& vmax, const RetimeOptions& o) {
    Vec cap(p.n, kInf);
    for (std::size_t i = 0; i < p.n; ++i) {
        if (p.rest[i]) {
            cap[i] = 0.0;
            continue;
        }
        for (int k = 0; k < p.joints; ++k) {
            const double t = std::abs(p.tangent[i][k]);
            if (t > 0.0) cap[i] = std::min(cap[i], std::pow(vmax[k] / t, 2));
        }
    }
    if (std::isfinite(o.ee_speed)) {
        // The EE's speed at a traced sample is the path speed times its
        // ds/dsigma there (retime_detail::Path::ee_rate).
        for (std::size_t i = 1; i + 1 < p.n; ++i) {
            const double rate = p.ee_rate(i);
            if (rate > 0.0) cap[i] = std::min(cap[i], std::pow(o.ee_speed / rate, 2));
        }
    }
    return cap;
}

/// The timing of the second order (limits on velocity and acceleration):
/// squared path speeds per sample.
Vec second_order(const Path& p, const Vec& cap, const Vec& amax) {
    const std::size_t n = p.n;
    std::vector<Row> rows;
    // Backward: the controllable squared speeds [0, hi[i]].
    Vec hi(n, 0.0);
    hi[n - 1] = cap[n - 1];
    for (std::size_t i = n - 1; i-- > 0;) {
        if (p.still[i]) {
            hi[i] = cap[i];
            continue;
        }
        rows.clear();
        step_rows(p, i, amax, rows);
        const double two_len = 2.0 * p.length[i];
        rows.push_back({1.0, two_len, hi[i + 1]});  // x_end <= hi[i + 1]
        rows.push_back({-1.0, -two_len, 0.0});      // x_end >= 0
        hi[i] = largest_x(rows, cap[i]);
    }
    // Forward: as fast as the controllable sets allow.
    Vec x(n, 0.0);
    x[0] = std::min(cap[0], hi[0]);
    for (std::size_t i = 0; i + 1 < n; ++i) {
        if (p.still[i]) {
            x[i + 1] = std::min(cap[i + 1], hi[i + 1]);
            continue;
        }
        rows.clear();
        step_rows(p, i, amax, rows);
        const double two_len = 2.0 * p.length[i];
        rows.push_back({1.0, two_len, hi[i + 1]});
        rows.push_back({-1.0, -two_len, 0.0});
        const double u = largest_u(rows, x[i]);
        x[i + 1] = std::clamp(x[i] + two_len * u, 0.0, hi[i + 1]);
    }
    return x;
}

/// formats.md's consistency rules between samples a and b, with room for
/// rounding only, far inside the 1e-6 slack the checker allows.
bool consistent(const Sample& a, const Sample& b, double dt, const Vec& vmax, const Vec& amax,
                const Vec* jmax) {
    constexpr double kRelative = 1e-9, kAbsolute = 1e-12;
    for (std::size_t k = 0; k < a.q.size(); ++k) {
        if (std::abs(b.qd[k]) > vmax[k] * (1.0 + kRelative)) return false;
        if (std::abs(b.qdd[k]) > amax[k] * (1.0 + kRelative)) return false;
        if (std::abs(b.qd[k] - a.qd[k]) > amax[k] * dt * (1.0 + kRelative) + kAbsolute)
            return false;
        const double mean = (b.q[k] - a.q[k]) / dt - 0.5 * (a.qd[k] + b.qd[k]);
        if (std::abs(mean) > 0.25 * amax[k] * dt * (1.0 + kRelative) + kAbsolute) return false;
        if (!jmax) continue;
        const double j = (*jmax)[k];
        if (std::abs(b.qdd[k] - a.qdd[k]) > j * dt * (1.0 + kRelative) + kAbsolute) return false;
        const double rate = (b.qd[k] - a.qd[k]) / dt - 0.5 * (a.qdd[k] + b.qdd[k]);
        if (std::abs(rate) > 0.25 * j * dt * (1.0 + kRelative) + kAbsolute) return false;
    }
    return true;
}

/// A step that starts and ends at rest: the bang-bang time of the joint
/// that needs longest (with jerk limits, of acceleration and of jerk), and
/// min_step_time when nothing moves.
double rest_to_rest(const Sample& a, const Sample& b, const Vec& amax, const Vec* jmax,
                    const RetimeOptions& o) {
    double dt = 0.0;
    for (std::size_t k = 0; k < a.q.size(); ++k) {
        const double move = std::abs(b.q[k] - a.q[k]);
        dt = std::max(dt, 2.0 * std::sqrt(move / amax[k]));
        if (jmax) dt = std::max(dt, std::cbrt(32.0 * move / (*jmax)[k]));
    }
    // A little longer than the bound, so that rounding cannot break it.
    return std::max(o.min_step_time, dt * (1.0 + 1e-6));
}

}  // namespace

bool RetimeOptions::IsValid(std::string* error) const {
    return text::OptionCheck("RetimeOptions", error)
        .holds("ee_speed",
               std::isinf(ee_speed)
                   ? ee_speed > 0.0
                   : ee_speed >= task::kMinJointLimit && ee_speed <= task::kMaxJointLimit,
               "must lie within 1e-06 to 1e+06 m/s (infinity: none)")
        .holds("joint_speed",
               std::isinf(joint_speed)
                   ? joint_speed > 0.0
                   : joint_speed >= task::kMinJointLimit && joint_speed <= task::kMaxJointLimit,
               "must lie within 1e-06 to 1e+06 rad/s (infinity: no cap)")
        .within("corner_angle", corner_angle, 0.0, std::numbers::pi)
        .at_least("corner_ratio", corner_ratio, 1.0)
        .at_least("still_length", still_length, 0.0)
        .greater("min_step_time", min_step_time, 0.0)
        .within("margin", margin, 0.0, 0.5)
        .at_least("jerk_passes", jerk_passes, 1)
        .ok();
}

std::vector<Sample> retime(std::vector<Sample> samples, const JointLimits& limits,
                           const RetimeOptions& options, RetimeStats* stats,
                           std::span<const std::size_t> stops) {
    text::require_valid(options);
    std::string error;
    if (!valid(limits, &error)) throw std::invalid_argument(error);
    for (std::size_t i = 0; i < samples.size(); ++i) {
        if (static_cast<int>(samples[i].q.size()) != limits.dof())
            throw std::invalid_argument(text::format(
                "retime: samples[%zu] has %zu joint angles, the limits are for %d joints", i,
                samples[i].q.size(), limits.dof()));
    }
    for (std::size_t i : stops) {
        if (i >= samples.size())
            throw std::invalid_argument(text::format(
                "retime: stop at sample %zu, but there are %zu samples", i, samples.size()));
    }
    const std::size_t n = samples.size();
    const std::size_t nj = static_cast<std::size_t>(limits.dof());
    Vec vmax = limits.velocity;
    for (double& v : vmax) v = std::min(v, options.joint_speed);
    const Vec& amax = limits.acceleration;
    const Vec* jmax = limits.jerk.empty() ? nullptr : &limits.jerk;
    RetimeStats local;
    for (auto& x : samples) {
        x.t = 0.0;
        x.qd.assign(nj, 0.0);
        x.qdd.assign(nj, 0.0);
    }
    if (n < 2) {
        local.rests = static_cast<int>(n);
        if (stats) *stats = local;
        return samples;
    }
    const Path path(samples, options, stops);
    Vec dt(n - 1, 0.0);
    // Velocities, accelerations and step times from squared path speeds x
    // and, with jerk limits, path accelerations u per sample; the duration.
    const auto fill = [&](const Vec& x, const Vec* u) {
        for (std::size_t i = 0; i < n; ++i) {
            const double v = std::sqrt(x[i]);
            for (std::size_t k = 0; k < nj; ++k) {
                samples[i].qd[k] = path.tangent[i][k] * v;
                if (u) samples[i].qdd[k] = path.tangent[i][k] * (*u)[i] + path.curve[i][k] * x[i];
            }
        }
        double total = 0.0;
        for (std::size_t i = 0; i + 1 < n; ++i) {
            const double v = std::sqrt(x[i]) + std::sqrt(x[i + 1]);
            dt[i] = !path.still[i] && v > 0.0
                        ? 2.0 * path.length[i] / v
                        : rest_to_rest(samples[i], samples[i + 1], amax, jmax, options);
            total += dt[i];
        }
        if (u) return total;
        // The acceleration at a sample: the mean of the steps' beside it,
        // each within the limit by the first consistency rule.
        Vec before(nj, 0.0), after(nj, 0.0);
        for (std::size_t i = 0; i < n; ++i) {
            for (std::size_t k = 0; k < nj; ++k) {
                before[k] = after[k];
                after[k] =
                    i + 1 < n ? (samples[i + 1].qd[k] - samples[i].qd[k]) / dt[i] : before[k];
                samples[i].qdd[k] = i == 0 ? after[k] : 0.5 * (before[k] + after[k]);
            }
        }
        return total;
    };
    for (double margin = options.margin;; margin *= 1e3) {
        Vec planned_v = vmax, planned_a = amax, planned_j = jmax ? *jmax : Vec{};
        for (double& v : planned_v) v *= 1.0 - margin;
        for (double& a : planned_a) a *= 1.0 - margin;
        for (double& j : planned_j) j *= 1.0 - margin;
        const Vec cap = speed_caps(path, planned_v, options);
        Vec x = second_order(path, cap, planned_a);
        ++local.passes;
        if (jmax) {
            // The timing without jerk limits is as fast as any can be: the
            // first jerk timing is taken around it, each later one around
            // the one before, and the quickest is kept.
            Vec around = x, best_x, best_u, u;
            double best = kInf;
            for (int pass = 0; pass < options.jerk_passes; ++pass) {
                ++local.passes;
                retime_detail::jerk_timing(path, cap, planned_a, planned_j, around, x, u);
                const double total = fill(x, &u);
                if (total < best) {
                    best = total;
                    best_x = x;
                    best_u = u;
                }
                // Taken around the last timing, but never below a quarter of
                // the speeds before: a pass around a near stop would keep
                // it one.
                for (std::size_t i = 0; i < n; ++i) around[i] = std::max(x[i], 0.25 * around[i]);
            }
            fill(best_x, &best_u);
        } else {
            fill(x, nullptr);
        }
        bool all = true;
        for (std::size_t i = 0; i + 1 < n && all; ++i)
            all = consistent(samples[i], samples[i + 1], dt[i], vmax, amax, jmax);
        if (all) break;
        if (margin > 1e-3)
            throw std::logic_error("retime: the timing breaks the rules it was planned with");
    }
    for (std::size_t i = 0; i + 1 < n; ++i) samples[i + 1].t = samples[i].t + dt[i];
    for (std::size_t i = 0; i < n; ++i) local.rests += path.rest[i] ? 1 : 0;
    local.duration = samples.back().t;
    retime_detail::find_slow_stretches(path, samples, limits, options, local);
    if (stats) *stats = local;
    return samples;
}

std::string timing_fault(const std::vector<Sample>& samples, const JointLimits& limits) {
    constexpr double kSlack = 1e-6;  // formats.md: relative on limits, absolute on the rest
    if (samples.empty()) return "";
    const std::size_t n = limits.velocity.size();
    const bool jerk = !limits.jerk.empty();
    const auto at = [](std::size_t i) { return "samples[" + std::to_string(i) + "]: "; };
    for (std::size_t i = 0; i < samples.size(); ++i) {
        const Sample& x = samples[i];
        if (x.qd.size() != n || x.qdd.size() != n || x.q.size() != n)
            return at(i) + "no joint velocities and accelerations for every joint";
        for (std::size_t k = 0; k < n; ++k) {
            const auto over = [&](const char* what, double v, double limit, const char* unit) {
                return at(i) + text::format("joint %zu's %s %.6g %s is over its %.6g %s limit",
                                            k + 1, what, v, unit, limit, unit);
            };
            if (std::abs(x.qd[k]) > limits.velocity[k] * (1.0 + kSlack))
                return over("velocity", x.qd[k], limits.velocity[k], "rad/s");
            if (std::abs(x.qdd[k]) > limits.acceleration[k] * (1.0 + kSlack))
                return over("acceleration", x.qdd[k], limits.acceleration[k], "rad/s^2");
            const bool end = i == 0 || i + 1 == samples.size();
            if (end && std::abs(x.qd[k]) > kSlack)
                return at(i) +
                       text::format("joint %zu is not at rest (%.6g rad/s)", k + 1, x.qd[k]);
            if (end && jerk && std::abs(x.qdd[k]) > kSlack)
                return at(i) + text::format("joint %zu accelerates (%.6g rad/s^2) at rest", k + 1,
                                            x.qdd[k]);
        }
        if (i == 0) continue;
        const Sample& a = samples[i - 1];
        const double dt = x.t - a.t;
        if (!(dt > 0.0)) return at(i) + "t does not increase";
        for (std::size_t k = 0; k < n; ++k) {
            const double amax = limits.acceleration[k];
            const auto rule = [&](const char* what) {
                return at(i) + text::format("joint %zu's %s breaks the limits since samples[%zu]",
                                            k + 1, what, i - 1);
            };
            if (std::abs(x.qd[k] - a.qd[k]) > amax * dt + kSlack) return rule("velocity change");
            const double mean = (x.q[k] - a.q[k]) / dt - 0.5 * (a.qd[k] + x.qd[k]);
            if (std::abs(mean) > 0.25 * amax * dt + kSlack) return rule("motion");
            if (!jerk) continue;
            const double j = limits.jerk[k];
            if (std::abs(x.qdd[k] - a.qdd[k]) > j * dt * (1.0 + kSlack) + kSlack)
                return rule("acceleration change (its jerk)");
            const double rate = (x.qd[k] - a.qd[k]) / dt - 0.5 * (a.qdd[k] + x.qdd[k]);
            if (std::abs(rate) > 0.25 * j * dt * (1.0 + kSlack) + kSlack)
                return rule("velocity change against its accelerations (its jerk)");
        }
    }
    return "";
}

}  // namespace modsynth::control
