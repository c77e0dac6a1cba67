#pragma once
// The path primitives of spatial tasks (formats.md "Spatial tasks"): lines,
// arcs and circles about a normal, and helices. Each is a small value type;
// a primitive is a std::variant of them, so that every function below
// dispatches with std::visit over all four and a new kind is a compile
// error wherever it must be handled. All functions are pure and take the
// arc length s from the start.
#include <variant>

#include <modsynth/geometry/vec3.h>

namespace modsynth::geometry {

/// The turn of an arc, a circle or a helix about its axis. Points are
/// origin() + radius (cos theta u + sin theta v) (+ rise along the axis for a
/// helix), theta from 0 at the start in the direction of travel.
struct Turn {
    Vec3 start = Vec3::Zero();   ///< as the task gives it
    Vec3 center = Vec3::Zero();  ///< as the task gives it
    /// The normal of an arc or circle, a helix's axis, as the task gives it
    /// (any length), so that the task is written back exactly as read.
    Vec3 given_axis = Vec3::UnitZ();
    Vec3 axis = Vec3::UnitZ();  ///< given_axis normalised
    /// (start - center) . axis: the start's height over center along the
    /// axis (within 1e-6 m of 0 in a valid task); the turn runs at that height.
    double offset = 0.0;
    double radius = 0.0;     ///< the start's distance from the axis
    Vec3 u = Vec3::UnitX();  ///< unit, from the axis towards the start
    Vec3 v = Vec3::UnitY();  ///< unit, where the turn heads: axis x u ("ccw"), u x axis ("cw")
    bool ccw = true;         ///< right-handed about axis

    /// The point of the axis level with the start.
    Vec3 origin() const { return center + offset * axis; }
};

struct Line3 {
    Vec3 start = Vec3::Zero();
    Vec3 end = Vec3::Zero();
};

/// An arc of sweep in (0, 2 pi]; 2 pi when the task's start equals its end.
struct Arc3 {
    Turn turn;
    double sweep = 0.0;
    /// The end as the task gives it (within 1e-6 m of the turn's point at
    /// `sweep`), kept so that the task is written back as it was read.
    Vec3 end = Vec3::Zero();
};

/// A full turn from the start back to it.
struct Circle3 {
    Turn turn;
};

/// turns > 0 turns about the axis, advancing `pitch` per turn along it
/// (negative: descending).
struct Helix3 {
    Turn turn;
    double pitch = 0.0;
    double turns = 0.0;
};

using Primitive3 = std::variant<Line3, Arc3, Circle3, Helix3>;

/// The turn of a primitive starting at `start` about the line through
/// `center` along `axis` (any non-zero length). Requires start off the axis.
Turn make_turn(const Vec3& start, const Vec3& center, const Vec3& axis, bool ccw);
/// An arc from start to end (the end's angle about the axis fixes the
/// sweep; an end equal to the start within 1e-9 m makes a full turn).
Arc3 make_arc3(const Vec3& start, const Vec3& end, const Vec3& center, const Vec3& normal,
               bool ccw);
Helix3 make_helix3(const Vec3& start, const Vec3& center, const Vec3& axis, bool ccw, double pitch,
                   double turns);

/// "line", "arc", "circle" or "helix", as in the task document.
const char* type_name(const Primitive3& p);
/// The primitive moved by `offset` (every point given, the rest as it was).
Primitive3 translate(const Primitive3& p, const Vec3& offset);
double length(const Primitive3& p);
Vec3 start_point(const Primitive3& p);
/// The point at the primitive's full length (an arc's turn at its sweep).
Vec3 end_point(const Primitive3& p);
/// Point at arc length s from the start (s is clamped to [0, length]); the
/// start itself, exactly as given, at s = 0.
Vec3 point_at(const Primitive3& p, double s);
/// Unit tangent in the direction of travel at arc length s.
Vec3 tangent_at(const Primitive3& p, double s);
/// The largest curvature anywhere on the primitive (constant on each kind):
/// 0 for a line, 1/R for an arc or circle, R/(R^2 + c^2) for a helix of
/// radius R rising c = pitch / (2 pi) per radian.
double max_curvature(const Primitive3& p);
/// Arc length of half a turn about the primitive's axis, infinite for a
/// line (geometry/primitive.h, half_turn_length of a planar primitive).
double half_turn_length(const Primitive3& p);

struct CurvePoint3 {
    double s = 0.0;  ///< arc length of the point
    Vec3 point = Vec3::Zero();
    double distance = 0.0;
};

/// The point of the primitive nearest to q: exact for lines, arcs and
/// circles; for a helix within 1e-9 m, by safeguarded Newton on each convex
/// stretch of the squared distance (docs/design.md, "Spatial types"). Ties
/// go to the smallest s.
CurvePoint3 nearest(const Primitive3& p, const Vec3& q);
/// The same among the points with arc length in [s0, s1] (clamped to the
/// primitive): what follows a point along the path without jumping to
/// another turn of a helix or the other end of a circle.
CurvePoint3 nearest_between(const Primitive3& p, const Vec3& q, double s0, double s1);
/// The point of the primitive farthest from q, with the same exactness (a
/// helix by Newton on the concave stretches).
CurvePoint3 farthest(const Primitive3& p, const Vec3& q);

}  // namespace modsynth::geometry
