#pragma once
// Planar vectors and the few operations on them that Eigen does not name.
#include <Eigen/Core>

namespace modsynth::geometry {

using Vec2 = Eigen::Vector2d;

constexpr double kPi = 3.14159265358979323846;
constexpr double kTau = 2.0 * kPi;

/// z-component of the 3-D cross product of (a, 0) and (b, 0).
inline double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

/// Unit vector at angle phi from the x-axis, counter-clockwise.
inline Vec2 unit(double phi) { return {std::cos(phi), std::sin(phi)}; }

/// Vector rotated by +90 degrees.
inline Vec2 perp(const Vec2& v) { return {-v.y(), v.x()}; }

}  // namespace modsynth::geometry
