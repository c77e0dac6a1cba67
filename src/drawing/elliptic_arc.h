#pragma once
// Arcs given by their end points, as SVG paths and DXF bulges give them,
// turned into the center form the curves use.
#include <optional>

#include <modsynth/drawing/curve.h>

namespace modsynth::drawing {

/// SVG's endpoint parameterisation (SVG 1.1 F.6.5, with the radii scaled
/// up when too small, F.6.6, however small). Empty when a radius is zero or
/// the end points coincide (then the arc is a line or nothing), and when
/// radii too far apart in size leave no ellipse a double can hold.
std::optional<EllipticArc> arc_from_endpoints(const Vec2& p0, const Vec2& p1, double rx, double ry,
                                              double rotation_degrees, bool large_arc, bool sweep);

/// Bulges below this in size are drawn as their chord (see arc_from_bulge).
constexpr double kStraightBulge = 1e-8;

/// A DXF polyline bulge: tan(sweep / 4), positive counter-clockwise. Empty
/// for a bulge below kStraightBulge in size: a line.
std::optional<EllipticArc> arc_from_bulge(const Vec2& p0, const Vec2& p1, double bulge);

}  // namespace modsynth::drawing
