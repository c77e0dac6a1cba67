#pragma once
// The discretized baseline's results as JSON (modsynth-baseline/1 and
// modsynth-comparison/1, described in README): a robot, its waypoints, the
// measured figures. Not a solution: nothing in them is certified.
#include <nlohmann/json_fwd.hpp>

#include <modsynth/baseline/baseline.h>
#include <modsynth/baseline/comparison.h>

namespace modsynth::output {

/// The figures of a fidelity measurement (without the trail).
nlohmann::json to_json(const baseline::Fidelity& fidelity);
/// With the waypoints when `with_motion`.
nlohmann::json to_json(const baseline::BaselineResult& result, bool with_motion);
/// Both methods' figures side by side, and their ratios.
nlohmann::json to_json(const baseline::Comparison& comparison);

}  // namespace modsynth::output
