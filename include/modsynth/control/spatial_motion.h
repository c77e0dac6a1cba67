#pragma once
// The motion of an arm of any family (kinematics/arm_model.h) along a
// spatial task (formats.md "Spatial tasks"): the family's exact closed-form
// IK along every primitive on its stroke's branch, the design's free
// numbers varied linearly along each primitive and swept in a transition
// (EE held) where they change at a join, and a straight joint-space travel
// between strokes. Samples are dense enough for the
// certified verifier: no joint moves more than max_joint_step, the EE no
// more than max_ee_step along the path, and the bound on how far the EE
// strays from its chord between two samples stays under max_chord_gap.
#include <chrono>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <modsynth/control/motion.h>
#include <modsynth/kinematics/arm_model.h>
#include <modsynth/run/deadline.h>
#include <modsynth/task/spatial_task.h>

namespace modsynth::control {

struct SpatialMotionOptions {
    /// rad between consecutive samples, for every joint (formats.md: at
    /// most 0.01 rad).
    double max_joint_step = 0.01;
    /// m of path between consecutive trace samples, as in the plane
    /// (MotionOptions::max_ee_step).
    double max_ee_step = 0.002;
    /// m: the bound on how far the EE strays from its chord between two
    /// samples (kinematics::chord_gap) is kept under this. A reader measures
    /// progress by the EE's nearest path point, which may fall back by four
    /// times the certified deviation (docs/verification.md), so the
    /// deviation must stay well under a quarter of formats.md's 1 mm; at
    /// 0.1 mm the chord adds at most 0.4 mm to that.
    double max_chord_gap = 1e-4;
    /// Planning gives up past this many samples or past the deadline.
    std::size_t max_samples = 2'000'000;
    /// Tries to find a step short enough before a point counts as out of
    /// reach, as in the plane (MotionOptions::step_attempts).
    int step_attempts = 60;
    run::Deadline deadline;

    /// False (with `error` naming the field) when some value is out of range.
    bool IsValid(std::string* error) const;
};

/// The configuration of the design's arm with its EE at arc length s of
/// primitive j (index in task.trajectory), on its stroke's branch, at the
/// free numbers of that point, unwrapped next to `previous` when given;
/// std::nullopt when out of reach or near a singularity.
std::optional<std::vector<double>> spatial_configuration_at(const task::SpatialTask& task,
                                                            const kinematics::ArmDesign& design,
                                                            int j, double s,
                                                            const std::vector<double>* previous);

/// The whole motion, stroke after stroke: trace samples of every primitive
/// from its start to its end, transitions (s = the fraction of the sweep,
/// 0 to 1) where the hand pitches change at a join, travel samples between
/// strokes. Times are not set. std::nullopt (with `failure` saying where)
/// when some point is out of reach, or when planning gave up (sample cap,
/// deadline: failure->gave_up). Throws std::invalid_argument when the
/// options are not valid or the design does not fit the task.
std::optional<std::vector<Sample>> plan_spatial_motion(const task::SpatialTask& task,
                                                       const kinematics::ArmDesign& design,
                                                       const SpatialMotionOptions& options,
                                                       MotionFailure* failure = nullptr);

/// Inserts a sample midway between samples i and i + 1 for each i in
/// `pairs`: by arc length within a trace, by the sweep's fraction in a
/// transition, in joint space between strokes (which move linearly there).
/// False when a midpoint is out of reach.
bool refine_spatial_motion(const task::SpatialTask& task, const kinematics::ArmDesign& design,
                           std::vector<Sample>& samples, const std::vector<int>& pairs);

}  // namespace modsynth::control
