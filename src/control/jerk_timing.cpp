#include "jerk_timing.h"

#include <algorithm>
#include <cmath>

namespace modsynth::control::retime_detail {
namespace {

using Vec = std::vector<double>;

/// a x + b u + c v <= r: the state (x, u) at a sample and the path
/// acceleration v at the next.
struct Row3 {
    double a, b, c, r;
};

/// a x + b u <= r.
struct Row2 {
    double a, b, r;
};

struct Pt {
    double x, u;
};

/// A linear expression in the states of a step's two samples, (x, u) and
/// (y, v), plus a constant.
struct Lin {
    double x = 0.0, u = 0.0, y = 0.0, v = 0.0, k = 0.0;
    Lin operator+(const Lin& o) const { return {x + o.x, u + o.u, y + o.y, v + o.v, k + o.k}; }
    Lin operator*(double s) const { return {x * s, u * s, y * s, v * s, k * s}; }
};

/// The controllable states at a sample: a convex polygon (counter-
/// clockwise), the single state (0, 0) at a rest, or, just before a rest,
/// the segment of states (x, -x / length) for x in [0, end] that stop the
/// next sample exactly.
struct Set {
    enum Kind { Rest, Segment, Polygon } kind = Rest;
    double end = 0.0;
    std::vector<Pt> poly;
};

void clip(std::vector<Pt>& p, const Row2& h) {
    if (p.empty()) return;
    thread_local std::vector<Pt> out;
    out.clear();
    const std::size_t n = p.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Pt& a = p[i];
        const Pt& b = p[(i + 1) % n];
        const double fa = h.a * a.x + h.b * a.u - h.r;
        const double fb = h.a * b.x + h.b * b.u - h.r;
        if (fa <= 0.0) out.push_back(a);
        if ((fa < 0.0 && fb > 0.0) || (fa > 0.0 && fb < 0.0)) {
            const double t = fa / (fa - fb);
            out.push_back({a.x + t * (b.x - a.x), a.u + t * (b.u - a.u)});
        }
    }
    p.swap(out);
}

/// The polygon's half-planes: its edges and its bounding box (which keeps
/// a polygon that has collapsed onto a segment from reading as a line).
void polygon_rows(const std::vector<Pt>& p, std::vector<Row2>& rows) {
    rows.clear();
    double x0 = kInf, x1 = -kInf, u0 = kInf, u1 = -kInf;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const Pt& a = p[i];
        const Pt& b = p[(i + 1) % p.size()];
        x0 = std::min(x0, a.x);
        x1 = std::max(x1, a.x);
        u0 = std::min(u0, a.u);
        u1 = std::max(u1, a.u);
        const double ea = b.u - a.u, eb = -(b.x - a.x);
        const double scale = std::abs(ea) + std::abs(eb);
        if (scale > 0.0) rows.push_back({ea / scale, eb / scale, (ea * a.x + eb * a.u) / scale});
    }
    rows.push_back({1.0, 0.0, x1});
    rows.push_back({-1.0, 0.0, -x0});
    rows.push_back({0.0, 1.0, u1});
    rows.push_back({0.0, -1.0, -u0});
}

/// Pulls the polygon towards its centre by a relative 1e-9: the forward
/// pass, which meets the next sample's polygon with rounded arithmetic,
/// then always finds a state inside the exact one.
void shrink(std::vector<Pt>& p) {
    if (p.empty()) return;
    Pt c{0.0, 0.0};
    for (const Pt& q : p) {
        c.x += q.x / static_cast<double>(p.size());
        c.u += q.u / static_cast<double>(p.size());
    }
    for (Pt& q : p) {
        q.x = c.x + (q.x - c.x) * (1.0 - 1e-9);
        q.u = c.u + (q.u - c.u) * (1.0 - 1e-9);
    }
}

/// Drops vertices of a polygon with more than kMaxVertices, each time the
/// one that cuts off the smallest triangle: the polygon only shrinks (a
/// subset of controllable states is controllable), and the next sets'
/// projections stay small.
constexpr std::size_t kMaxVertices = 12;

void simplify(std::vector<Pt>& p) {
    while (p.size() > kMaxVertices) {
        std::size_t best = 0;
        double least = kInf;
        for (std::size_t i = 0; i < p.size(); ++i) {
            const Pt& a = p[(i + p.size() - 1) % p.size()];
            const Pt& b = p[i];
            const Pt& c = p[(i + 1) % p.size()];
            const double area = std::abs((b.x - a.x) * (c.u - a.u) - (b.u - a.u) * (c.x - a.x));
            if (area < least) {
                least = area;
                best = i;
            }
        }
        p.erase(p.begin() + static_cast<long>(best));
    }
}

