#include <modsynth/geometry/primitive.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace modsynth::geometry {

namespace {

using Where = CriticalPoints::Where;

// Start and end closer than this make a full circle: an arc of that length is
// below anything a task can specify and would only produce a degenerate sweep.
constexpr double kSamePoint = 1e-9;

double polar_angle(const Vec2& v) { return std::atan2(v.y(), v.x()); }

// Angle travelled from the start, in the direction of the sweep, to reach the
// polar angle theta; in [0, 2pi).
double travelled(const Primitive& p, double theta) {
    double d = p.sweep > 0.0 ? theta - p.start_angle : p.start_angle - theta;
    d = std::fmod(d, kTau);
    if (d < 0.0) d += kTau;
    // A tiny negative remainder rounds up to exactly 2pi: that is the start.
    return d >= kTau ? 0.0 : d;
}

struct Located {
    NearestPoint point;
    Where where = Where::Start;
};

Located at_start(const Primitive& p, const Vec2& q) {
    return {{0.0, p.start, (q - p.start).norm()}, Where::Start};
}

Located at_end(const Primitive& p, const Vec2& q) {
    return {{length(p), p.end, (q - p.end).norm()}, Where::End};
}

enum class Extremum { Nearest, Farthest };

// Distance to a point moving on a circle grows monotonically with its angular
// distance from the direction of q, so on an arc the extremum is the radial
// (or antipodal) point when the arc passes through it and an end point
// otherwise.
Located curve_extremum(const Primitive& p, const Vec2& q, Extremum which) {
    const Vec2 v = q - p.center;
    const double r = v.norm();
    // From the center every point is equally near and far.
    if (r == 0.0) return at_start(p, q);
    const Vec2 u = (which == Extremum::Nearest ? v : Vec2(-v)) / r;
    const double delta = travelled(p, polar_angle(u));
    const double span = std::abs(p.sweep);
    assert(span <= kTau);
    // travelled() is below 2 pi, a circle's span: a circle passes through
    // every direction and never ends at its sweep, so one test serves both.
    if (delta <= span) {
        const double distance = which == Extremum::Nearest ? std::abs(r - p.radius) : r + p.radius;
        Located found{{p.radius * delta, p.center + p.radius * u, distance}, Where::Interior};
        if (delta == 0.0) {
            found.point.point = p.start;
            found.where = Where::Start;
        } else if (delta == span) {
            found.point.point = p.end;
            found.where = Where::End;
        }
        return found;
    }
    const Located s = at_start(p, q);
    const Located e = at_end(p, q);
    const bool take_end = which == Extremum::Nearest ? e.point.distance < s.point.distance
                                                     : e.point.distance > s.point.distance;
    return take_end ? e : s;
}

Located line_nearest(const Primitive& p, const Vec2& q) {
    const Vec2 d = p.end - p.start;
    const double dd = d.squaredNorm();
    const double t = dd > 0.0 ? std::clamp((q - p.start).dot(d) / dd, 0.0, 1.0) : 0.0;
    if (t == 0.0) return at_start(p, q);
    if (t == 1.0) return at_end(p, q);
    const Vec2 point = p.start + t * d;
    return {{t * std::sqrt(dd), point, (q - point).norm()}, Where::Interior};
}

Located locate_nearest(const Primitive& p, const Vec2& q) {
    switch (p.kind) {
        case PrimitiveKind::Line:
            return line_nearest(p, q);
        case PrimitiveKind::Arc:
        case PrimitiveKind::Circle:
            return curve_extremum(p, q, Extremum::Nearest);
    }
    invalid_kind(p.kind);
}

Located locate_farthest(const Primitive& p, const Vec2& q) {
    switch (p.kind) {
        case PrimitiveKind::Line: {
            const Located s = at_start(p, q);
            const Located e = at_end(p, q);
            return e.point.distance > s.point.distance ? e : s;
        }
        case PrimitiveKind::Arc:
        case PrimitiveKind::Circle:
            return curve_extremum(p, q, Extremum::Farthest);
    }
    invalid_kind(p.kind);
}

}  // namespace

void invalid_kind(PrimitiveKind kind) {
    assert(false && "a primitive kind outside the enum");
    throw std::logic_error("primitive kind " + std::to_string(static_cast<int>(kind)) +
                           " is none of line, arc, circle");
}

Primitive make_line(const Vec2& start, const Vec2& end) {
    Primitive p;
    p.kind = PrimitiveKind::Line;
    p.start = start;
    p.end = end;
    return p;
}

Primitive make_circle(const Vec2& start, const Vec2& center, bool ccw) {
    Primitive p;
    p.kind = PrimitiveKind::Circle;
    p.start = start;
    p.end = start;
    p.center = center;
    p.radius = (start - center).norm();
    p.start_angle = polar_angle(start - center);
    p.sweep = ccw ? kTau : -kTau;
    return p;
}

