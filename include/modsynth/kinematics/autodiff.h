#pragma once
// The scalars of the spatial refinement: doubles, and forward-mode
// automatic-differentiation scalars (Eigen's AutoDiffScalar) whose
// derivatives are those with respect to the variables one path point's
// constraints depend on. Pose code is written once for both.
#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

namespace modsynth::kinematics {

/// Variables one point's constraints may depend on, at most: the base, an
/// arm's lengths and offsets, and its free numbers at both ends of a
/// primitive. A fixed bound keeps the derivatives on the stack.
inline constexpr int kMaxLocalVariables = 24;

using AdDerivatives = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxLocalVariables, 1>;
using AD = Eigen::AutoDiffScalar<AdDerivatives>;

template <class T>
using Point3 = Eigen::Matrix<T, 3, 1>;

inline double value_of(double v) { return v; }
inline double value_of(const AD& v) { return v.value(); }

}  // namespace modsynth::kinematics
