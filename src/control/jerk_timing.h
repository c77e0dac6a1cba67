#pragma once
// retime() under jerk limits: the path acceleration at each sample is a
// second state besides the squared path speed, and the sets of states from
// which the rest of the path can be followed are convex polygons. Internal
// to the control library.
#include <vector>

#include "retime_path.h"

namespace modsynth::control::retime_detail {

/// Squared path speeds `x` and path accelerations `u` per sample (both 0 at
/// rests) with which the samples meet formats.md's rules for the
/// velocities qd = tangent sqrt(x) and accelerations qdd = tangent u +
/// curve x under `vmax`-derived `cap`, `amax` and the jerk rules under
/// `jmax`: |qdd_k(i+1) - qdd_k(i)| <= J_k dt and |(qd_k(i+1) - qd_k(i)) / dt
/// - (qdd_k(i) + qdd_k(i+1)) / 2| <= J_k dt / 4, with dt = 2 length /
/// (sqrt(x_i) + sqrt(x_i+1)). The step times make the jerk rules
/// nonlinear; they are taken in forms linear in (x, u) that imply them,
/// around the squared speeds `around` (any non-negative numbers: the forms
/// are tangents of concave and convex bounds, exact there and safe
/// elsewhere). Returns false when no timing moves at all (a path that
/// cannot be followed), which does not happen for finite limits.
bool jerk_timing(const Path& path, const std::vector<double>& cap, const std::vector<double>& amax,
                 const std::vector<double>& jmax, const std::vector<double>& around,
                 std::vector<double>& x, std::vector<double>& u);

}  // namespace modsynth::control::retime_detail
