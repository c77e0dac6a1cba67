#pragma once
// How clear one pose of an arm is, by the rules of formats.md guarantees 3
// and 4: every link keeps radius + diameter/2 from every obstacle centre,
// and the end-effector keeps a diameter from every link but the last.
#include <algorithm>
#include <limits>
#include <span>

#include <modsynth/kinematics/robot.h>
#include <modsynth/task/task.h>

namespace modsynth::kinematics {

struct PoseClearance {
    /// m beyond the limit; +inf when there is nothing to keep clear of.
    double obstacles = std::numeric_limits<double>::infinity();
    double self = std::numeric_limits<double>::infinity();
    double worst() const { return std::min(obstacles, self); }
};

PoseClearance pose_clearance(const task::Task& task, const Robot& robot, std::span<const double> q);

}  // namespace modsynth::kinematics
