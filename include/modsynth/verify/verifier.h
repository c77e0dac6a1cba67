#pragma once
// Certified verification of a sampled motion: every guarantee of formats.md,
// checked at the samples and proved between them with the second-order
// bounds of notes/certified-verification.md.
#include <limits>
#include <string>
#include <vector>

#include <modsynth/control/motion.h>

namespace modsynth::verify {

struct Violation {
    enum class Kind { Structure, Deviation, Clearance, SelfCollision, JointStep, Order, ToolAxis };
    Kind kind = Kind::Structure;
    int sample = -1;  ///< first sample of the offending pair, -1 for the robot itself
    /// Primitive traced there (or left, in a transition or travel) as an
    /// index into task.trajectory, -1 if none.
    int primitive = -1;
    bool transition = false;  ///< in the transition after `primitive`
    bool travel = false;      ///< in the travel after `primitive` (to the next stroke)
    double s = 0.0;           ///< arc length along it (first joint's angle in a transition)
    int obstacle = -1;        ///< for Clearance
    int link = -1;            ///< 0-based link index, for Clearance and SelfCollision
    double amount = 0.0;      ///< how far past the limit, m or rad
    std::string message;
};

struct Certificate {
    bool ok = false;
    /// Certified lower bounds over the whole continuous motion (m): obstacle
    /// clearance beyond radius + diameter/2, EE distance to lower links beyond
    /// the diameter; +inf when nothing to check. Upper bound on EE deviation.
    double min_clearance = 0.0;
    double min_self_clearance = 0.0;
    double max_deviation = 0.0;
    double max_joint_step = 0.0;
    /// rad: certified lower bound on a tool axis's tolerance less the
    /// tool's angle from its wanted direction, over every primitive traced
    /// with one (formats.md rule 6); +inf when no primitive has one.
    double min_tool_angle_margin = std::numeric_limits<double>::infinity();
    /// Violations at the samples themselves: real counterexamples.
    std::vector<Violation> violations;
    /// Sample pairs whose bound fails only because they are far apart:
    /// refining them (control::refine_motion) may certify them.
    std::vector<int> coarse_pairs;
};

struct VerifyOptions {
    /// m: how far the EE may stray from the path anywhere along the
    /// continuous motion (formats.md guarantee 1).
    double deviation_tolerance = 1e-3;
    /// rad: the largest change of one joint between consecutive samples
    /// that formats.md allows (and certificate.max_joint_step reports).
    double max_joint_step = 0.01;
    /// m of progress along the path between consecutive trace samples
    /// (docs/verification.md): at most 5 mm keeps any two samples on an arc
    /// within half a turn of each other on arcs of radius above 1.6 mm,
    /// which the pairwise bounds assume. This is the limit a motion must
    /// meet, not the step it is planned with: the planner walks finer
    /// (MotionOptions::max_ee_step, 2 mm) to keep the bounds tight, and a
    /// motion planned coarser is checked against its own step (options_for).
    /// On arcs of a smaller radius a step of half a turn or more is refused
    /// whatever this limit (the planner takes at most a quarter turn).
    double max_ee_step = 0.005;

    /// False (with `error` naming the field) when some value is out of range.
    bool IsValid(std::string* error) const;
};

/// The limits a motion planned with `motion` is certified against: the
/// same joint step, and the EE progress limit widened to the planning step
/// when that is coarser (synth plans long paths coarser, see
/// SynthesisOptions::trace_samples).
VerifyOptions options_for(const control::MotionOptions& motion, const VerifyOptions& base = {});

/// Throws std::invalid_argument when the options are not valid.
Certificate certify(const task::Task& task, const kinematics::Robot& robot,
                    const std::vector<control::Sample>& samples, const VerifyOptions& options = {});

}  // namespace modsynth::verify
