#pragma once
// Shared test fixtures: paths into the source tree and small hand-made tasks.
#include <string>

#include <nlohmann/json.hpp>

#include <modsynth/task/task.h>

namespace modsynth::testing {

inline std::string source_path(const std::string& relative) {
    return std::string(MODSYNTH_SOURCE_DIR) + "/" + relative;
}

/// A vertical line in front of an arm based near the origin, with optional
/// obstacles: small enough to reason about by hand.
inline task::Task line_task() {
    task::Task t;
    t.name = "line";
    t.trajectory.push_back(geometry::make_line({0.40, 0.05}, {0.40, 0.30}));
    t.base_regions.push_back({{-0.05, -0.05}, {0.05, 0.05}});
    t.robot.dof = {2};
    return t;
}

nlohmann::json read_json(const std::string& path);

}  // namespace modsynth::testing
