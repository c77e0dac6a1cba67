#pragma once
// How near a spatial primitive comes to a closed convex set (an obstacle, a
// base box), and how far it strays from it: the least and the largest
// distance over the primitive's points.
#include <functional>

#include <modsynth/geometry/primitive3.h>

namespace modsynth::geometry {

/// The distance from a point to a closed convex set, 0 inside it.
using ConvexDistance = std::function<double(const Vec3&)>;

/// The point of the primitive nearest to the set. Lines: the least value of
/// a convex function along a segment. Arcs, circles and helices: a branch
/// and bound on arc length with second-order bounds (the squared distance to
/// a convex set has a second derivative along a unit-speed curve between
/// -2 k d and 2 + 2 k d, k the curvature, d the distance), to within
/// `tolerance` m of the least distance. The point returned lies on the
/// primitive, so its distance is attained: never below the least distance.
CurvePoint3 least_distance(const Primitive3& p, const ConvexDistance& distance,
                           double tolerance = 1e-9);
/// The point of the primitive farthest from the set, to within `tolerance`
/// m (exact on a line: an end point, the distance being convex). Its
/// distance is attained: never above the largest distance.
CurvePoint3 largest_distance(const Primitive3& p, const ConvexDistance& distance,
                             double tolerance = 1e-9);
/// Whether some point of the primitive lies within `gap` of the set
/// (least distance <= gap), decided as soon as a point within it is found or
/// every part of the primitive is proved farther; ties within 1e-12 m count
/// as within.
bool comes_within(const Primitive3& p, const ConvexDistance& distance, double gap);

/// The least distance from the primitive to the box: exact for a line
/// (segment_box), to 1e-9 m otherwise.
CurvePoint3 least_distance_to_box(const Primitive3& p, const Box3& box);
/// The largest distance of a point of the primitive from the box: the
/// farthest any base in the box must reach at least. Exact for a line.
CurvePoint3 largest_distance_to_box(const Primitive3& p, const Box3& box);

}  // namespace modsynth::geometry
