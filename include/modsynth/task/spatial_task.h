#pragma once
// A spatial task (formats.md "Spatial tasks", `"space": "3d"`) as plain
// value types: 3-D primitives, sphere, capsule and box obstacles, box base
// regions and the robot spec of a Denavit-Hartenberg chain. A SpatialTask
// that exists has been validated (io::parse_spatial_task).
#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include <modsynth/geometry/obstacle3.h>
#include <modsynth/geometry/primitive3.h>
#include <modsynth/geometry/vec.h>
#include <modsynth/geometry/vec3.h>
#include <modsynth/task/part.h>
#include <modsynth/task/task.h>
#include <modsynth/task/tool_axis.h>

namespace modsynth::task {

/// What a spatial robot may be (formats.md, `robot` of a spatial task); the
/// defaults are the contract's.
struct SpatialRobotSpec {
    std::vector<int> dof{3, 4};  ///< allowed joint counts (each 3 to 6), fewest preferred
    double link_diameter = 0.03175;
    /// Every non-zero DH `a` and `|d|` of the chain lies within these.
    double min_link_length = 0.05;
    double max_link_length = 1.0;
    /// The DH twists (alpha) allowed; a chain's alpha must equal one within
    /// 1e-9 rad.
    std::vector<double> twists{0.0, geometry::kPi / 2, -geometry::kPi / 2};
    /// The last tool_length m of the chain before the EE are the tool (a pen,
    /// a nozzle), which may touch obstacles.
    double tool_length = 0.0;
    /// As in the plane (formats.md "Timing a controller accepts", "Modules
    /// and loads").
    std::optional<JointLimitsSpec> joint_limits;
    std::vector<std::string> modules;
    double payload = 0.0;                     ///< kg held at the tool
    geometry::Vec3 gravity{0.0, 0.0, -9.81};  ///< m/s^2 in the task frame
    /// The hardware sizes of the planar robot spec (docs/formats.md
    /// "Hardware sizes"), read the same way.
    double module_length = 0.110;
    double module_width = 0.073;
    double module_height = 0.045;
    double adapter_length = 0.020;
    double ee_rod_diameter = 0.0095;

    /// m: no EE of an allowed chain gets farther from its base than this:
    /// each of its links moves it by at most |d| + a <= 2 max_link_length.
    double longest_chain() const {
        return dof.empty() ? 0.0
                           : *std::max_element(dof.begin(), dof.end()) * 2.0 * max_link_length;
    }
};

struct SpatialTask {
    std::string name;
    /// Every primitive, the strokes one after another (split by
    /// stroke_starts), numbered in this list everywhere inside modsynth;
    /// task/spatial_strokes.h names them as the document does.
    std::vector<geometry::Primitive3> trajectory;
    std::vector<geometry::Obstacle3> obstacles;
    std::vector<geometry::Box3> base_regions;  ///< empty: the base may be anywhere
    SpatialRobotSpec robot;
    /// Empty: written with `trajectory`, one stroke. Otherwise (written with
    /// `strokes`) the index in `trajectory` of each stroke's first primitive.
    std::vector<int> stroke_starts;
    /// formats.md "Tool orientation": the task's own tool axis, for every
    /// primitive without one, and each primitive's as written (empty: no
    /// primitive gives one). tool_axis_of() resolves them.
    std::optional<ToolAxis> tool_axis;
    std::vector<std::optional<ToolAxis>> tool_axes;
};

/// The tool axis primitive j is traced with: its own, else the task's;
/// nullptr where the tool is free.
inline const ToolAxis* tool_axis_of(const SpatialTask& task, int j) {
    if (!task.tool_axes.empty()) {
        const auto& own = task.tool_axes[static_cast<std::size_t>(j)];
        if (own) return &*own;
    }
    return task.tool_axis ? &*task.tool_axis : nullptr;
}

/// Whether any primitive is traced with a tool axis.
inline bool holds_tool(const SpatialTask& task) {
    if (task.tool_axis) return true;
    for (const auto& a : task.tool_axes)
        if (a) return true;
    return false;
}

/// Which way the tool should point with the EE at `ee` on primitive j, and
/// how far it may be off.
struct WantedTool {
    geometry::Vec3 direction = -geometry::Vec3::UnitZ();  ///< unit
    double tolerance = kDefaultToolTolerance;
};

/// Nothing where primitive j leaves the tool free, or where `ee` lies on
/// the axis a "toward" tool points at (no direction is wanted there: the
/// verifier refuses such a pose, see has_tool_axis()).
std::optional<WantedTool> wanted_tool(const SpatialTask& task, int j, const geometry::Vec3& ee);
inline bool has_tool_axis(const SpatialTask& task, int j) {
    return tool_axis_of(task, j) != nullptr;
}

/// The part that names primitive j's tool axis: its own
/// (`trajectory[j].tool_axis`, `strokes[s][i].tool_axis`) or the task's.
TaskPart tool_axis_part(const SpatialTask& task, int j);

/// Joint counts of spatial chains (formats.md: each 3 to 6).
constexpr int kMinSpatialDof = 3;
constexpr int kMaxSpatialDof = 6;

}  // namespace modsynth::task
