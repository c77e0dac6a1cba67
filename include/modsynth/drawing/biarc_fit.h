#pragma once
// Curves to primitives. Lines and circular arcs map exactly; every other
// segment (Bézier, elliptic arc, spline) becomes a chain of biarcs: pairs
// of arcs (or lines) that meet the curve's end points and end tangents, so
// the chain is tangent-continuous wherever the curve is. A biarc that
// strays further than the tolerance from the curve is split where it strays
// most, and each half fitted again.
#include <cstddef>
#include <vector>

#include <modsynth/drawing/curve.h>
#include <modsynth/geometry/primitive.h>

namespace modsynth::drawing {

using geometry::Primitive;

struct FittedCurve {
    std::vector<Primitive> primitives;
    /// The largest distance found from a dense sampling of the curve to the
    /// primitives, and from the primitives back to the curve.
    double deviation = 0.0;
};

/// Fits one curve (in task coordinates, metres). Throws task::InputError
/// naming curve.source when it cannot be followed within `tolerance` in at
/// most `max_primitives` pieces.
FittedCurve fit_curve(const Curve& curve, double tolerance, std::size_t max_primitives);

/// Deviation of primitives from one segment, both ways, on `samples`
/// points of each: what fit_curve bounds, and what the tests measure.
double deviation(const Segment& segment, double t0, double t1,
                 const std::vector<Primitive>& primitives, int samples);

/// The same path run backwards.
Primitive reversed(const Primitive& p);

}  // namespace modsynth::drawing
