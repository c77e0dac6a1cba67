#pragma once
// How far a path turns round a point: summed over a closed run of
// primitives, how often it winds round an obstacle (prove/loop_proof.h).

#include <modsynth/geometry/primitive.h>
#include <modsynth/geometry/vec.h>

namespace modsynth::geometry {

/// The signed angle (rad, counter-clockwise positive) through which the
/// vector from c to the primitive's point turns from its start to its end.
/// Exact up to rounding for any c off the primitive; NaN when c lies on it.
double turning_angle(const Primitive& p, const Vec2& c);

}  // namespace modsynth::geometry