Primitive make_arc(const Vec2& start, const Vec2& end, const Vec2& center, bool ccw) {
    if ((end - start).norm() <= kSamePoint) return make_circle(start, center, ccw);
    Primitive p;
    p.kind = PrimitiveKind::Arc;
    p.start = start;
    p.center = center;
    p.radius = (start - center).norm();
    p.start_angle = polar_angle(start - center);
    const double end_angle = polar_angle(end - center);
    // An end already on the circle up to rounding is kept as given: the
    // projection of a projected end can differ from it in the last bit, and
    // a task written back and read again must not drift.
    const double rounding = 1e-13 * (1.0 + center.cwiseAbs().maxCoeff() + p.radius);
    p.end = std::abs((end - center).norm() - p.radius) <= rounding
                ? end
                : center + p.radius * unit(end_angle);
    // The projected end may coincide with the start even when the given end
    // does not (same ray, other radius).
    if ((p.end - start).norm() <= kSamePoint) return make_circle(start, center, ccw);
    double sweep = std::fmod(end_angle - p.start_angle, kTau);
    if (ccw && sweep <= 0.0) sweep += kTau;
    if (!ccw && sweep >= 0.0) sweep -= kTau;
    p.sweep = sweep;
    return p;
}

Primitive translate(const Primitive& p, const Vec2& offset) {
    Primitive moved = p;
    moved.start += offset;
    moved.end += offset;
    switch (p.kind) {
        case PrimitiveKind::Line:
            break;
        case PrimitiveKind::Arc:
        case PrimitiveKind::Circle:
            moved.center += offset;
            break;
    }
    return moved;
}

double length(const Primitive& p) {
    switch (p.kind) {
        case PrimitiveKind::Line:
            return (p.end - p.start).norm();
        case PrimitiveKind::Arc:
        case PrimitiveKind::Circle:
            return p.radius * std::abs(p.sweep);
    }
    invalid_kind(p.kind);
}

Vec2 point_at(const Primitive& p, double s) {
    const double total = length(p);
    // Exact end points keep consecutive primitives joined bit for bit.
    if (!(s > 0.0) || total == 0.0) return p.start;
    if (s >= total) return p.end;
    const double fraction = s / total;
    switch (p.kind) {
        case PrimitiveKind::Line:
            return p.start + fraction * (p.end - p.start);
        case PrimitiveKind::Arc:
        case PrimitiveKind::Circle:
            return p.center + p.radius * unit(p.start_angle + fraction * p.sweep);
    }
    invalid_kind(p.kind);
}

Vec2 tangent_at(const Primitive& p, double s) {
    const double total = length(p);
    switch (p.kind) {
        case PrimitiveKind::Line:
            return total > 0.0 ? Vec2((p.end - p.start) / total) : Vec2::UnitX();
        case PrimitiveKind::Arc:
        case PrimitiveKind::Circle: {
            const double fraction = total > 0.0 ? std::clamp(s / total, 0.0, 1.0) : 0.0;
            const Vec2 radial = unit(p.start_angle + fraction * p.sweep);
            return p.sweep > 0.0 ? perp(radial) : Vec2(-perp(radial));
        }
    }
    invalid_kind(p.kind);
}

double curvature(const Primitive& p) {
    switch (p.kind) {
        case PrimitiveKind::Line:
            return 0.0;
        case PrimitiveKind::Arc:
        case PrimitiveKind::Circle:
            if (p.radius == 0.0) return 0.0;
            return (p.sweep > 0.0 ? 1.0 : -1.0) / p.radius;
    }
    invalid_kind(p.kind);
}

double half_turn_length(const Primitive& p) {
    switch (p.kind) {
        case PrimitiveKind::Line:
            return std::numeric_limits<double>::infinity();
        case PrimitiveKind::Arc:
        case PrimitiveKind::Circle:
            return kPi * p.radius;
    }
    invalid_kind(p.kind);
}

NearestPoint nearest(const Primitive& p, const Vec2& q) { return locate_nearest(p, q).point; }

NearestPoint farthest(const Primitive& p, const Vec2& q) { return locate_farthest(p, q).point; }

CriticalPoints critical_points(const Primitive& p, const Vec2& origin) {
    const Located closest = locate_nearest(p, origin);
    const Located farthest = locate_farthest(p, origin);
    CriticalPoints c;
    c.closest = closest.point;
    c.closest_at = closest.where;
    c.farthest = farthest.point;
    c.farthest_at = farthest.where;
    return c;
}

}  // namespace modsynth::geometry
