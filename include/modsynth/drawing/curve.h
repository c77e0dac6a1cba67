#pragma once
// The curves of a drawing before they become primitives: the exact shapes a
// file describes (segments, Béziers, elliptic arcs, B-splines), as value
// types with pure evaluation functions. Every segment is parameterised on
// [0, 1]; a Curve is a chain of segments, each starting where the one before
// ends.
#include <string>
#include <variant>
#include <vector>

#include <modsynth/geometry/vec.h>

namespace modsynth::drawing {

using geometry::Vec2;

struct LineSegment {
    Vec2 a = Vec2::Zero();
    Vec2 b = Vec2::Zero();
};

/// Cubic Bézier (quadratic ones are raised to cubic, exactly).
struct CubicBezier {
    Vec2 p0 = Vec2::Zero(), p1 = Vec2::Zero(), p2 = Vec2::Zero(), p3 = Vec2::Zero();
};

/// center + u cos(t) + v sin(t) for t from t0 to t1 (either way round). The
/// affine image of an elliptic arc is one too, so transforms stay exact; a
/// circular arc is the case u perpendicular to v and |u| == |v|.
struct EllipticArc {
    Vec2 center = Vec2::Zero();
    Vec2 u = Vec2::UnitX();
    Vec2 v = Vec2::UnitY();
    double t0 = 0.0;
    double t1 = 0.0;
};

/// A (rational) B-spline: degree, clamped or not, knots of size
/// control.size() + degree + 1, one weight per control point (all 1 when
/// not rational), evaluated over [knots[degree], knots[control.size()]].
struct BSpline {
    int degree = 3;
    std::vector<double> knots;
    std::vector<Vec2> control;
    std::vector<double> weights;
};

using Segment = std::variant<LineSegment, CubicBezier, EllipticArc, BSpline>;

/// One continuous piece of the drawing, named after where it came from
/// (e.g. "path#p3 (line 12)", "LWPOLYLINE (layer 0, handle 2A)").
struct Curve {
    std::string source;
    std::vector<Segment> segments;
};

/// A 2-D affine map x -> m x + offset.
struct Affine {
    Eigen::Matrix2d m = Eigen::Matrix2d::Identity();
    Vec2 offset = Vec2::Zero();
    Vec2 operator()(const Vec2& p) const { return m * p + offset; }
    /// this after inner: x -> this(inner(x)).
    Affine after(const Affine& inner) const { return {m * inner.m, m * inner.offset + offset}; }
};

Vec2 point(const Segment& s, double t);
/// d point / d t, the one-sided limit from inside [0, 1] at the ends.
Vec2 derivative(const Segment& s, double t);
Vec2 start_point(const Segment& s);
Vec2 end_point(const Segment& s);
Segment transformed(const Segment& s, const Affine& a);
/// True when the elliptic arc is circular within a relative 1e-12.
bool is_circular(const EllipticArc& e);
/// Approximate length by a polyline of `pieces` chords.
double approximate_length(const Segment& s, int pieces = 64);

}  // namespace modsynth::drawing
