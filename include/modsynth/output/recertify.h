#pragma once
// A solution read back from a file is verified again before anything is
// derived from it. Its samples may have been edited since its certificate
// was computed, so a stored certificate proves nothing: only the verifier's
// verdict on the motion as it now stands may be called certified.
#include <string>

#include <modsynth/io/solution_io.h>
#include <modsynth/task/spatial_task.h>
#include <modsynth/task/task.h>
#include <modsynth/verify/verifier.h>

namespace modsynth::output {

/// Checks that the solution fits the task (check_solution_fits, which
/// throws InputError) and, for a solved one, replaces its certificate with
/// the verifier's; a motion without velocities and accelerations is timed
/// (control::retime) with the task's joint limits, its q unchanged. Throws
/// InputError naming robot.joint_limits when the task's per-joint limits do
/// not fit the robot's joint count. Returns the report's "Certificate source" note: set when
/// the file carried no certificate to compare with, else "".
std::string recertify(const task::Task& task, io::ParsedSolution& parsed);
/// The same for a spatial task: the fit checked, the samples' progress
/// recovered from their joint angles (control::recover_parameters) and the
/// motion certified against the contract's limits (verify::VerifyOptions);
/// the samples are not retimed.
std::string recertify(const task::SpatialTask& task, io::ParsedSolution& parsed);

/// Why a certificate is not ok, in one line naming the first offending
/// sample ("samples[3]: EE is 0.052000 m off the path (and 4 more)"), or
/// "" when it is ok.
std::string uncertified_reason(const verify::Certificate& certificate);

}  // namespace modsynth::output
