#pragma once
// Certified verification of a sampled motion: every guarantee of formats.md,
// checked at the samples and proved between them with the second-order
// bounds of notes/certified-verification.md.
#include <string>
#include <vector>

#include <modsynth/control/motion.h>

namespace modsynth::verify {

struct Violation {
    enum class Kind { Structure, Deviation, Clearance, SelfCollision, JointStep, Order };
    Kind kind = Kind::Structure;
    int sample = -1;     ///< first sample of the offending pair, -1 for the robot itself
    int primitive = -1;  ///< primitive traced there (or left, in a transition), -1 if none
    bool transition = false;  ///< in the transition after `primitive`
    double s = 0.0;      ///< arc length along it (first joint's angle in a transition)
    int obstacle = -1;   ///< for Clearance
    int link = -1;       ///< 0-based link index, for Clearance and SelfCollision
    double amount = 0.0; ///< how far past the limit, m or rad
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
    /// Violations at the samples themselves: real counterexamples.
    std::vector<Violation> violations;
    /// Sample pairs whose bound fails only because they are far apart:
    /// refining them (control::refine_motion) may certify them.
    std::vector<int> coarse_pairs;
};

struct VerifyOptions {
    double deviation_tolerance = 1e-3;  ///< m, formats.md guarantee 1
    double max_joint_step = 0.01;       ///< rad
    double max_ee_step = 0.005;         ///< m of progress between trace samples
};

Certificate certify(const task::Task& task, const kinematics::Robot& robot,
                    const std::vector<control::Sample>& samples,
                    const VerifyOptions& options = {});

}  // namespace modsynth::verify
