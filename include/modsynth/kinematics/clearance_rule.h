#pragma once
// The clearance rule of formats.md guarantees 3 and 4, defined once for every
// stage: links are tubes of the robot's diameter around the segments between
// joint axes, so a link's centre line keeps an obstacle's radius plus half a
// diameter from its centre, and the end-effector's axis keeps a whole
// diameter from the centre line of every link but the last. The stages
// differ in how they enforce it (Z3 relaxation, Ipopt constraints, sampled
// search, certified bounds), never in what it is.
#include <modsynth/geometry/disc.h>
#include <modsynth/geometry/vec.h>

namespace modsynth::kinematics {

struct ClearanceRule {
    double link_diameter = 0.0;

    /// Least distance from a link's centre line to the obstacle's centre.
    double obstacle_distance(const geometry::Disc& obstacle) const {
        return obstacle.radius + link_diameter / 2.0;
    }
    /// Least distance from the end-effector to a lower link's centre line.
    double self_distance() const { return link_diameter; }

    /// How far the link from a to b is beyond the rule (negative: it touches).
    double link_margin(const geometry::Disc& obstacle, const geometry::Vec2& a,
                       const geometry::Vec2& b) const;
    /// How far the end-effector is beyond the rule for the lower link a-b.
    double self_margin(const geometry::Vec2& ee, const geometry::Vec2& a,
                       const geometry::Vec2& b) const;
};

}  // namespace modsynth::kinematics
