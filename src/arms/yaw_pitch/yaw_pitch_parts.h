#pragma once
// What the yaw-pitch family shares with the families built on it (a wrist
// on a yaw-pitch arm): the front stage's reach conditions and the drawing
// of a column and links, for a chain whose last `dof - 3` links are a hand.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <random>
#include <vector>

#include <modsynth/arms/family.h>
#include <modsynth/kinematics/yaw_pitch_ik.h>
#include <modsynth/kinematics/yaw_pitch_pose.h>

namespace modsynth::arms {

namespace yaw_pitch {

/// The IK branches (shoulder, elbow), numbered as ArmDesign::branches.
inline constexpr kinematics::IkBranch kBranches[] = {{1, 1}, {1, -1}, {-1, 1}, {-1, -1}};

/// Variants: bits 0-1 the column (0 up, 1 hanging, 2 none), bit 2 the
/// column's twist -pi/2.
inline int column_of(int variant) {
    const int c = variant & 3;
    return c == 0 ? 1 : c == 1 ? -1 : 0;
}
inline int twist_of(int variant) { return (variant & 4) ? -1 : 1; }
inline bool has_column(int variant) { return column_of(variant) != 0; }

/// Whether robot.twists holds `angle`.
inline bool allows(const std::vector<double>& twists, double angle) {
    return std::any_of(twists.begin(), twists.end(),
                       [&](double a) { return std::abs(a - angle) <= 1e-9; });
}

/// The design's column and its first `links` links (every one when -1),
/// values [d_1 with a column], a_2, ...
template <class T>
kinematics::YawPitchShape<T> shape_of(const kinematics::ArmShape<T>& s, int links = -1) {
    kinematics::YawPitchShape<T> y;
    y.base = s.base;
    const std::size_t first = has_column(s.variant) ? 1 : 0;
    y.column = first ? s.values[0] : T(0.0);
    const auto begin = s.values.begin() + static_cast<std::ptrdiff_t>(first);
    y.links.assign(begin, links < 0 ? s.values.end() : begin + links);
    y.column_twist = twist_of(s.variant);
    return y;
}

inline kinematics::YawPitchArm arm_of(const kinematics::ArmShape<double>& s, int links = -1) {
    const auto y = shape_of(s, links);
    kinematics::YawPitchArm arm;
    arm.base = y.base;
    arm.column = y.column;
    arm.column_twist = y.column_twist;
    arm.links = y.links;
    return arm;
}

}  // namespace yaw_pitch

/// The wrist's annulus about the shoulder at every sampled point, the
/// links' bounds and the path off the column's axis (c.dof - 3 hand links
/// of total length "hand").
smt::Pattern yaw_pitch_reach(const PatternContext& c);
/// A column and c.dof - 1 links, drawn for the path's reach.
std::optional<kinematics::ArmShape<double>> yaw_pitch_draw(const DrawContext& c, std::mt19937& rng,
                                                           int candidate);
const Family& yaw_pitch_family();

}  // namespace modsynth::arms
