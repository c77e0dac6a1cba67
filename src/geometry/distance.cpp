#include <modsynth/geometry/distance.h>

#include <algorithm>
#include <cmath>

namespace modsynth::geometry {

namespace {

// Whether the ray from an arc's center in direction v passes through the arc
// (always for circles). Cross products instead of angles: no trigonometry in
// the distance loops.
bool in_sweep(const Primitive& arc, const Vec2& v) {
    switch (arc.kind) {
        case PrimitiveKind::Circle:
            return true;
        case PrimitiveKind::Arc:
            break;
        case PrimitiveKind::Line:
            invalid_kind(arc.kind);  // a line has no sweep
    }
    // The arc as a counter-clockwise run from `from` to `to`.
    const bool ccw = arc.sweep > 0.0;
    const Vec2 from = (ccw ? arc.start : arc.end) - arc.center;
    const Vec2 to = (ccw ? arc.end : arc.start) - arc.center;
    if (std::abs(arc.sweep) <= kPi) return cross(from, v) >= 0.0 && cross(v, to) >= 0.0;
    // Longer than half a turn: the complement is the short run, test that.
    return !(cross(to, v) > 0.0 && cross(v, from) > 0.0);
}

double point_arc(const Vec2& p, const Primitive& arc) {
    const Vec2 v = p - arc.center;
    if (in_sweep(arc, v)) return std::abs(v.norm() - arc.radius);
    return std::sqrt(std::min((p - arc.start).squaredNorm(), (p - arc.end).squaredNorm()));
}

double segment_circle(const Vec2& a, const Vec2& b, const Primitive& circle) {
    const double closest = point_segment(circle.center, a, b);
    if (closest > circle.radius) return closest - circle.radius;
    const double farthest =
        std::sqrt(std::max((a - circle.center).squaredNorm(), (b - circle.center).squaredNorm()));
    if (farthest < circle.radius) return circle.radius - farthest;
    return 0.0;
}

// At a closest pair (x on the segment, y on the arc) either x is an end of
// the segment, y is an end of the arc, the two touch, or x - y is normal to
// both: then x is the foot of the center on the segment's line and y the
// radial point toward it (the point on the far side is a maximum along the
// arc). The minimum over those candidates is the distance.
double segment_arc(const Vec2& a, const Vec2& b, const Primitive& arc) {
    const Vec2 d = b - a;
    const double dd = d.squaredNorm();
    if (dd == 0.0) return point_arc(a, arc);
    const Vec2 f = a - arc.center;
    const double t_foot = -f.dot(d) / dd;
    const Vec2 foot = f + t_foot * d;
    const double r2 = arc.radius * arc.radius;
    const double h2 = foot.squaredNorm();
    if (h2 <= r2) {
        const double half = std::sqrt((r2 - h2) / dd);
        for (const double t : {t_foot - half, t_foot + half}) {
            if (t >= 0.0 && t <= 1.0 && in_sweep(arc, f + t * d)) return 0.0;
        }
    }
    double best = std::min({point_arc(a, arc), point_arc(b, arc), point_segment(arc.start, a, b),
                            point_segment(arc.end, a, b)});
    if (t_foot > 0.0 && t_foot < 1.0 && in_sweep(arc, foot)) {
        best = std::min(best, std::abs(std::sqrt(h2) - arc.radius));
    }
    return best;
}

}  // namespace

double segment_parameter(const Vec2& p, const Vec2& a, const Vec2& b) {
    const Vec2 d = b - a;
    const double dd = d.squaredNorm();
    if (dd == 0.0) return 0.0;
    return std::clamp((p - a).dot(d) / dd, 0.0, 1.0);
}

double point_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
    const double t = segment_parameter(p, a, b);
    return (p - (a + t * (b - a))).norm();
}

double segment_segment(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
    // Proper crossing: each segment's ends lie strictly on both sides of the
    // other's line. Touching and collinear overlaps are caught below, as an end
    // point then lies on the other segment.
    const double ca = cross(d - c, a - c);
    const double cb = cross(d - c, b - c);
    const double cc = cross(b - a, c - a);
    const double cd = cross(b - a, d - a);
    if (((ca > 0.0 && cb < 0.0) || (ca < 0.0 && cb > 0.0)) &&
        ((cc > 0.0 && cd < 0.0) || (cc < 0.0 && cd > 0.0))) {
        return 0.0;
    }
    // Without a crossing the closest pair in the plane includes an end point.
    return std::min({point_segment(a, c, d), point_segment(b, c, d), point_segment(c, a, b),
                     point_segment(d, a, b)});
}

double point_primitive(const Vec2& p, const Primitive& prim) {
    switch (prim.kind) {
        case PrimitiveKind::Line:
            return point_segment(p, prim.start, prim.end);
        case PrimitiveKind::Circle:
            return std::abs((p - prim.center).norm() - prim.radius);
        case PrimitiveKind::Arc:
            break;
    }
    return point_arc(p, prim);
}

double segment_primitive(const Vec2& a, const Vec2& b, const Primitive& prim) {
    switch (prim.kind) {
        case PrimitiveKind::Line:
            return segment_segment(a, b, prim.start, prim.end);
        case PrimitiveKind::Circle:
            return segment_circle(a, b, prim);
        case PrimitiveKind::Arc:
            break;
    }
    return segment_arc(a, b, prim);
}

double disc_segment(const Vec2& center, double radius, const Vec2& a, const Vec2& b) {
    return std::max(0.0, point_segment(center, a, b) - radius);
}

}  // namespace modsynth::geometry

namespace modsynth::geometry {

Vec2 nearest_in_box(const Vec2& p, const Vec2& lo, const Vec2& hi) {
    return p.cwiseMax(lo).cwiseMin(hi);
}

double point_box(const Vec2& p, const Vec2& lo, const Vec2& hi) {
    return (p - nearest_in_box(p, lo, hi)).norm();
}

double segment_box(const Vec2& a, const Vec2& b, const Vec2& lo, const Vec2& hi) {
    const Vec2 corners[4] = {lo, {hi.x(), lo.y()}, hi, {lo.x(), hi.y()}};
    double best = std::min(point_box(a, lo, hi), point_box(b, lo, hi));
    for (int k = 0; k < 4 && best > 0.0; ++k) {
        // Disjoint convex sets are nearest at a vertex of one of them, and
        // they meet if and only if the segment meets a side (or lies inside).
        best = std::min(best, segment_segment(a, b, corners[k], corners[(k + 1) % 4]));
    }
    return best;
}

}  // namespace modsynth::geometry
