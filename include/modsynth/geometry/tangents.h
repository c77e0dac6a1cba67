#pragma once
// Lines tangent to circles: the edges of shortest paths among discs.
#include <modsynth/geometry/vec.h>

#include <vector>

namespace modsynth::geometry {

struct TangentSegment {
    Vec2 from = Vec2::Zero();  ///< on the first circle (or the point)
    Vec2 to = Vec2::Zero();    ///< on the second circle
};

/// The points where the lines through p touch the circle (c, r): two, or
/// none when p is inside or on the circle.
std::vector<Vec2> tangent_points(const Vec2& p, const Vec2& c, double r);

/// The segments touching both circles (c1, r1) and (c2, r2): the two outer
/// ones, and the two inner ones when the circles lie apart. Circles closer
/// than `slack` to touching get their single inner tangent at the touching
/// point, so that a shortest path through such a pinch is never lost.
std::vector<TangentSegment> bitangents(const Vec2& c1, double r1, const Vec2& c2, double r2,
                                       double slack);

}  // namespace modsynth::geometry
