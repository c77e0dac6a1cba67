#pragma once
// What a run tells while it works: one event per step, with the pipeline
// stage it belongs to, a sentence, and the seconds since the run started.
// The console prints it as a line, the server forwards it as JSON
// (io/progress_json.h); nobody reads the line back.
#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace modsynth::run {

enum class Stage {
    Proofs,        ///< reach, wall, detour and branch-and-bound proofs
    FrontStage,    ///< the Z3 relaxation of a joint count
    Search,        ///< skeletons and their initial guesses
    Refinement,    ///< an Ipopt refinement round
    Verification,  ///< motion planning and certification of a candidate
    Shortening,    ///< the search for a shorter robot after the first
    Timing,        ///< retiming the certified motion for a controller
    Modules,       ///< choosing the actuator modules
    Explanation,   ///< explaining an infeasible task, suggesting changes
    Baseline,      ///< the discretized method modsynth is compared with
};

/// "front stage", "refinement", ...: how documents and the console name it.
const char* to_string(Stage stage);
/// The stage named by to_string, or nothing.
std::optional<Stage> stage_from_string(std::string_view name);

struct ProgressEvent {
    Stage stage = Stage::Search;
    std::string message;   ///< e.g. "2 joints: skeleton 1 (elbow -1, base region 0)"
    double elapsed = 0.0;  ///< seconds since the run started
};

/// Where a run sends its events; may be empty (silence).
using ProgressSink = std::function<void(const ProgressEvent&)>;

/// As the console prints it: "[  0.123s] 2 joints: front stage".
std::string console_line(const ProgressEvent& event);

}  // namespace modsynth::run
