#include <modsynth/output/recertify.h>

#include <modsynth/control/joint_limits.h>
#include <modsynth/control/motion.h>
#include <modsynth/control/path_corners.h>
#include <modsynth/control/retime.h>
#include <modsynth/control/spatial_samples.h>
#include <modsynth/synth/synthesizer.h>
#include <modsynth/verify/spatial_verifier.h>

namespace modsynth::output {

std::string recertify(const task::Task& task, io::ParsedSolution& parsed) {
    io::check_solution_fits(task, parsed.solution);
    synth::Solution& s = parsed.solution;
    if (s.status != synth::Status::Solved) return "";
    // The file does not store the progress along each primitive; the
    // verifier needs it, and it follows from the joint angles.
    control::recover_parameters(task, s.robot, s.samples);
    // With the limits the search certified it against: a long path is
    // planned with steps coarser than the verifier's default.
    s.certificate = verify::certify(task, s.robot, s.samples, synth::verify_options_for(task));
    // The task's per-joint limits must fit the robot (an InputError naming
    // robot.joint_limits otherwise). A motion saved without velocities is
    // timed for the controller outputs as solve would; its path is kept.
    const control::JointLimits limits = control::joint_limits_for(task, s.robot.dof());
    if (s.samples.front().qd.empty() || s.samples.front().qdd.empty())
        s.samples = control::retime_for(task, std::move(s.samples), limits);
    // Figures recomputed from an unchanged motion are the stored ones, so
    // the report of a saved solution matches the one solve wrote.
    return parsed.has_certificate ? ""
                                  : "computed by export: the solution file carries no certificate";
}

std::string recertify(const task::SpatialTask& task, io::ParsedSolution& parsed) {
    io::check_solution_fits(task, parsed.solution);
    synth::Solution& s = parsed.solution;
    if (s.status != synth::Status::Solved) return "";
    control::recover_parameters(task, *s.dh_robot, s.samples);
    s.certificate = verify::certify(task, *s.dh_robot, s.samples);
    return parsed.has_certificate ? ""
                                  : "computed by export: the solution file carries no certificate";
}

std::string uncertified_reason(const verify::Certificate& c) {
    if (c.ok) return "";
    if (c.violations.empty()) {
        const int i = c.coarse_pairs.front();
        return "samples[" + std::to_string(i) + "] and samples[" + std::to_string(i + 1) +
               "] are too far apart to bound the motion between them" +
               (c.coarse_pairs.size() > 1
                    ? " (and " + std::to_string(c.coarse_pairs.size() - 1) + " more pairs)"
                    : std::string());
    }
    const verify::Violation& v = c.violations.front();
    std::string out =
        v.sample >= 0 ? "samples[" + std::to_string(v.sample) + "]: " + v.message : v.message;
    if (c.violations.size() > 1)
        out += " (and " + std::to_string(c.violations.size() - 1) + " more)";
    return out;
}

}  // namespace modsynth::output
