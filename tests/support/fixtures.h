#pragma once
// Shared test fixtures: paths into the source tree and small hand-made tasks.
#include <string>

#include <nlohmann/json.hpp>

#include <modsynth/kinematics/robot.h>
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

/// A 2-joint arm at the origin (0.30 m and 0.25 m links, elbow +1) that
/// reaches line_task's path.
inline kinematics::Robot line_robot() {
    kinematics::Robot r;
    r.base = {0.0, 0.0};
    r.link_lengths = {0.30, 0.25};
    r.link_diameter = 0.03175;
    r.elbow = 1;
    return r;
}

nlohmann::json read_json(const std::string& path);

}  // namespace modsynth::testing
