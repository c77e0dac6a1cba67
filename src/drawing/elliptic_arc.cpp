#include "elliptic_arc.h"

#include <cmath>

namespace modsynth::drawing {

namespace {

double angle_between(const Vec2& a, const Vec2& b) {
    return std::atan2(geometry::cross(a, b), a.dot(b));
}

}  // namespace

std::optional<EllipticArc> arc_from_endpoints(const Vec2& p0, const Vec2& p1, double rx, double ry,
                                              double rotation_degrees, bool large_arc, bool sweep) {
    rx = std::abs(rx);
    ry = std::abs(ry);
    if (!(rx > 0.0) || !(ry > 0.0) || p0 == p1) return std::nullopt;
    const double phi = rotation_degrees * geometry::kPi / 180.0;
    const double c = std::cos(phi), s = std::sin(phi);
    const Vec2 half = (p0 - p1) / 2.0;
    const Vec2 q(c * half.x() + s * half.y(), -s * half.x() + c * half.y());
    const double lambda = q.x() * q.x() / (rx * rx) + q.y() * q.y() / (ry * ry);
    if (lambda > 1.0) {
        rx *= std::sqrt(lambda);
        ry *= std::sqrt(lambda);
    }
    const double num = rx * rx * ry * ry - rx * rx * q.y() * q.y() - ry * ry * q.x() * q.x();
    const double den = rx * rx * q.y() * q.y() + ry * ry * q.x() * q.x();
    double k = std::sqrt(std::max(0.0, num / den));
    if (large_arc == sweep) k = -k;
    const Vec2 cq(k * rx * q.y() / ry, -k * ry * q.x() / rx);
    EllipticArc arc;
    arc.center = Vec2(c * cq.x() - s * cq.y(), s * cq.x() + c * cq.y()) + (p0 + p1) / 2.0;
    arc.u = rx * Vec2(c, s);
    arc.v = ry * Vec2(-s, c);
    const Vec2 a((q.x() - cq.x()) / rx, (q.y() - cq.y()) / ry);
    const Vec2 b((-q.x() - cq.x()) / rx, (-q.y() - cq.y()) / ry);
    arc.t0 = angle_between(Vec2::UnitX(), a);
    double dt = angle_between(a, b);
    if (!sweep && dt > 0.0) dt -= geometry::kTau;
    if (sweep && dt < 0.0) dt += geometry::kTau;
    arc.t1 = arc.t0 + dt;
    return arc;
}

std::optional<EllipticArc> arc_from_bulge(const Vec2& p0, const Vec2& p1, double bulge) {
    if (bulge == 0.0 || p0 == p1) return std::nullopt;
    const double sweep = 4.0 * std::atan(bulge);
    const double chord = (p1 - p0).norm();
    const double radius = chord / (2.0 * std::abs(std::sin(sweep / 2.0)));
    // The center lies on the chord's bisector, on the left of p0 -> p1 for
    // a counter-clockwise arc of less than half a turn.
    const Vec2 mid = (p0 + p1) / 2.0;
    const Vec2 dir = (p1 - p0) / chord;
    const double offset = chord / 2.0 / std::tan(sweep / 2.0);
    EllipticArc arc;
    arc.center = mid + offset * geometry::perp(dir);
    arc.u = Vec2(radius, 0.0);
    arc.v = Vec2(0.0, radius);
    const Vec2 r0 = p0 - arc.center;
    arc.t0 = std::atan2(r0.y(), r0.x());
    arc.t1 = arc.t0 + sweep;
    return arc;
}

}  // namespace modsynth::drawing
