#pragma once
// The control as a CSV table for actuators: one row per sample,
// `t,q1,...,qn,phase,primitive`, then `qd1,...,qdn,qdd1,...,qddn` when the
// motion is timed (its samples carry velocities and accelerations), and
// `,stroke` last when the motion has several strokes (phase `travel` between
// them); angles in radians, never wrapped, rates in rad/s and rad/s^2.
#include <string>

#include <modsynth/synth/solution.h>

namespace modsynth::output {

/// The whole table, header first. A solution without samples gives the
/// header alone (with q1, q2 as the joint columns).
std::string trajectory_csv(const synth::Solution& solution);

}  // namespace modsynth::output
