#pragma once
// The travel between two strokes (formats.md "Several strokes"): a pen-up
// motion in joint space from the pose that ends one stroke to the pose that
// starts the next, with the EE free but every link clear of the obstacles and
// the EE clear of the lower links all the way (the bound of
// kinematics/motion_clearance.h, which the verifier also proves). OMPL stays
// out of this interface.
#include <optional>
#include <string>
#include <vector>

#include <modsynth/kinematics/robot.h>
#include <modsynth/run/deadline.h>
#include <modsynth/task/task.h>

namespace modsynth::control {

struct TravelOptions {
    /// rad: the largest change of one joint between consecutive poses.
    double max_joint_step = 0.01;
    /// m of clearance the planner's waypoints keep beyond the rule, so that
    /// the certified bound holds between its densified poses.
    double spare = 1e-3;
    /// s the sampling planner (RRT-Connect) may take when no straight line
    /// is clear; it also stops at the deadline.
    double plan_seconds = 2.0;
    /// Times a pair of consecutive poses may be halved until the certified
    /// bound holds between them.
    int max_halvings = 8;
    run::Deadline deadline;

    /// False (with `error` naming the field) when some value is out of range.
    bool IsValid(std::string* error) const;
};

struct TravelPlan {
    /// The poses after `from`, the last one `to` with each joint possibly
    /// shifted by a multiple of 2 pi (the same pose, reached the other way
    /// round). Consecutive poses differ by at most max_joint_step.
    std::vector<std::vector<double>> poses;
    /// "straight" or "planned": how the path was found.
    std::string method;
};

/// Tries the straight joint-space line to `to` and to each other unwrapping
/// of its joints (+-2 pi), shortest first, then an RRT-Connect search;
/// std::nullopt when neither finds a certified motion in time. Throws
/// std::invalid_argument when the options are not valid.
std::optional<TravelPlan> plan_travel(const task::Task& task, const kinematics::Robot& robot,
                                      const std::vector<double>& from,
                                      const std::vector<double>& to, const TravelOptions& options);

}  // namespace modsynth::control
