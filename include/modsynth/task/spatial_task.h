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
#include <modsynth/task/task.h>

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
};

/// Joint counts of spatial chains (formats.md: each 3 to 6).
constexpr int kMinSpatialDof = 3;
constexpr int kMaxSpatialDof = 6;

}  // namespace modsynth::task
