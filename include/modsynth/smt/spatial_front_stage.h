#pragma once
// The spatial front stage (Z3 over nonlinear real arithmetic), for one joint
// count. Two encodings over few real variables, every constraint family
// guarded by assumption literals named after the task parts it comes from:
//
// - the relaxation: necessary conditions for ANY chain of that joint count
//   (each sampled path point within 2 n max_link_length of a base in a
//   base region; with only vertical joint axes, twists 0 and pi, the EE's
//   height fixed, so that the path's sampled points lie at one height).
//   Unsat is a proof of infeasibility, and its minimal core names the
//   conflicting parts;
// - a pattern: the conditions an arm family puts on the designs of one of
//   its skeletons (smt/pattern.h; the yaw column's annulus about its
//   shoulder, a SCARA's height), checked with the skeleton's base region.
//   Unsat there only rules the skeleton out.
//
// Neither tells the IK branches apart, so the branch of each stroke is left
// to the initial guesses, which score them.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <modsynth/geometry/vec3.h>
#include <modsynth/run/deadline.h>
#include <modsynth/smt/pattern.h>
#include <modsynth/task/part.h>
#include <modsynth/task/spatial_task.h>

namespace modsynth::smt {

struct SpatialFrontStageOptions {
    /// Seconds of Z3 time per check; nlsat decides these encodings in
    /// milliseconds on the planted tasks.
    double time_limit = 5.0;
    /// Intervals sampled along each primitive, and sampled points over the
    /// whole path, at most (fewer per primitive on long paths, never fewer
    /// than its ends). Every sampled point gives a sound condition.
    int samples_per_primitive = 8;
    int encoded_points = 400;
    /// m: the EE's height may differ from a sampled path point's by this
    /// much in the height condition: a motion that traces the path within
    /// formats.md's 1 mm and in steps of at most 5 mm passes within this of
    /// every point of it.
    double height_tolerance = 5e-3;
    /// Seconds for each check while a core is minimised: the larger of
    /// these and this factor times what the conflict took.
    double core_trial_seconds = 0.3;
    double core_trial_factor = 4.0;
    /// m (m^2 for squared atoms): every constraint is loosened by this much
    /// so that the decimal rounding of task numbers never makes the
    /// relaxation unsound.
    double slack = 1e-7;
    /// Every check's timeout ends here, and core minimisation returns the
    /// core it has.
    run::Deadline deadline;

    /// False (with `error` naming the field) when some value is out of range.
    bool IsValid(std::string* error) const;
};

class SpatialFrontStage {
public:
    enum class Result { Sat, Unsat, Unknown };

    /// Throws std::invalid_argument when the options are not valid.
    SpatialFrontStage(const task::SpatialTask& task, int dof,
                      const SpatialFrontStageOptions& options = {});
    ~SpatialFrontStage();
    SpatialFrontStage(const SpatialFrontStage&) = delete;
    SpatialFrontStage& operator=(const SpatialFrontStage&) = delete;

    /// The relaxation for any chain of this joint count: Unsat is a proof.
    Result check();
    /// After Unsat: the conflicting task parts, shrunk by deletion (a
    /// conflict, if not a minimal one, when the time runs out).
    std::vector<task::TaskPart> minimal_core();
    /// Whether these parts alone are proved to conflict.
    bool conflicts(const std::vector<task::TaskPart>& parts);
    /// The points sampled along each primitive (its ends among them), on
    /// which every condition is encoded; patterns use the same.
    const std::vector<std::vector<geometry::Vec3>>& sampled_points() const;
    /// Whether a pattern holds with the base in `base_region` (-1: any),
    /// with the values of its reported variables in a model; nothing when
    /// it does not or is undecided.
    std::optional<std::vector<double>> pattern_holds(const Pattern& pattern, int base_region);
    /// Why the last check answered Unknown.
    std::string reason_unknown() const;
    /// Both encodings as SMT-LIB2 scripts, for regression suites.
    std::string smtlib() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace modsynth::smt
