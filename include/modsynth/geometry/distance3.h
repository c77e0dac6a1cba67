#pragma once
// Euclidean distances in space between points, segments, boxes and convex
// hulls of a few points: exact (up to rounding) for parallel, collinear,
// zero-length segments and points on faces, never NaN on finite input.
#include <span>

#include <modsynth/geometry/vec3.h>

namespace modsynth::geometry {

/// Parameter t in [0, 1] of the point of segment ab nearest to p (0 when a
/// and b coincide).
double segment_parameter(const Vec3& p, const Vec3& a, const Vec3& b);
double point_segment(const Vec3& p, const Vec3& a, const Vec3& b);
/// Distance between segments ab and cd (either may be a point).
double segment_segment(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);
/// The point of the closed box nearest to p (p itself inside).
Vec3 nearest_in_box(const Vec3& p, const Box3& box);
/// Distance from p to the closed box; 0 inside and on its faces.
double point_box(const Vec3& p, const Box3& box);
/// Distance from segment ab to the closed box, 0 when they meet; `t`, when
/// given, receives the parameter in [0, 1] of a nearest point of the segment.
double segment_box(const Vec3& a, const Vec3& b, const Box3& box, double* t = nullptr);

/// A lower bound on the distance between the convex hulls of two non-empty
/// point sets, tight up to rounding. The nearest points are searched with
/// Gilbert-Johnson-Keerthi; the value returned is the gap between the two
/// sets measured along the direction that joins them, min over a of a.n
/// minus max over b of b.n, which no pair of points of the hulls can beat
/// whatever the accuracy of the search. 0 when the hulls meet. At most 8
/// points in each set.
double hull_distance(std::span<const Vec3> a, std::span<const Vec3> b);

}  // namespace modsynth::geometry
