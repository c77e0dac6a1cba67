#pragma once
// The obstacle-free reachable space of an arm (paper Fig. 1C/D), sampled on
// a grid: the points the distal pair of links can put the end-effector on,
// on either elbow branch, with every link clear of every obstacle and the
// end-effector clear of every link but the last.
#include <span>
#include <utility>
#include <vector>

#include <modsynth/geometry/disc.h>
#include <modsynth/geometry/vec.h>
#include <modsynth/kinematics/robot.h>

namespace modsynth::kinematics {

using geometry::Vec2;

/// The two distal links, hinged at `origin`, with the links before them
/// held still (none for a 2-joint arm; link 1 for a 3-joint arm, which
/// stays still while a primitive is traced).
struct DistalPair {
    Vec2 origin = Vec2::Zero();
    double r1 = 0.0;
    double r2 = 0.0;
    std::vector<std::pair<Vec2, Vec2>> fixed_links;
};

/// The distal pair of a robot with its leading joints at `q` (only the
/// first dof - 2 entries are used).
DistalPair distal_pair(const Robot& robot, std::span<const double> q);

/// True when some elbow branch puts the end-effector at p with all links
/// clear of the obstacles by half the diameter and the end-effector clear
/// of all links but the last by the diameter.
bool reaches_clear(const DistalPair& arm, const std::vector<geometry::Disc>& obstacles,
                   double diameter, const Vec2& p);

/// Cell centres min + (i + 1/2, j + 1/2) * cell, row-major from the bottom.
struct ReachGrid {
    Vec2 min = Vec2::Zero();
    double cell = 0.0;
    int nx = 0;
    int ny = 0;
    std::vector<unsigned char> reachable;  ///< 1 reachable, index j * nx + i

    bool at(int i, int j) const { return reachable[static_cast<std::size_t>(j * nx + i)] != 0; }
    Vec2 center(int i, int j) const { return min + cell * Vec2(i + 0.5, j + 0.5); }
    double fraction() const;
};

/// The grid over the rectangle [min, max] with square cells of side `cell`.
ReachGrid reachable_space(const DistalPair& arm, const std::vector<geometry::Disc>& obstacles,
                          double diameter, const Vec2& min, const Vec2& max, double cell);

}  // namespace modsynth::kinematics
