#pragma once
// modsynth as a library: the calls a program that embeds it makes, and the
// value types they take and give. This header and the ones it includes are
// the public API (what `cmake --install` installs, and all that
// tests/embed/example.cpp may use); the other headers under
// include/modsynth/ are the stages' interfaces to each other and may change
// without notice.
#include <string>
#include <string_view>

#include <modsynth/explanation/explain.h>
#include <modsynth/run/cancel.h>
#include <modsynth/run/progress.h>
#include <modsynth/synth/solution.h>
#include <modsynth/task/input_error.h>
#include <modsynth/task/part.h>
#include <modsynth/task/spatial_task.h>
#include <modsynth/task/task.h>

namespace modsynth {

using explanation::Explanation;
using run::CancelToken;
using run::ProgressEvent;
using run::ProgressSink;
using synth::Solution;
using synth::Status;
using task::InputError;
using task::SpatialTask;
using task::Task;
using task::TaskPart;
using verify::Certificate;

/// A modsynth-task/1 document (docs/formats.md), validated. Throws
/// InputError naming the offending part (`part()`) on anything invalid.
Task read_task(std::string_view json_text);
/// The same from a file; an unreadable file is an InputError too.
Task load_task(const std::string& path);

/// Whether a task document (JSON text) is a spatial task, `"space": "3d"`
/// (docs/formats.md "Spatial tasks"), which read_task refuses by name.
/// Throws InputError when the text is not JSON.
bool is_spatial_task(std::string_view json_text);
/// A spatial task document, validated; InputError naming the offending part.
SpatialTask read_spatial_task(std::string_view json_text);
SpatialTask load_spatial_task(const std::string& path);

struct SolveOptions {
    double time_limit = 60.0;  ///< seconds for the whole synthesis; > 0
    unsigned seed = 0;         ///< varies initial guesses; same seed, same answer
    /// Told of every step (stage, sentence, seconds since the start;
    /// run::console_line prints it as `modsynth solve` does); leave empty
    /// for silence.
    ProgressSink progress;
    /// Keep a copy and call cancel() on it (from any thread) to end the
    /// solve early; it then answers as at its time limit, "unknown" unless
    /// a robot is already certified.
    run::CancelToken cancel;
};

/// A certified robot and its timed motion (with the actuator modules that
/// carry it), a proof that none exists, or "unknown" with the stage reached
/// and why: the same answer as `modsynth solve`. Throws InputError when the
/// task names a module the catalog lacks, and std::invalid_argument naming
/// the field when the options are not valid.
Solution solve(const Task& task, const SolveOptions& options = {});
/// The same for a spatial task: a certified DH chain (Solution::dh_robot)
/// and its timed motion with its modules, a proof that none exists, or
/// "unknown"; the same answer as `modsynth solve` on that task.
Solution solve(const SpatialTask& task, const SolveOptions& options = {});

/// Why a task cannot be done, within `time_limit` seconds in all;
/// `solve_seconds` of synthesis go to each suggested change. The same flow
/// as `modsynth explain`.
Explanation explain(const Task& task, double time_limit = 60.0, double solve_seconds = 10.0);
/// The same for a spatial task: the spatial reach proof or the front
/// stage's core as task parts, else the spatial synthesis, else the
/// changes (links, joints, twists, base regions) that remove the conflict.
Explanation explain(const SpatialTask& task, double time_limit = 60.0, double solve_seconds = 10.0);

/// Checks a solution's motion against the task over the whole continuum,
/// independently of how it was made (docs/verification.md). A solution
/// that is not "solved" gets a certificate that is not ok.
Certificate certify(const Task& task, const Solution& solution);
/// The same for a spatial task, whose solution carries a DH robot
/// (Solution::dh_robot; an InputError when it does not).
Certificate certify(const SpatialTask& task, const Solution& solution);

/// A solution as a modsynth-solution/1 document, and back (the reader
/// throws InputError naming the part).
std::string write_solution_json(const Solution& solution);
Solution read_solution(std::string_view json_text);

}  // namespace modsynth
