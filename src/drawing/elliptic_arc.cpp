#include "elliptic_arc.h"

#include <algorithm>
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
    // Everything in units of the radii, (a, b) = (qx / rx, qy / ry): SVG's
    // formulas multiply squared radii, which underflow or overflow for
    // radii far from 1 (1e-170 is a valid radius, scaled up below).
    double a = q.x() / rx, b = q.y() / ry;
    const double reach = std::hypot(a, b);  // sqrt of F.6.6's lambda
    double k = 0.0;
    if (reach > 1.0) {
        // Radii too small: scaled up, in proportion, until the ellipse just
        // spans the end points; its centre is then halfway between them.
        const double scaled_rx = std::hypot(q.x(), q.y() * (rx / ry));
        const double scaled_ry = std::hypot(q.x() * (ry / rx), q.y());
        rx = scaled_rx;
        ry = scaled_ry;
        a = q.x() / rx;
        b = q.y() / ry;
    } else {
        // The centre's offset from the midpoint, in units of the radii
        // (F.6.5.2): sqrt((1 - lambda) / lambda), signed by the flags.
        k = std::sqrt(std::max(0.0, (1.0 - reach) * (1.0 + reach))) / reach;
        if (large_arc == sweep) k = -k;
    }
    const Vec2 cq(k * rx * b, -k * ry * a);
    EllipticArc arc;
    arc.center = Vec2(c * cq.x() - s * cq.y(), s * cq.x() + c * cq.y()) + (p0 + p1) / 2.0;
    arc.u = rx * Vec2(c, s);
    arc.v = ry * Vec2(-s, c);
    const Vec2 from(a - k * b, b + k * a);
    const Vec2 to(-a - k * b, -b + k * a);
    arc.t0 = angle_between(Vec2::UnitX(), from);
    double dt = angle_between(from, to);
    if (!sweep && dt > 0.0) dt -= geometry::kTau;
    if (sweep && dt < 0.0) dt += geometry::kTau;
    arc.t1 = arc.t0 + dt;
    const bool finite = arc.center.allFinite() && arc.u.allFinite() && arc.v.allFinite() &&
                        std::isfinite(arc.t0) && std::isfinite(arc.t1);
    if (!finite || !(rx > 0.0) || !(ry > 0.0)) return std::nullopt;
    return arc;
}

std::optional<EllipticArc> arc_from_bulge(const Vec2& p0, const Vec2& p1, double bulge) {
    // Below kStraightBulge the centre lies so far out (chord / (4 bulge))
    // that evaluating the arc through it errs by more than the arc strays
    // from its chord (bulge * chord / 2): the chord is the better line.
    if (std::abs(bulge) < kStraightBulge || p0 == p1) return std::nullopt;
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