class Timing {
public:
    Timing(const Path& p, const Vec& cap, const Vec& amax, const Vec& jmax, const Vec& around)
        : p_(p), cap_(cap), amax_(amax), jmax_(jmax) {
        // The tangent of sqrt at the squared speed it is taken around,
        // (x + xh) / (2 sqrt(xh)), bounds the speed from above for every
        // x; at a rest the speed is 0.
        slope_.assign(p.n, 0.0);
        offset_.assign(p.n, 0.0);
        speed_.assign(p.n, 0.0);
        for (std::size_t i = 0; i < p.n; ++i) {
            if (p.rest[i]) continue;
            const double s = std::sqrt(std::max(around[i], 1e-12));
            slope_[i] = 0.5 / s;
            offset_[i] = 0.5 * s;
            speed_[i] = s;
        }
    }

    bool run(Vec& x, Vec& u) {
        backward();
        return forward(x, u);
    }

private:
    /// The step's rules as rows over (x, u, v), y = x + length (u + v)
    /// substituted.
    /// With `jerk` false the rules of velocities against accelerations,
    /// with it true the jerk rules' linear forms, appended; jerk_end_ is
    /// where the latter end.
    void step_rows(std::size_t i, std::vector<Row3>& rows) {
        rows.clear();
        step_rows(i, rows, false);
        step_rows(i, rows, true, rows.size());
    }

    void step_rows(std::size_t i, std::vector<Row3>& rows, bool jerk, std::size_t = 0) {
        if (jerk) jerk_begin_ = rows.size();
        const double len = p_.length[i];
        const auto add = [&](const Lin& e, double bound) {
            rows.push_back({e.x + e.y, e.u + e.y * len, e.v + e.y * len, bound - e.k});
        };
        const auto both = [&](const Lin& e, double bound) {
            add(e, bound);
            add(e * -1.0, bound);
        };
        const Vec& ta = p_.tail(i);
        const Vec& tb = p_.head(i);
        const Vec& t0 = p_.tangent[i];
        const Vec& t1 = p_.tangent[i + 1];
        const Vec& c0 = p_.curve[i];
        const Vec& c1 = p_.curve[i + 1];
        // Bounds on the sum of the two speeds, linear in x and y.
        const Lin speeds{slope_[i], 0.0, slope_[i + 1], 0.0, offset_[i] + offset_[i + 1]};
        const double around = speed_[i] + speed_[i + 1];
        for (int k = 0; k < p_.joints; ++k) {
            const double a = amax_[k], j = jmax_[k];
            const double delta = tb[k] - ta[k], tau = delta / len;
            if (!jerk) {
                // Velocities against accelerations, as without jerk limits,
                // the step's path acceleration being the mean of its ends'.
                const Lin mean_u{0.0, 0.5 * ta[k], 0.0, 0.5 * ta[k], 0.0};
                both(mean_u + Lin{tau, 0.0, 0.0, 0.0, 0.0}, a);
                both(mean_u + Lin{0.0, 0.0, tau, 0.0, 0.0}, a);
                const double e = p_.dir[i][k] - ta[k], f = p_.dir[i][k] - tb[k];
                both(Lin{2.0 * e + f, 0.0, f, 0.0, 0.0}, a * len);
                both(Lin{e, 0.0, e + 2.0 * f, 0.0, 0.0}, a * len);
                continue;
            }
            if (around <= 0.0) continue;
            // J dt = 2 J len / (a + b) >= (2 J len / S^2) (2 S - speeds)
            // for S = the speeds' sum where the bounds are taken (1 / s is
            // convex), and speeds >= a + b.
            const double g = 2.0 * j * len / (around * around);
            // |qdd(i+1) - qdd(i)| <= J dt.
            const Lin jump{-c0[k], -t0[k], c1[k], t1[k], 0.0};
            add(jump + speeds * g, 4.0 * j * len / around);
            add(jump * -1.0 + speeds * g, 4.0 * j * len / around);
            // |(qd(i+1) - qd(i)) / dt - (qdd(i) + qdd(i+1)) / 2| <= J dt / 4:
            // exactly, the left side is |m - delta (b - a)^2 / (4 len)| with
            // m linear and 0 <= (b - a)^2 <= |y - x| = len |u + v|.
            const Lin m{0.5 * (tau - c0[k]), 0.25 * delta, 0.5 * (tau - c1[k]), -0.25 * delta, 0.0};
            const Lin r{0.0, 0.25 * delta, 0.0, 0.25 * delta, 0.0};
            for (double s1 : {1.0, -1.0})
                for (double s2 : {1.0, -1.0})
                    add(m * s1 + r * s2 + speeds * (0.25 * g), j * len / around);
        }
        if (jerk) jerk_end_ = rows.size();
    }

