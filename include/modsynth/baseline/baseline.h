#pragma once
// The paper's discretized baseline end to end (IV-B): design from N
// equidistant points, RRT between the poses, and the fidelity of what the
// robot would then do, timed stage by stage.
#include <string>
#include <vector>

#include <modsynth/baseline/discretized_design.h>
#include <modsynth/baseline/fidelity.h>
#include <modsynth/baseline/rrt_motion.h>
#include <modsynth/run/progress.h>
#include <modsynth/task/task.h>

namespace modsynth::baseline {

struct BaselineOptions {
    /// Equidistant points of the path the design sees (the paper's N):
    /// 25 is the paper's comparison setting.
    int points = 25;
    double time_limit = 120.0;  ///< seconds, wall clock, design and planning together
    /// Share of time_limit the design may use at most: a design that used
    /// the whole budget would leave RRT nothing.
    double design_share = 0.8;
    DesignOptions design;
    PlannerOptions planner;
    FidelityOptions fidelity;
    /// Told of every step (may be empty).
    run::ProgressSink progress;

    /// False (with `error` naming the field) when some value is out of range.
    bool IsValid(std::string* error) const;
};

struct BaselineResult {
    enum class Status {
        Executed,  ///< a design and a complete motion through all the points
        NoDesign,  ///< no robot reaches all the points
        NoMotion,  ///< RRT could not connect some pair of points
    };
    Status status = Status::NoDesign;
    std::vector<PathSample> points;
    PointDesign design;
    PlannedMotion motion;
    /// With a design: measured over the motion as far as it was planned.
    Fidelity fidelity;
    double design_seconds = 0.0;
    double planning_seconds = 0.0;
    double seconds = 0.0;  ///< design + planning (not the measurement)
    std::string message;   ///< why, when not executed
};

const char* to_string(BaselineResult::Status status);

/// Throws std::invalid_argument when the options are not valid (fewer than
/// 2 points among them).
BaselineResult run_baseline(const task::Task& task, const BaselineOptions& options);

}  // namespace modsynth::baseline
