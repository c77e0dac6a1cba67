#pragma once
// A certified lower bound on the clearance of every pose an arm passes
// through while its joints move linearly from one configuration to another:
// the bound verify::certify proves between two samples
// (docs/verification.md), for planners that must produce motions it accepts.
#include <span>
#include <vector>

#include <modsynth/geometry/disc.h>
#include <modsynth/kinematics/pose_clearance.h>
#include <modsynth/kinematics/robot.h>

namespace modsynth::kinematics {

/// E_k = sum_{i<=k} r_i (dphi_i)^2 for k = 0..n-1, dphi the change of each
/// link's absolute angle: while the joints move linearly from one pose to
/// the other, every point of link k stays within E_k / 8 of the hull of the
/// link's two end positions (docs/verification.md).
std::vector<double> sweep_bounds(const Robot& robot, std::span<const double> phi_a,
                                 std::span<const double> phi_b);

/// Lower bounds (m beyond the clearance rule) over the joint-space segment
/// from qa to qb: each link stays within the hull of its end poses widened
/// by E_k / 8, E_k = sum_{i<=k} r_i (dphi_i)^2. The bound tends to the pose
/// clearance as the segment shrinks.
PoseClearance linear_motion_clearance(std::span<const geometry::Disc> obstacles, const Robot& robot,
                                      std::span<const double> qa, std::span<const double> qb);

}  // namespace modsynth::kinematics