    /// The jerk rules themselves for the step from (x, u) at i with v at
    /// i + 1, with the step's time from its speeds.
    bool jerk_ok(std::size_t i, double x, double u, double v) const {
        const double len = p_.length[i];
        const double y = x + len * (u + v);
        if (y < 0.0) return false;
        const double a = std::sqrt(x), b = std::sqrt(y);
        if (a + b <= 0.0) return true;
        const double dt = 2.0 * len / (a + b);
        const Vec& ta = p_.tail(i);
        const Vec& tb = p_.head(i);
        for (int k = 0; k < p_.joints; ++k) {
            const double j = jmax_[k];
            const double qdd0 = p_.tangent[i][k] * u + p_.curve[i][k] * x;
            const double qdd1 = p_.tangent[i + 1][k] * v + p_.curve[i + 1][k] * y;
            if (std::abs(qdd1 - qdd0) > j * dt) return false;
            const double rate = (tb[k] * b - ta[k] * a) / dt;
            if (std::abs(rate - 0.5 * (qdd0 + qdd1)) > 0.25 * j * dt) return false;
        }
        return true;
    }

    /// The sample's own rows: acceleration limits of qdd = tangent u +
    /// curve x.
    void sample_rows(std::size_t i, std::vector<Row2>& rows) const {
        rows.clear();
        for (int k = 0; k < p_.joints; ++k) {
            const double t = p_.tangent[i][k], c = p_.curve[i][k], a = amax_[k];
            rows.push_back({c, t, a});
            rows.push_back({-c, -t, a});
        }
    }

    void backward() {
        const std::size_t n = p_.n;
        sets_.assign(n, Set{});
        std::vector<Row3> rows;
        std::vector<Row2> own, next, flat;
        for (std::size_t i = n; i-- > 0;) {
            Set& s = sets_[i];
            if (p_.rest[i] || i + 1 == n) {
                s.kind = Set::Rest;
                continue;
            }
            step_rows(i, rows);
            sample_rows(i, own);
            const double len = p_.length[i];
            if (p_.rest[i + 1]) {
                // Stop at the next sample: v = 0, y = x + len u = 0.
                s.kind = Set::Segment;
                double end = cap_[i];
                const auto bound = [&](double a, double r) {
                    if (a > 0.0) end = std::min(end, r / a);
                };
                for (const Row3& c : rows) bound(c.a - c.b / len, c.r);
                for (const Row2& c : own) bound(c.a - c.b / len, c.r);
                s.end = std::max(0.0, end) * (1.0 - 1e-9);
                continue;
            }
            s.kind = Set::Polygon;
            std::vector<Pt>& poly = s.poly;
            double umax = 0.0;
            for (int k = 0; k < p_.joints; ++k) {
                const double t = std::abs(p_.tangent[i][k]);
                if (t > 1e-9)
                    umax = std::max(umax, (amax_[k] + std::abs(p_.curve[i][k]) * cap_[i]) / t);
            }
            poly = {{0.0, -umax}, {cap_[i], -umax}, {cap_[i], umax}, {0.0, umax}};
            for (const Row2& c : own) clip(poly, c);
            flat.clear();
            const Set& after = sets_[i + 1];
            if (after.kind == Set::Segment) {
                // The next sample stops the one after it: (y, v) =
                // (y, -y / len2), with y = x + len (u + v), fixes v.
                const double len2 = p_.length[i + 1];
                const double w = 1.0 / (len + len2);
                for (const Row3& c : rows)
                    flat.push_back({c.a - c.c * w, c.b - c.c * len * w, c.r});
                // 0 <= y = (x + len u) len2 w <= end.
                flat.push_back({len2 * w, len * len2 * w, after.end});
                flat.push_back({-len2 * w, -len * len2 * w, 0.0});
            } else {
                polygon_rows(after.poly, next);
                for (const Row2& c : next) rows.push_back({c.a, c.a * len, c.a * len + c.b, c.r});
                // Fourier-Motzkin: v out, pair by pair.
                thread_local std::vector<Row3> lower, upper;
                lower.clear();
                upper.clear();
                for (const Row3& c : rows) {
                    if (c.c > 0.0) {
                        upper.push_back(c);
                    } else if (c.c < 0.0) {
                        lower.push_back(c);
                    } else {
                        flat.push_back({c.a, c.b, c.r});
                    }
                }
                for (const Row3& l : lower) {
                    for (const Row3& h : upper) {
                        const double wl = h.c, wh = -l.c;
                        Row2 r{h.a * wh + l.a * wl, h.b * wh + l.b * wl, h.r * wh + l.r * wl};
                        const double scale = std::abs(r.a) + std::abs(r.b);
                        if (scale > 0.0) {
                            flat.push_back({r.a / scale, r.b / scale, r.r / scale});
                        } else if (r.r < 0.0) {
                            poly.clear();
                        }
                    }
                }
            }
            for (const Row2& c : flat) {
                if (poly.empty()) break;
                clip(poly, c);
            }
            // Standing still is always possible, so the set is never empty;
            // rounding aside, it holds (0, 0).
            if (poly.empty()) poly = {{0.0, 0.0}};
            simplify(poly);
            shrink(poly);
        }
    }

