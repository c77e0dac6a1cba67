#pragma once
// The task a user asks modsynth to solve (formats.md, modsynth-task/1), as
// plain value types. A Task that exists has been validated.
#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include <modsynth/geometry/disc.h>
#include <modsynth/geometry/primitive.h>

namespace modsynth::task {

using geometry::Primitive;
using geometry::Vec2;

using Obstacle = geometry::Disc;

/// Axis-aligned rectangle where the base may stand.
struct BaseRegion {
    Vec2 min = Vec2::Zero();
    Vec2 max = Vec2::Zero();
    bool contains(const Vec2& p, double tolerance = 0.0) const {
        return p.x() >= min.x() - tolerance && p.x() <= max.x() + tolerance &&
               p.y() >= min.y() - tolerance && p.y() <= max.y() + tolerance;
    }
};

/// The range of every joint limit (formats.md: each from 1e-6 to 1e6, in
/// rad/s, rad/s^2 or rad/s^3), and of a speed cap given beside them
/// (`solve --joint-speed`, `--ee-speed`): past it no motion is worth timing
/// (a motion at 1e-9 rad/s lasts for centuries) and its numbers stop being
/// ones a controller or a file can hold.
inline constexpr double kMinJointLimit = 1e-6;
inline constexpr double kMaxJointLimit = 1e6;

/// Joint speed, acceleration and (optionally) jerk limits a controller must
/// respect (formats.md `robot.joint_limits`), in rad/s, rad/s^2 and
/// rad/s^3. Each list holds
/// one value for every joint, or one value per joint (then its length is
/// the only joint count the task allows).
struct JointLimitsSpec {
    std::vector<double> velocity;
    std::vector<double> acceleration;
    /// rad/s^3, optional (formats.md `robot.joint_limits.jerk`): empty for
    /// no jerk limit.
    std::vector<double> jerk{};
};

/// Defaults are those of formats.md.
struct RobotSpec {
    std::vector<int> dof{2, 3};  ///< allowed joint counts, fewest preferred
    double link_diameter = 0.03175;
    double min_link_length = 0.05;
    double max_link_length = 1.0;
    /// m: the farthest any allowed arm reaches from its base, its most
    /// joints times max_link_length (0 when no joint count is allowed).
    double longest_arm() const {
        return dof.empty() ? 0.0 : *std::max_element(dof.begin(), dof.end()) * max_link_length;
    }
    /// The hardware the arm is built from (optional keys, used by the build
    /// sheet and the URDF only): actuator modules as boxes with the joint
    /// axis at the centre of the output end, module_width / 2 from that end;
    /// defaults are a HEBI X8 (110 x 73 x 45 mm, the height along the axis).
    double module_length = 0.110;
    double module_width = 0.073;
    double module_height = 0.045;
    /// How far a tube adapter reaches beyond the module's outline before the
    /// tube begins, at each end of a tube.
    double adapter_length = 0.020;
    /// The rod that carries the end-effector down to the task plane.
    double ee_rod_diameter = 0.0095;
    /// What the modules must carry (optional keys, formats.md "Modules and
    /// loads"; they do not change the geometry the synthesis finds).
    /// Actuators the arm may be built from, by catalog name; empty: every
    /// actuator of the catalog.
    std::vector<std::string> modules;
    double payload = 0.0;  ///< kg held at the tool (the end-effector)
    /// Gravity in the task plane (m/s^2, task frame) when the plane stands
    /// upright; none when the plane is horizontal and gravity runs along the
    /// joint axes, where it loads no joint (the bearings carry it) and the
    /// torques are inertial only.
    std::optional<Vec2> gravity;
    /// Absent: the motion is timed with the modules' limits
    /// (control::default_joint_limits()).
    std::optional<JointLimitsSpec> joint_limits;
};

struct Task {
    std::string name;
    /// Every primitive to trace, in order: with several strokes (formats.md
    /// "Several strokes") the strokes one after another, split by
    /// stroke_starts. Primitives are numbered in this list everywhere inside
    /// modsynth; task/strokes.h names them as the document does.
    std::vector<Primitive> trajectory;
    std::vector<Obstacle> obstacles;
    std::vector<BaseRegion> base_regions;  ///< empty: the base may be anywhere
    RobotSpec robot;
    /// Last, so that code building a Task member by member is unchanged.
    /// Empty: the task was written with `trajectory`, one stroke. Otherwise
    /// (written with `strokes`) the index in `trajectory` of each stroke's
    /// first primitive, starting with 0 and increasing.
    std::vector<int> stroke_starts;
};

/// The base-region choices of a search: each index into base_regions, or
/// just -1 (unconstrained) when the task has none.
inline std::vector<int> base_region_choices(const Task& task) {
    std::vector<int> out;
    for (int i = 0; i < static_cast<int>(task.base_regions.size()); ++i) out.push_back(i);
    if (out.empty()) out.push_back(-1);
    return out;
}

/// Joint counts modsynth can synthesise.
constexpr int kMinDof = 2;
constexpr int kMaxDof = 3;

}  // namespace modsynth::task
