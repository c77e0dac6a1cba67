#include <modsynth/geometry/winding.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace modsynth::geometry {
namespace {

// The angle from a - c to b - c, in (-pi, pi]: the turn along the segment
// ab when c is off it.
double chord_angle(const Vec2& a, const Vec2& b, const Vec2& c) {
    const Vec2 u = a - c;
    const Vec2 v = b - c;
    return std::atan2(u.x() * v.y() - u.y() * v.x(), u.dot(v));
}

// An arc turns round c as its chord does when c lies outside the circular
// segment between them; every point of that segment is within the sagitta
// of the arc. So arcs are cut into pieces whose sagitta is below half the
// distance from c to the arc, and each piece turns as its chord.
double arc_angle(const Primitive& p, const Vec2& c) {
    const double d = nearest(p, c).distance;
    if (!(d > 0.0)) return std::numeric_limits<double>::quiet_NaN();
    const double sweep = std::abs(p.sweep);
    // R (1 - cos(phi / 2)) <= d / 2  <=>  phi <= 2 acos(1 - d / (2 R)).
    const double ratio = std::min(1.0, d / (2.0 * p.radius));
    const double widest = std::min(kPi / 2.0, 2.0 * std::acos(1.0 - ratio));
    const int pieces = std::max(1, static_cast<int>(std::ceil(sweep / widest)));
    double turn = 0.0;
    Vec2 from = p.start;
    for (int k = 1; k <= pieces; ++k) {
        const double a = p.start_angle + p.sweep * k / pieces;
        const Vec2 to = k == pieces && p.kind != PrimitiveKind::Circle
                            ? p.end
                            : p.center + p.radius * Vec2(std::cos(a), std::sin(a));
        turn += chord_angle(from, to, c);
        from = to;
    }
    return turn;
}

}  // namespace

double turning_angle(const Primitive& p, const Vec2& c) {
    switch (p.kind) {
        case PrimitiveKind::Line:
            if (!(nearest(p, c).distance > 0.0)) return std::numeric_limits<double>::quiet_NaN();
            return chord_angle(p.start, p.end, c);
        case PrimitiveKind::Arc:
        case PrimitiveKind::Circle:
            return arc_angle(p, c);
    }
    invalid_kind(p.kind);
}

}  // namespace modsynth::geometry
