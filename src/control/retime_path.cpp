#include "retime_path.h"

#include <algorithm>
#include <cmath>

namespace modsynth::control::retime_detail {
namespace {

using Vec = std::vector<double>;

double norm(const Vec& v) {
    double s = 0.0;
    for (double x : v) s += x * x;
    return std::sqrt(s);
}

double turn_angle(const Vec& a, const Vec& b) {
    double dot = 0.0;
    for (std::size_t k = 0; k < a.size(); ++k) dot += a[k] * b[k];
    return std::acos(std::clamp(dot, -1.0, 1.0));
}

/// m of path the EE traces from a to b: along one primitive, or from the
/// end of one (where a verified motion's junction sample stands) into the
/// next; 0 off the path.
double traced(const Sample& a, const Sample& b) {
    if (a.phase != Phase::Trace || b.phase != Phase::Trace || a.stroke != b.stroke) return 0.0;
    if (a.primitive == b.primitive) return std::abs(b.s - a.s);
    return b.primitive == a.primitive + 1 ? b.s : 0.0;
}

}  // namespace

Path::Path(const std::vector<Sample>& s, const RetimeOptions& o,
           std::span<const std::size_t> stops) {
    n = s.size();
    joints = static_cast<int>(s[0].q.size());
    const std::size_t nj = s[0].q.size();
    length.assign(n - 1, 0.0);
    dir.assign(n - 1, Vec(nj, 0.0));
    still.assign(n - 1, 0);
    ee_travel.assign(n - 1, 0.0);
    for (std::size_t i = 0; i + 1 < n; ++i) {
        Vec d(nj);
        for (std::size_t k = 0; k < nj; ++k) d[k] = s[i + 1].q[k] - s[i].q[k];
        const double len = norm(d);
        length[i] = len;
        // A step too long to measure (angles read from a file near the
        // largest double) is timed as one from rest to rest, like a still one.
        if (len < o.still_length || !std::isfinite(len)) {
            still[i] = 1;
            continue;
        }
        for (double& x : d) x /= len;
        dir[i] = std::move(d);
        ee_travel[i] = traced(s[i], s[i + 1]);
    }
    Vec turn(n, 0.0);
    for (std::size_t i = 1; i + 1 < n; ++i)
        if (!still[i - 1] && !still[i]) turn[i] = turn_angle(dir[i - 1], dir[i]);
    rest.assign(n, 0);
    rest[0] = rest[n - 1] = 1;
    for (std::size_t i = 1; i + 1 < n; ++i) {
        // A transition or a travel begins or ends at a traced sample (the
        // EE's point, where the joint path turns); the pen lifts and lands
        // at the ends of strokes.
        const bool change = (s[i].phase == Phase::Trace &&
                             (s[i].phase != s[i - 1].phase || s[i].phase != s[i + 1].phase)) ||
                            s[i].stroke != s[i - 1].stroke || s[i].stroke != s[i + 1].stroke;
        // A corner turns much more than the steps beside it; where a smooth
        // joint path bends sharply (a joint reversing), its neighbours turn
        // nearly as much, and the acceleration limits slow the motion there.
        const bool corner = turn[i] > o.corner_angle &&
                            turn[i] > o.corner_ratio * std::max(turn[i - 1], turn[i + 1]);
        rest[i] = change || still[i - 1] || still[i] || corner;
    }
    for (std::size_t i : stops) rest[i] = 1;
    tangent.assign(n, Vec(nj, 0.0));
    curve.assign(n, Vec(nj, 0.0));
    for (std::size_t i = 1; i + 1 < n; ++i) {
        if (rest[i]) continue;
        const double a = length[i - 1], b = length[i];
        for (std::size_t k = 0; k < nj; ++k) {
            tangent[i][k] = (b * dir[i - 1][k] + a * dir[i][k]) / (a + b);
            curve[i][k] = 2.0 * (dir[i][k] - dir[i - 1][k]) / (a + b);
        }
    }
}

double Path::ee_rate(std::size_t i) const {
    if (i == 0 || i + 1 >= n || rest[i] || ee_travel[i - 1] <= 0.0 || ee_travel[i] <= 0.0)
        return 0.0;
    const double a = length[i - 1], b = length[i];
    return (b * ee_travel[i - 1] / a + a * ee_travel[i] / b) / (a + b);
}

void find_slow_stretches(const Path& p, const std::vector<Sample>& s, const JointLimits& limits,
                         const RetimeOptions& o, RetimeStats& stats) {
    for (std::size_t i = 0; i + 1 < p.n; ++i)
        if (p.ee_travel[i] > 0.0) stats.traced_seconds += s[i + 1].t - s[i].t;
    if (!std::isfinite(o.ee_speed)) return;
    // The EE's speed at each traced sample that is not a rest: the path
    // speed times ds/dsigma there (weighted as the tangent is).
    const auto speed = [&](std::size_t i) {
        return p.ee_rate(i) * norm(s[i].qd) / norm(p.tangent[i]);
    };
    const auto slow = [&](std::size_t i) {
        return p.ee_rate(i) > 0.0 && speed(i) < o.ee_speed * (1.0 - 1e-3);
    };
    std::size_t i = 1;
    while (i + 1 < p.n) {
        if (!slow(i)) {
            ++i;
            continue;
        }
        std::size_t j = i;
        while (j + 2 < p.n && slow(j + 1)) ++j;
        const std::size_t end = j;
        // Where a stretch reaches a stop, the speed rising away from it is
        // the ramp into or out of the stop, not the limits' doing.
        bool ramp = false;
        if (p.rest[i - 1]) {
            while (i < j && speed(i + 1) > speed(i)) ++i;
            ramp = i == j;
        }
        if (p.rest[j + 1]) {
            while (j > i && speed(j - 1) > speed(j)) --j;
            ramp = ramp || i == j;
        }
        if (!ramp) {
            SlowStretch st;
            st.first = i;
            st.last = j;
            st.slowest = kInf;
            std::size_t m = i;
            for (std::size_t k = i; k <= j; ++k) {
                const double v = speed(k);
                if (v < st.slowest) {
                    st.slowest = v;
                    m = k;
                }
            }
            double nearest = -1.0;
            for (int k = 0; k < p.joints; ++k) {
                const double rv = std::abs(s[m].qd[k]) / limits.velocity[k];
                const double ra = std::abs(s[m].qdd[k]) / limits.acceleration[k];
                double rj = 0.0;
                if (!limits.jerk.empty()) {
                    for (std::size_t e : {m - 1, m}) {
                        const double dt = s[e + 1].t - s[e].t;
                        rj = std::max(
                            rj, std::abs(s[e + 1].qdd[k] - s[e].qdd[k]) / dt / limits.jerk[k]);
                    }
                }
                for (const auto& [r, name] :
                     {std::pair{rv, "velocity"}, std::pair{ra, "acceleration"},
                      std::pair{rj, "jerk"}}) {
                    if (r > nearest) {
                        nearest = r;
                        st.joint = k;
                        st.limit = name;
                    }
                }
            }
            stats.slow_seconds += s[j + 1].t - s[i - 1].t;
            stats.slow.push_back(std::move(st));
        }
        i = end + 1;
    }
}

}  // namespace modsynth::control::retime_detail
