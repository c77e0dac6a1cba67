#include <modsynth/control/retime.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <modsynth/text/format.h>
#include <modsynth/text/option_check.h>

namespace modsynth::control {
namespace {

using Vec = std::vector<double>;
constexpr double kInf = std::numeric_limits<double>::infinity();

double norm(const Vec& v) {
    double s = 0.0;
    for (double x : v) s += x * x;
    return std::sqrt(s);
}

/// The joint-linear path through the samples, parametrised by its length
/// in joint space (sigma): what the passes time.
struct Path {
    int joints = 0;
    Vec length;                ///< per step: its length in rad
    std::vector<Vec> dir;      ///< per step: unit direction (zero when still)
    std::vector<char> still;   ///< per step: does not move
    std::vector<char> rest;    ///< per sample: the motion stops there
    std::vector<Vec> tangent;  ///< per sample: dq/dsigma reported as qd / sdot
    std::vector<Vec> turning;  ///< per step: change of dq/dsigma per sigma along it
};

double turn_angle(const Vec& a, const Vec& b) {
    double dot = 0.0;
    for (std::size_t k = 0; k < a.size(); ++k) dot += a[k] * b[k];
    return std::acos(std::clamp(dot, -1.0, 1.0));
}

Path make_path(const std::vector<Sample>& s, const RetimeOptions& o) {
    Path p;
    const std::size_t n = s.size();
    p.joints = static_cast<int>(s[0].q.size());
    const std::size_t nj = s[0].q.size();
    p.length.assign(n - 1, 0.0);
    p.dir.assign(n - 1, Vec(nj, 0.0));
    p.still.assign(n - 1, 0);
    for (std::size_t i = 0; i + 1 < n; ++i) {
        Vec d(nj);
        for (std::size_t k = 0; k < nj; ++k) d[k] = s[i + 1].q[k] - s[i].q[k];
        const double len = norm(d);
        p.length[i] = len;
        if (len < o.still_length) {
            p.still[i] = 1;
            continue;
        }
        for (double& x : d) x /= len;
        p.dir[i] = std::move(d);
    }
    p.rest.assign(n, 0);
    p.rest[0] = p.rest[n - 1] = 1;
    for (std::size_t i = 1; i + 1 < n; ++i) {
        const bool phase_change = s[i].phase != s[i - 1].phase || s[i].phase != s[i + 1].phase;
        p.rest[i] = phase_change || p.still[i - 1] || p.still[i] ||
                    turn_angle(p.dir[i - 1], p.dir[i]) > o.corner_angle;
    }
    // The derivative at a sample from the two steps beside it, weighted as a
    // central difference on an uneven grid.
    p.tangent.assign(n, Vec(nj, 0.0));
    for (std::size_t i = 1; i + 1 < n; ++i) {
        if (p.rest[i]) continue;
        const double a = p.length[i - 1], b = p.length[i];
        for (std::size_t k = 0; k < nj; ++k)
            p.tangent[i][k] = (b * p.dir[i - 1][k] + a * p.dir[i][k]) / (a + b);
    }
    // At a rest the step's own direction is the tangent on its side.
    p.turning.assign(n - 1, Vec(nj, 0.0));
    for (std::size_t i = 0; i + 1 < n; ++i) {
        if (p.still[i]) continue;
        const Vec& tail = p.rest[i] ? p.dir[i] : p.tangent[i];
        const Vec& head = p.rest[i + 1] ? p.dir[i] : p.tangent[i + 1];
        for (std::size_t k = 0; k < nj; ++k) p.turning[i][k] = (head[k] - tail[k]) / p.length[i];
    }
    return p;
}

/// The path accelerations (d^2 sigma / dt^2) step i allows at squared path
/// speed x: the interval where |dir_k a + turning_k x| <= A_k for every
/// joint. Empty (lo > hi) when x is too fast for the path's turning.
struct Interval {
    double lo = -kInf, hi = kInf;
};

Interval accelerations(const Path& p, std::size_t i, double x, const Vec& amax) {
    Interval r;
    for (int k = 0; k < p.joints; ++k) {
        const double d = p.dir[i][k], c = p.turning[i][k] * x;
        if (std::abs(d) < 1e-12) {
            if (std::abs(c) > amax[k]) return {kInf, -kInf};
            continue;
        }
        double lo = (-amax[k] - c) / d, hi = (amax[k] - c) / d;
        if (d < 0.0) std::swap(lo, hi);
        r.lo = std::max(r.lo, lo);
        r.hi = std::min(r.hi, hi);
    }
    return r;
}

/// The fastest squared path speed at which step i can still be followed
/// (some path acceleration within the limits), at most `upper`.
double fastest_on_step(const Path& p, std::size_t i, double upper, const Vec& amax) {
    const auto ok = [&](double x) {
        const Interval a = accelerations(p, i, x, amax);
        return a.lo <= a.hi;
    };
    if (ok(upper)) return upper;
    double lo = 0.0, hi = upper;
    for (int it = 0; it < 100 && hi - lo > 1e-12 * hi; ++it) {
        const double mid = 0.5 * (lo + hi);
        (ok(mid) ? lo : hi) = mid;
    }
    return lo;
}

/// Squared path speed caps per sample: rests, joint speeds (of the reported
/// velocity and of the steps beside it), the EE speed cap, and how fast the
/// path's turning allows.
Vec speed_caps(const std::vector<Sample>& s, const Path& p, const Vec& vmax, const Vec& amax,
               const RetimeOptions& o) {
    const std::size_t n = s.size();
    Vec cap(n, kInf);
    const auto limit_by = [&](std::size_t i, const Vec& v) {
        for (int k = 0; k < p.joints; ++k) {
            if (std::abs(v[k]) > 0.0) cap[i] = std::min(cap[i], std::pow(vmax[k] / v[k], 2));
        }
    };
    for (std::size_t i = 0; i < n; ++i) {
        if (p.rest[i]) {
            cap[i] = 0.0;
            continue;
        }
        limit_by(i, p.tangent[i]);
        limit_by(i, p.dir[i - 1]);
        limit_by(i, p.dir[i]);
    }
    for (std::size_t i = 0; i + 1 < n; ++i) {
        if (p.still[i]) continue;
        const bool traced = s[i].phase == Phase::Trace && s[i + 1].phase == Phase::Trace &&
                            s[i].primitive == s[i + 1].primitive;
        const double ee = traced ? std::abs(s[i + 1].s - s[i].s) / p.length[i] : 0.0;
        for (std::size_t j : {i, i + 1}) {
            if (ee > 0.0 && std::isfinite(o.ee_speed))
                cap[j] = std::min(cap[j], std::pow(o.ee_speed / ee, 2));
            if (cap[j] > 0.0) cap[j] = fastest_on_step(p, i, cap[j], amax);
        }
    }
    return cap;
}

/// Forward and backward passes: the fastest squared path speeds under the
/// caps whose path acceleration on every step stays within what the step
/// allows at the speed it starts (forward) or ends (backward) with.
Vec passes(const Path& p, const Vec& cap, const Vec& amax) {
    const std::size_t n = cap.size();
    Vec x(n, 0.0);
    x[0] = cap[0];
    for (std::size_t i = 0; i + 1 < n; ++i) {
        if (p.still[i]) {
            x[i + 1] = cap[i + 1];
            continue;
        }
        const Interval a = accelerations(p, i, x[i], amax);
        const double reach = a.lo <= a.hi ? x[i] + 2.0 * p.length[i] * a.hi : 0.0;
        x[i + 1] = std::min(cap[i + 1], std::max(0.0, reach));
    }
    for (std::size_t i = n - 1; i-- > 0;) {
        if (p.still[i]) continue;
        const Interval a = accelerations(p, i, x[i + 1], amax);
        const double reach = a.lo <= a.hi ? x[i + 1] - 2.0 * p.length[i] * a.lo : 0.0;
        x[i] = std::min(x[i], std::max(0.0, reach));
    }
    return x;
}

/// The step's duration from the path speeds at its ends: constant path
/// acceleration. From rest to rest it is the bang-bang time of the joint
/// that needs longest (and min_step_time when nothing moves).
double step_time(const std::vector<Sample>& s, const Path& p, std::size_t i, const Vec& x,
                 const Vec& amax, const RetimeOptions& o) {
    const double v = std::sqrt(x[i]) + std::sqrt(x[i + 1]);
    if (!p.still[i] && v > 0.0) return 2.0 * p.length[i] / v;
    double dt = 0.0;
    for (int k = 0; k < p.joints; ++k)
        dt = std::max(dt, 2.0 * std::sqrt(std::abs(s[i + 1].q[k] - s[i].q[k]) / amax[k]));
    // A little longer than the bound, so that rounding cannot break it.
    return std::max(o.min_step_time, dt * (1.0 + 1e-6));
}

/// formats.md's consistency rules between samples i and i + 1, with room
/// for rounding only (a step at full acceleration meets the first rule with
/// equality), far inside the 1e-6 slack the checker allows.
bool consistent(const Sample& a, const Sample& b, double dt, const Vec& vmax, const Vec& amax) {
    constexpr double kRelative = 1e-9, kAbsolute = 1e-12;
    for (std::size_t k = 0; k < a.q.size(); ++k) {
        if (std::abs(b.qd[k]) > vmax[k] * (1.0 + kRelative)) return false;
        if (std::abs(b.qd[k] - a.qd[k]) > amax[k] * dt * (1.0 + kRelative) + kAbsolute)
            return false;
        const double mean = (b.q[k] - a.q[k]) / dt - 0.5 * (a.qd[k] + b.qd[k]);
        if (std::abs(mean) > 0.25 * amax[k] * dt * (1.0 + kRelative) + kAbsolute) return false;
    }
    return true;
}

}  // namespace

bool RetimeOptions::IsValid(std::string* error) const {
    return text::OptionCheck("RetimeOptions", error)
        .holds("ee_speed", ee_speed > 0.0 && !std::isnan(ee_speed),
               "must be greater than 0 (infinity: no cap)")
        .holds("joint_speed", joint_speed > 0.0 && !std::isnan(joint_speed),
               "must be greater than 0 (infinity: no cap)")
        .within("corner_angle", corner_angle, 0.0, std::numbers::pi)
        .at_least("still_length", still_length, 0.0)
        .greater("min_step_time", min_step_time, 0.0)
        .within("acceleration_margin", acceleration_margin, 0.0, 0.5)
        .ok();
}

std::vector<Sample> retime(std::vector<Sample> samples, const JointLimits& limits,
                           const RetimeOptions& options, RetimeStats* stats) {
    text::require_valid(options);
    std::string error;
    if (!valid(limits, &error)) throw std::invalid_argument(error);
    for (std::size_t i = 0; i < samples.size(); ++i) {
        if (static_cast<int>(samples[i].q.size()) != limits.dof())
            throw std::invalid_argument(text::format(
                "retime: samples[%zu] has %zu joint angles, the limits are for %d joints", i,
                samples[i].q.size(), limits.dof()));
    }
    const std::size_t n = samples.size();
    const std::size_t nj = static_cast<std::size_t>(limits.dof());
    Vec vmax = limits.velocity;
    for (double& v : vmax) v = std::min(v, options.joint_speed);
    const Vec& amax = limits.acceleration;
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
    const Path path = make_path(samples, options);
    // The passes plan with a little less than the limits: their model of a
    // step (the turning taken at one end) differs from the rules checked
    // below by terms of the step's length squared, and a motion planned at
    // exactly the limits would break the rules by those on every step.
    Vec planned = amax;
    for (double& a : planned) a *= 1.0 - options.acceleration_margin;
    Vec cap = speed_caps(samples, path, vmax, planned, options);
    Vec dt(n - 1, 0.0);
    // The passes bound the path's acceleration on each step from one end;
    // where the reported velocities still break a rule (the turning grows
    // along the step, or the tangents differ from the step's direction), the
    // speed at both ends is lowered and the passes run again. Lowering the
    // speeds by a factor shrinks every rule's left side by it and grows the
    // right side (dt) by it, so this ends.
    for (local.passes = 1;; ++local.passes) {
        const Vec x = passes(path, cap, planned);
        for (std::size_t i = 0; i < n; ++i) {
            const double v = std::sqrt(x[i]);
            for (std::size_t k = 0; k < nj; ++k) samples[i].qd[k] = path.tangent[i][k] * v;
        }
        bool all = true;
        for (std::size_t i = 0; i + 1 < n; ++i) {
            dt[i] = step_time(samples, path, i, x, amax, options);
            if (consistent(samples[i], samples[i + 1], dt[i], vmax, amax)) continue;
            all = false;
            cap[i] = std::min(cap[i], 0.8 * x[i]);
            cap[i + 1] = std::min(cap[i + 1], 0.8 * x[i + 1]);
        }
        if (all) break;
        if (local.passes >= 500)
            throw std::logic_error("retime: the path speeds did not settle in 500 passes");
    }
    for (std::size_t i = 0; i + 1 < n; ++i) samples[i + 1].t = samples[i].t + dt[i];
    // The acceleration at a sample: the mean of the steps' beside it, each
    // within the limit by the first consistency rule.
    Vec before(nj, 0.0), after(nj, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t k = 0; k < nj; ++k) {
            before[k] = after[k];
            after[k] = i + 1 < n ? (samples[i + 1].qd[k] - samples[i].qd[k]) / dt[i] : before[k];
            samples[i].qdd[k] = i == 0 ? after[k] : 0.5 * (before[k] + after[k]);
        }
        local.rests += path.rest[i] ? 1 : 0;
    }
    local.duration = samples.back().t;
    if (stats) *stats = local;
    return samples;
}

}  // namespace modsynth::control
