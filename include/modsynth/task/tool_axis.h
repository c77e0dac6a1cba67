#pragma once
// Which way the tool points while it traces a primitive (formats.md "Tool
// orientation"): along a fixed direction, or square at (or away from) the
// axis of an arc, circle or helix, within a tolerance. The tool is
// symmetric about its axis: its spin is free.
#include <optional>
#include <vector>

#include <modsynth/geometry/primitive3.h>
#include <modsynth/geometry/vec3.h>

namespace modsynth::task {

/// rad: formats.md's default tolerance, 5 degrees.
inline constexpr double kDefaultToolTolerance = 0.08726646259971647;
/// m: the least radius of a turn whose axis a tool may point at.
inline constexpr double kLeastTowardRadius = 0.005;

struct ToolAxis {
    enum class Kind { Direction, TowardAxis, AwayFromAxis };
    Kind kind = Kind::Direction;
    /// Direction only: as the task gives it (any length), so that the task
    /// is written back as read; unit() normalises it.
    geometry::Vec3 direction = -geometry::Vec3::UnitZ();
    double tolerance = kDefaultToolTolerance;  ///< rad, in (0, pi/2]
    bool tolerance_given = false;              ///< written back only when given
};

/// The wanted unit direction of the tool with its EE at `ee` on primitive
/// `p`: the fixed direction, or -w/|w| (toward the axis) or w/|w| (away),
/// w the part of ee - center perpendicular to the axis. Nothing on the axis
/// itself, where a turn's direction is undefined.
std::optional<geometry::Vec3> wanted_tool_axis(const ToolAxis& axis, const geometry::Primitive3& p,
                                               const geometry::Vec3& ee);

/// The axis line of an arc, circle or helix (a point on it and its unit
/// direction); nothing for a line.
std::optional<std::pair<geometry::Vec3, geometry::Vec3>> turn_axis(const geometry::Primitive3& p);

}  // namespace modsynth::task
