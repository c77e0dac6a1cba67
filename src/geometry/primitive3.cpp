#include <modsynth/geometry/primitive3.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <type_traits>

#include <modsynth/geometry/distance3.h>
#include <modsynth/geometry/vec.h>

#include "overload.h"

namespace modsynth::geometry {
namespace {

// Start and end closer than this make a full turn (formats.md: "an arc
// whose start equals its end is a full circle").
constexpr double kSamePoint = 1e-9;

Vec3 turn_point(const Turn& t, double theta) {
    return t.origin() + t.radius * (std::cos(theta) * t.u + std::sin(theta) * t.v);
}

Vec3 turn_tangent(const Turn& t, double theta) {
    return -std::sin(theta) * t.u + std::cos(theta) * t.v;
}

double rise_per_radian(const Helix3& h) { return h.pitch / kTau; }
double helix_end_angle(const Helix3& h) { return kTau * h.turns; }
/// Metres along the helix per radian about its axis.
double helix_speed(const Helix3& h) { return std::hypot(h.turn.radius, rise_per_radian(h)); }

Vec3 helix_point(const Helix3& h, double theta) {
    return turn_point(h.turn, theta) + rise_per_radian(h) * theta * h.turn.axis;
}

/// Where a convex function with increasing derivative g (and second
/// derivative dg) is least on [lo, hi]: Newton's method on g = 0, kept inside
/// a shrinking bracket (bisection when a step leaves it).
template <class G, class DG>
double convex_argmin(G g, DG dg, double lo, double hi) {
    if (g(lo) >= 0.0) return lo;
    if (g(hi) <= 0.0) return hi;
    double x = 0.5 * (lo + hi);
    for (int i = 0; i < 200; ++i) {
        const double gx = g(x);
        if (gx == 0.0) return x;
        (gx > 0.0 ? hi : lo) = x;
        const double d = dg(x);
        double nx = d > 0.0 ? x - gx / d : 0.5 * (lo + hi);
        if (!(nx > lo && nx < hi)) nx = 0.5 * (lo + hi);
        const double scale = std::max(1.0, std::abs(x));
        if (std::abs(nx - x) <= 1e-15 * scale || hi - lo <= 1e-15 * scale) return nx;
        x = nx;
    }
    return x;
}

enum class Extremum { Nearest, Farthest };

/// The extreme of |q - point| over the angles [lo, hi] of a circle (no
/// rise): the squared distance is A - B cos(theta - phi), so the nearest
/// point is at phi + 2 pi m or an end, the farthest at phi + pi + 2 pi m or
/// an end.
double circle_extreme_angle(const Turn& t, const Vec3& q, double lo, double hi, Extremum which) {
    const Vec3 e = q - t.origin();
    const double px = e.dot(t.u), py = e.dot(t.v);
    if (px == 0.0 && py == 0.0) return lo;  // on the axis: every point is as near
    const double target = std::atan2(py, px) + (which == Extremum::Nearest ? 0.0 : kPi);
    double best_theta = lo;
    double best = (q - turn_point(t, lo)).squaredNorm();
    auto consider = [&](double theta) {
        const double d = (q - turn_point(t, theta)).squaredNorm();
        if (which == Extremum::Nearest ? d < best : d > best) best = d, best_theta = theta;
    };
    const double m0 = std::ceil((lo - target) / kTau), m1 = std::floor((hi - target) / kTau);
    for (double m = m0; m <= m1; m += 1.0) consider(target + kTau * m);
    consider(hi);
    return best_theta;
}

/// The helix angle in [lo, hi] nearest to / farthest from q. With
/// v = q - origin, z its height along the axis, rho and phi its polar
/// coordinates in the (u, v) plane and c the rise per radian,
/// |q - point(theta)|^2 = rho^2 + R^2 - 2 rho R cos(theta - phi) + (z - c theta)^2,
/// convex where cos(theta - phi) >= -c^2 / (rho R) and concave elsewhere: the
/// least value on [lo, hi] is at an end or the minimum of a convex stretch,
/// the largest at an end or the maximum of a concave stretch. Stretches are
/// visited outwards from the one nearest z / c (for the nearest point) and
/// inwards from the ends (for the farthest), and a side is left once a
/// bound on its remaining stretches cannot beat the best so far.
double helix_extreme_angle(const Helix3& h, const Vec3& q, double lo, double hi, Extremum which) {
    const Turn& t = h.turn;
    const Vec3 e = q - t.origin();
    const double z = e.dot(t.axis), px = e.dot(t.u), py = e.dot(t.v);
    const double rho = std::hypot(px, py), phi = std::atan2(py, px);
    const double r = t.radius, c = rise_per_radian(h), c2 = c * c, b = rho * r;
    const auto f = [&](double th) {
        const double a = z - c * th;
        return rho * rho + r * r - 2.0 * b * std::cos(th - phi) + a * a;
    };
    const bool nearest = which == Extremum::Nearest;
    double best_theta = lo, best = f(lo);
    auto consider = [&](double th) {
        const double v = f(th);
        if (nearest ? v < best : v > best) best = v, best_theta = th;
    };
    consider(hi);
    // g = f' / 2 and its derivative f'' / 2; for a maximum the same of -f.
    const double sign = nearest ? 1.0 : -1.0;
    const auto g = [&](double th) { return sign * (b * std::sin(th - phi) - c * (z - c * th)); };
    const auto dg = [&](double th) { return sign * (b * std::cos(th - phi) + c2); };
    if (b <= c2) {  // convex everywhere: no interior maximum, one minimum
        if (nearest) consider(convex_argmin(g, dg, lo, hi));
        return best_theta;
    }
    const double beta = std::acos(-c2 / b);  // half-width of a convex stretch
    // Stretch m: convex about phi + 2 pi m (half-width beta), concave about
    // phi + pi + 2 pi m (half-width pi - beta).
    const double centre = nearest ? phi : phi + kPi;
    const double half = nearest ? beta : kPi - beta;
    const double m0 = std::ceil((lo - centre - half) / kTau);
    const double m1 = std::floor((hi - centre + half) / kTau);
    if (m0 > m1) return best_theta;
    const double zc = std::clamp(z / c, lo, hi);
    auto piece = [&](double m) {
        return std::pair{std::max(lo, centre + kTau * m - half),
                         std::min(hi, centre + kTau * m + half)};
    };
    auto visit = [&](double m) {
        const auto [a0, a1] = piece(m);
        // The rise term's extreme over the piece, and the turn term's.
        double bound;
        if (nearest) {
            const double tz = std::clamp(z / c, a0, a1);
            bound = (rho - r) * (rho - r) + (z - c * tz) * (z - c * tz);
            if (bound >= best) return false;
        } else {
            const double far = std::max(std::abs(z - c * a0), std::abs(z - c * a1));
            bound = (rho + r) * (rho + r) + far * far;
            if (bound <= best) return false;
        }
        if (a0 <= a1) consider(convex_argmin(g, dg, a0, a1));
        return true;
    };
    if (nearest) {
        const double mid = std::clamp(std::round((zc - centre) / kTau), m0, m1);
        for (double m = mid; m <= m1; m += 1.0)
            if (!visit(m)) break;
        for (double m = mid - 1.0; m >= m0; m -= 1.0)
            if (!visit(m)) break;
    } else {
        // Farther from z / c the rise term only grows: start at the ends.
        const double mid = std::clamp(std::round((zc - centre) / kTau), m0, m1);
        for (double m = m1; m >= mid; m -= 1.0)
            if (!visit(m)) break;
        for (double m = m0; m < mid; m += 1.0)
            if (!visit(m)) break;
    }
    return best_theta;
}

CurvePoint3 extreme_between(const Primitive3& p, const Vec3& q, double s0, double s1,
                            Extremum which) {
    const double len = length(p);
    s0 = std::clamp(s0, 0.0, len);
    s1 = std::clamp(s1, s0, len);
    const double s = std::visit(
        Overload{[&](const Line3& l) {
                     if (which == Extremum::Farthest) {
                         const double d0 = (q - point_at(p, s0)).norm();
                         const double d1 = (q - point_at(p, s1)).norm();
                         return d1 > d0 ? s1 : s0;
                     }
                     const Vec3 d = l.end - l.start;
                     const double t = len > 0.0 ? (q - l.start).dot(d) / (len * len) : 0.0;
                     return std::clamp(t * len, s0, s1);
                 },
                 [&](const Arc3& a) {
                     const double r = a.turn.radius;
                     return r * circle_extreme_angle(a.turn, q, s0 / r, s1 / r, which);
                 },
                 [&](const Circle3& c) {
                     const double r = c.turn.radius;
                     return r * circle_extreme_angle(c.turn, q, s0 / r, s1 / r, which);
                 },
                 [&](const Helix3& h) {
                     const double w = helix_speed(h);
                     return w * helix_extreme_angle(h, q, s0 / w, s1 / w, which);
                 }},
        p);
    const double clamped = std::clamp(s, s0, s1);
    const Vec3 point = point_at(p, clamped);
    return {clamped, point, (q - point).norm()};
}

}  // namespace

Turn make_turn(const Vec3& start, const Vec3& center, const Vec3& axis, bool ccw) {
    Turn t;
    t.start = start;
    t.center = center;
    t.given_axis = axis;
    t.axis = unit_vector(axis);
    t.ccw = ccw;
    const Vec3 r0 = start - center;
    t.offset = r0.dot(t.axis);
    const Vec3 w0 = r0 - t.offset * t.axis;
    t.radius = w0.norm();
    assert(t.radius > 0.0);
    t.u = w0 / t.radius;
    t.v = ccw ? t.axis.cross(t.u) : t.u.cross(t.axis);
    return t;
}

Arc3 make_arc3(const Vec3& start, const Vec3& end, const Vec3& center, const Vec3& normal,
               bool ccw) {
    Arc3 a;
    a.turn = make_turn(start, center, normal, ccw);
    a.end = end;
    if ((end - start).norm() <= kSamePoint) {
        a.sweep = kTau;
        return a;
    }
    const Vec3 e = end - a.turn.origin();
    double theta = std::atan2(e.dot(a.turn.v), e.dot(a.turn.u));
    if (theta < 0.0) theta += kTau;
    a.sweep = theta >= kTau ? 0.0 : theta;
    return a;
}

Helix3 make_helix3(const Vec3& start, const Vec3& center, const Vec3& axis, bool ccw, double pitch,
                   double turns) {
    return Helix3{make_turn(start, center, axis, ccw), pitch, turns};
}

Primitive3 translate(const Primitive3& p, const Vec3& offset) {
    Primitive3 moved = p;
    std::visit(
        [&](auto& x) {
            using T = std::decay_t<decltype(x)>;
            if constexpr (std::is_same_v<T, Line3>) {
                x.start += offset;
                x.end += offset;
            } else {
                // The turn's frame (axis, u, v, radius, offset) moves with it.
                x.turn.start += offset;
                x.turn.center += offset;
                if constexpr (std::is_same_v<T, Arc3>) x.end += offset;
            }
        },
        moved);
    return moved;
}

const char* type_name(const Primitive3& p) {
    return std::visit(
        Overload{[](const Line3&) { return "line"; }, [](const Arc3&) { return "arc"; },
                 [](const Circle3&) { return "circle"; }, [](const Helix3&) { return "helix"; }},
        p);
}

double length(const Primitive3& p) {
    return std::visit(Overload{[](const Line3& l) { return (l.end - l.start).norm(); },
                               [](const Arc3& a) { return a.sweep * a.turn.radius; },
                               [](const Circle3& c) { return kTau * c.turn.radius; },
                               [](const Helix3& h) { return helix_end_angle(h) * helix_speed(h); }},
                      p);
}

Vec3 start_point(const Primitive3& p) {
    return std::visit(
        Overload{[](const Line3& l) { return l.start; }, [](const Arc3& a) { return a.turn.start; },
                 [](const Circle3& c) { return c.turn.start; },
                 [](const Helix3& h) { return h.turn.start; }},
        p);
}

Vec3 end_point(const Primitive3& p) { return point_at(p, length(p)); }

Vec3 point_at(const Primitive3& p, double s) {
    if (!(s > 0.0)) return start_point(p);
    s = std::min(s, length(p));
    return std::visit(
        Overload{[&](const Line3& l) {
                     const double len = (l.end - l.start).norm();
                     if (s >= len) return l.end;
                     return Vec3(l.start + (s / len) * (l.end - l.start));
                 },
                 [&](const Arc3& a) { return turn_point(a.turn, s / a.turn.radius); },
                 [&](const Circle3& c) { return turn_point(c.turn, s / c.turn.radius); },
                 [&](const Helix3& h) { return helix_point(h, s / helix_speed(h)); }},
        p);
}

Vec3 tangent_at(const Primitive3& p, double s) {
    s = std::clamp(s, 0.0, length(p));
    return std::visit(
        Overload{[&](const Line3& l) { return Vec3((l.end - l.start).normalized()); },
                 [&](const Arc3& a) { return turn_tangent(a.turn, s / a.turn.radius); },
                 [&](const Circle3& c) { return turn_tangent(c.turn, s / c.turn.radius); },
                 [&](const Helix3& h) {
                     const double w = helix_speed(h);
                     const double theta = s / w;
                     return Vec3((h.turn.radius * turn_tangent(h.turn, theta) +
                                  rise_per_radian(h) * h.turn.axis) /
                                 w);
                 }},
        p);
}

double max_curvature(const Primitive3& p) {
    return std::visit(Overload{[](const Line3&) { return 0.0; },
                               [](const Arc3& a) { return 1.0 / a.turn.radius; },
                               [](const Circle3& c) { return 1.0 / c.turn.radius; },
                               [](const Helix3& h) {
                                   const double r = h.turn.radius, c = rise_per_radian(h);
                                   return r / (r * r + c * c);
                               }},
                      p);
}

double half_turn_length(const Primitive3& p) {
    return std::visit(Overload{[](const Line3&) { return std::numeric_limits<double>::infinity(); },
                               [](const Arc3& a) { return kPi * a.turn.radius; },
                               [](const Circle3& c) { return kPi * c.turn.radius; },
                               [](const Helix3& h) {
                                   const double r = h.turn.radius, c = rise_per_radian(h);
                                   return kPi * std::sqrt(r * r + c * c);
                               }},
                      p);
}

CurvePoint3 nearest(const Primitive3& p, const Vec3& q) {
    return extreme_between(p, q, 0.0, length(p), Extremum::Nearest);
}

CurvePoint3 nearest_between(const Primitive3& p, const Vec3& q, double s0, double s1) {
    return extreme_between(p, q, s0, s1, Extremum::Nearest);
}

CurvePoint3 farthest(const Primitive3& p, const Vec3& q) {
    return extreme_between(p, q, 0.0, length(p), Extremum::Farthest);
}

}  // namespace modsynth::geometry
