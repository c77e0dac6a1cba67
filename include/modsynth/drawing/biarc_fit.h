#pragma once
// Curves to primitives. Lines and circular arcs map exactly; every other
// segment (Bézier, elliptic arc, spline) becomes a chain of biarcs: pairs
// of arcs (or lines) that meet the curve's end points and end tangents, so
// the chain is tangent-continuous wherever the curve is. A biarc that
// strays further than the tolerance from the curve is split where it strays
// most, and each half fitted again.
#include <cstddef>
#include <optional>
#include <vector>

#include <modsynth/drawing/curve.h>
#include <modsynth/drawing/deadline.h>
#include <modsynth/geometry/primitive.h>

namespace modsynth::drawing {

using geometry::Primitive;

struct FittedCurve {
    std::vector<Primitive> primitives;
    /// The largest distance found from a dense sampling of the curve to the
    /// primitives, and from the primitives back to the curve.
    double deviation = 0.0;
    /// The curve goes out and back within the tolerance of its start (a
    /// flag's zero-area filler, "q0-.2 0 0"): no primitive follows it, as
    /// no stroke of the tool can draw a dot. `primitives` is empty.
    bool dot = false;
};

/// Pieces shorter than this (metres) are folded into their neighbour, and a
/// curve must be larger than this across to be fitted at all.
constexpr double kMinPiece = 1e-8;

/// Fits one curve (in task coordinates, metres); a curve that is a dot at
/// this tolerance comes back with `dot` set. Throws task::InputError
/// naming curve.source when it cannot be followed within `tolerance` in at
/// most `max_primitives` pieces, or is smaller than kMinPiece across, and
/// ImportTimeout once `deadline` has passed. Its work is bounded whatever
/// the curve: every step advances along it by a share of it or adds a
/// piece, and the pieces are capped.
FittedCurve fit_curve(const Curve& curve, double tolerance, std::size_t max_primitives,
                      Clock::time_point deadline = kNoDeadline);

/// Deviation of primitives from one segment, both ways, on `samples`
/// points of each: what fit_curve bounds, and what the tests measure.
double deviation(const Segment& segment, double t0, double t1,
                 const std::vector<Primitive>& primitives, int samples);

/// The same path run backwards.
Primitive reversed(const Primitive& p);

/// The arc leaving p with unit tangent t that passes through q; a line
/// when nearly straight.
Primitive arc_through(const Vec2& p, const Vec2& t, const Vec2& q);

/// The arc that passes through q and arrives at p with unit tangent t; a
/// line when nearly straight.
Primitive arc_into(const Vec2& q, const Vec2& p, const Vec2& t);

/// The biarc from p0 (unit tangent t0) to p1 (unit tangent t1) whose two
/// arcs have equal tangent lengths, tangent-continuous where they meet;
/// empty when none runs forwards.
std::optional<std::vector<Primitive>> biarc(const Vec2& p0, const Vec2& t0, const Vec2& p1,
                                            const Vec2& t1);

}  // namespace modsynth::drawing
