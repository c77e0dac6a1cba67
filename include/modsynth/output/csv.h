#pragma once
// The control as a CSV table for position-controlled actuators: one row per
// sample, `t,q1,...,qn,phase,primitive` (and `,stroke` when the motion has
// several strokes; phase `travel` between them), angles in radians, never
// wrapped.
#include <string>

#include <modsynth/synth/solution.h>

namespace modsynth::output {

/// The whole table, header first. A solution without samples gives the
/// header alone (with q1, q2 as the joint columns).
std::string trajectory_csv(const synth::Solution& solution);

}  // namespace modsynth::output
