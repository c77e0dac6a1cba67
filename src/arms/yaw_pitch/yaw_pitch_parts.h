#pragma once
// What the yaw-pitch family shares with the families built on it (a wrist
// on a yaw-pitch arm): the front stage's reach conditions and the drawing
// of a column and links, for a chain whose last `dof - 3` links are a hand.
#include <optional>
#include <random>

#include <modsynth/arms/family.h>

namespace modsynth::arms {

/// The wrist's annulus about the shoulder at every sampled point, the
/// links' bounds and the path off the column's axis (c.dof - 3 hand links
/// of total length "hand").
smt::Pattern yaw_pitch_reach(const PatternContext& c);
/// A column and c.dof - 1 links, drawn for the path's reach.
std::optional<kinematics::ArmShape<double>> yaw_pitch_draw(const DrawContext& c, std::mt19937& rng,
                                                           int candidate);
const Family& yaw_pitch_family();

}  // namespace modsynth::arms
