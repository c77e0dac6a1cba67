#pragma once
// modsynth-solution/1 documents (formats.md).
#include <string>

#include <nlohmann/json_fwd.hpp>

#include <modsynth/synth/solution.h>

namespace modsynth::output {

nlohmann::json to_json(const synth::Solution& solution);
/// Writes the document; throws std::runtime_error naming the path on failure.
void write_solution(const synth::Solution& solution, const std::string& path);

}  // namespace modsynth::output