    bool forward(Vec& x, Vec& u) {
        const std::size_t n = p_.n;
        x.assign(n, 0.0);
        u.assign(n, 0.0);
        std::vector<Row3> rows;
        std::vector<Row2> next;
        bool moved = false;
        for (std::size_t i = 0; i + 1 < n; ++i) {
            const Set& after = sets_[i + 1];
            const double len = p_.length[i];
            double y = 0.0, v = 0.0;
            if (after.kind == Set::Segment) {
                const double len2 = p_.length[i + 1];
                y = (x[i] + len * u[i]) * len2 / (len + len2);
                v = -y / len2;
            } else if (after.kind == Set::Polygon) {
                // The largest v the linear rows allow (the jerk rules in
                // their safe linear forms) and the largest the rows other
                // than those allow: between them, the largest that meets
                // the jerk rules themselves, with this step's real time.
                rows.clear();
                step_rows(i, rows, false);
                const std::size_t plain = rows.size();
                step_rows(i, rows, true, plain);
                polygon_rows(after.poly, next);
                for (const Row2& c : next) rows.push_back({c.a, c.a * len, c.a * len + c.b, c.r});
                double lo = -kInf, hi = kInf, top = kInf;
                for (std::size_t r = 0; r < rows.size(); ++r) {
                    const Row3& c = rows[r];
                    const double rest = c.r - c.a * x[i] - c.b * u[i];
                    if (c.c > 0.0) {
                        hi = std::min(hi, rest / c.c);
                        if (r < plain || r >= jerk_end_) top = std::min(top, rest / c.c);
                    } else if (c.c < 0.0) {
                        lo = std::max(lo, rest / c.c);
                    }
                }
                v = hi >= lo ? hi : 0.5 * (lo + hi);
                if (hi >= lo && top > hi) {
                    double good = hi, bad = top;
                    if (jerk_ok(i, x[i], u[i], top)) {
                        good = top;
                    } else {
                        for (int it = 0; it < 40 && bad - good > 1e-12 * (1.0 + std::abs(good));
                             ++it) {
                            const double mid = 0.5 * (good + bad);
                            (jerk_ok(i, x[i], u[i], mid) ? good : bad) = mid;
                        }
                    }
                    v = good;
                }
                y = x[i] + len * (u[i] + v);
            }
            x[i + 1] = std::max(0.0, y);
            u[i + 1] = v;
            moved = moved || x[i + 1] > 0.0;
        }
        return moved;
    }

    const Path& p_;
    const Vec& cap_;
    const Vec& amax_;
    const Vec& jmax_;
    Vec slope_, offset_, speed_;
    std::size_t jerk_begin_ = 0, jerk_end_ = 0;
    std::vector<Set> sets_;
};

}  // namespace

bool jerk_timing(const Path& path, const Vec& cap, const Vec& amax, const Vec& jmax,
                 const Vec& around, Vec& x, Vec& u) {
    return Timing(path, cap, amax, jmax, around).run(x, u);
}

}  // namespace modsynth::control::retime_detail
