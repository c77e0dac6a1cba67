#pragma once
// Convex polygons: hulls of swept link positions and swept-volume bounds.
#include <vector>

#include <modsynth/geometry/vec.h>

namespace modsynth::geometry {

/// Convex hull in counter-clockwise order without collinear points (Andrew's
/// monotone chain). Degenerate inputs give 1 or 2 points.
std::vector<Vec2> convex_hull(std::vector<Vec2> points);
/// True when p lies inside or on the boundary of a convex polygon given in
/// counter-clockwise order (1 or 2 points: on the point or segment).
bool point_in_convex_polygon(const Vec2& p, const std::vector<Vec2>& polygon);
/// Distance from p to a convex polygon (ccw), 0 inside.
double point_convex_polygon(const Vec2& p, const std::vector<Vec2>& polygon);
/// Distance from the segment ab to a convex polygon (ccw), 0 when they meet.
double segment_convex_polygon(const Vec2& a, const Vec2& b, const std::vector<Vec2>& polygon);
/// Gap between a disc and a convex polygon (ccw), 0 when they overlap.
double disc_convex_polygon(const Vec2& center, double radius, const std::vector<Vec2>& polygon);
/// How many times the closed polygon (any shape, self-crossings allowed; the
/// last vertex joins the first) winds counter-clockwise around p. Exact for
/// points well off the polygon; on it, either neighbouring value.
int winding_number(const std::vector<Vec2>& polygon, const Vec2& p);

}  // namespace modsynth::geometry
