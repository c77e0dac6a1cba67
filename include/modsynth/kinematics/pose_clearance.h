#pragma once
// How clear one pose of an arm is, by the clearance rule (clearance_rule.h).
#include <algorithm>
#include <limits>
#include <span>

#include <modsynth/geometry/disc.h>
#include <modsynth/kinematics/robot.h>

namespace modsynth::kinematics {

struct PoseClearance {
    /// m beyond the limit; +inf when there is nothing to keep clear of.
    double obstacles = std::numeric_limits<double>::infinity();
    double self = std::numeric_limits<double>::infinity();
    double worst() const { return std::min(obstacles, self); }
};

PoseClearance pose_clearance(std::span<const geometry::Disc> obstacles, const Robot& robot,
                             std::span<const double> q);

}  // namespace modsynth::kinematics
