#pragma once
// modsynth as a library: the calls a program that embeds it makes, and the
// value types they take and give. This header and the ones it includes are
// the public API (what `cmake --install` installs, and all that
// tests/embed/example.cpp may use); the other headers under
// include/modsynth/ are the stages' interfaces to each other and may change
// without notice.
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <modsynth/synth/explanation.h>
#include <modsynth/synth/solution.h>
#include <modsynth/task/input_error.h>
#include <modsynth/task/spatial_task.h>
#include <modsynth/task/task.h>

namespace modsynth {

using synth::Solution;
using synth::Status;
using task::InputError;
using task::SpatialTask;
using task::Task;
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
    /// Called with one line per stage reached ("[  0.012s] 2 joints: front
    /// stage"); leave empty for silence.
    std::function<void(const std::string&)> progress;
};

/// A certified robot and its timed motion, a proof that none exists, or
/// "unknown" with the stage reached and why. Throws std::invalid_argument
/// naming the field when the options are not valid.
Solution solve(const Task& task, const SolveOptions& options = {});

struct Explanation {
    /// Infeasible when proved so; otherwise what a full synthesis found.
    Status status;
    /// A sentence a person can act on.
    std::string message;
    /// The task parts that conflict, named as in formats.md.
    std::vector<std::string> core;
    /// The data of an obstacle proof (formats.md, "explanation.separation",
    /// ".geodesic"), when the task was proved infeasible that way.
    std::optional<synth::SeparationWitness> separation;
    std::optional<synth::GeodesicWitness> geodesic;
    /// When proved infeasible: the smallest changes of one part each that
    /// remove the conflict, each re-checked with the full pipeline.
    std::vector<synth::Relaxation> suggestions;
};

/// Why a task cannot be done, within `time_limit` seconds in all;
/// `solve_seconds` of synthesis go to each suggested change.
Explanation explain(const Task& task, double time_limit = 60.0, double solve_seconds = 10.0);

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
