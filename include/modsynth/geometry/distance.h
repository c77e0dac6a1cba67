#pragma once
// Euclidean distances between points, segments, primitives and discs.
#include <modsynth/geometry/primitive.h>

namespace modsynth::geometry {

/// Parameter t in [0, 1] of the point of segment ab nearest to p.
double segment_parameter(const Vec2& p, const Vec2& a, const Vec2& b);
double point_segment(const Vec2& p, const Vec2& a, const Vec2& b);
double segment_segment(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d);
double point_primitive(const Vec2& p, const Primitive& prim);
double segment_primitive(const Vec2& a, const Vec2& b, const Primitive& prim);
/// Gap between a disc and a segment; 0 when they overlap.
double disc_segment(const Vec2& center, double radius, const Vec2& a, const Vec2& b);
/// Distance from p to the closed axis-aligned box [lo, hi]; 0 inside.
double point_box(const Vec2& p, const Vec2& lo, const Vec2& hi);
/// The point of the box [lo, hi] nearest to p.
Vec2 nearest_in_box(const Vec2& p, const Vec2& lo, const Vec2& hi);
/// Distance from segment ab to the closed box [lo, hi]; 0 when they meet.
double segment_box(const Vec2& a, const Vec2& b, const Vec2& lo, const Vec2& hi);

}  // namespace modsynth::geometry
