#pragma once
// Inverse dynamics of the planar serial chain: recursive Newton-Euler
// (Featherstone, "Rigid Body Dynamics Algorithms", ch. 5), specialised to
// revolute joints with parallel axes, where every velocity is one angular
// rate and every moment one number.
#include <vector>

#include <modsynth/hardware/arm_model.h>

namespace modsynth::hardware {

/// The joint torques (N m) that move the arm with joint angles q, rates qd
/// and accelerations qdd (joint angles as in formats.md: q_1 from the task's
/// x-axis, q_k relative to link k - 1). Each vector has one entry per link;
/// throws std::invalid_argument otherwise.
std::vector<double> inverse_dynamics(const ArmModel& model, const std::vector<double>& q,
                                     const std::vector<double>& qd, const std::vector<double>& qdd);

}  // namespace modsynth::hardware
