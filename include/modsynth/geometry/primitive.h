#pragma once
// Shape primitives of a trajectory (paper II-A) as one small value type, and
// the pure functions that evaluate them by arc length.
#include <modsynth/geometry/vec.h>

namespace modsynth::geometry {

/// Every place that treats kinds apart switches over all of them with no
/// default (the build has -Werror=switch), so a new kind is a compile error
/// wherever it needs handling; docs/design.md lists those places.
enum class PrimitiveKind { Line, Arc, Circle };

/// After a switch over every PrimitiveKind: a value outside the enum is a
/// broken invariant (std::logic_error).
[[noreturn]] void invalid_kind(PrimitiveKind kind);

/// A line segment, an arc or a full circle. Arcs and circles share one
/// representation: a center, a radius, the polar angle of the start about the
/// center and a signed sweep (counter-clockwise positive; +-2*pi for a circle).
/// For a circle `end == start`. Construct through the make_* functions, which
/// fill every field consistently.
struct Primitive {
    PrimitiveKind kind = PrimitiveKind::Line;
    Vec2 start = Vec2::Zero();
    Vec2 end = Vec2::Zero();
    Vec2 center = Vec2::Zero();  ///< arcs and circles only
    double radius = 0.0;         ///< arcs and circles only
    double start_angle = 0.0;    ///< polar angle of start about center
    double sweep = 0.0;          ///< signed swept angle, ccw > 0
};

Primitive make_line(const Vec2& start, const Vec2& end);
/// Arc from start around center to end; ccw selects the direction. The end is
/// projected onto the circle through start. start == end gives a full circle.
Primitive make_arc(const Vec2& start, const Vec2& end, const Vec2& center, bool ccw);
Primitive make_circle(const Vec2& start, const Vec2& center, bool ccw);
/// The same primitive moved by `offset`.
Primitive translate(const Primitive& p, const Vec2& offset);

double length(const Primitive& p);
/// Point at arc length s from the start (s is clamped to [0, length]).
Vec2 point_at(const Primitive& p, double s);
/// Unit tangent in the direction of travel at arc length s.
Vec2 tangent_at(const Primitive& p, double s);
/// Signed curvature (1/radius, + for ccw, 0 for lines).
double curvature(const Primitive& p);
/// Arc length of half a turn about the primitive's centre, infinite for a
/// line: a reader that follows progress as an angle unwrapped from one
/// sample to the next takes a step this long or longer for one back, so
/// motions step less and the verifier refuses more.
double half_turn_length(const Primitive& p);

struct NearestPoint {
    double s = 0.0;  ///< arc length parameter of the nearest point
    Vec2 point = Vec2::Zero();
    double distance = 0.0;
};
/// The point of the primitive nearest to q (the first one, by s, on ties).
NearestPoint nearest(const Primitive& p, const Vec2& q);
/// The point of the primitive farthest from q (the first one, by s, on ties).
NearestPoint farthest(const Primitive& p, const Vec2& q);

/// The critical points of a primitive relative to an origin (paper Table I,
/// with the errata's fix for lines): the points nearest to and farthest from
/// the origin, and for each whether it is an end point or lies inside.
struct CriticalPoints {
    enum class Where { Start, End, Interior };
    NearestPoint closest;
    NearestPoint farthest;
    Where closest_at = Where::Start;
    Where farthest_at = Where::Start;
};
CriticalPoints critical_points(const Primitive& p, const Vec2& origin);

}  // namespace modsynth::geometry
