#pragma once
// Numbers in the JSON documents modsynth writes.
#include <cmath>

#include <nlohmann/json.hpp>

namespace modsynth::io {

/// JSON has no infinity: an unconstrained margin is written as null.
inline nlohmann::json finite_or_null(double v) {
    return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

}  // namespace modsynth::io
