#pragma once
// Why a task cannot be done, in one flow for the command line, the server
// (which runs the command) and the library: prove it infeasible, else say
// what a full run finds; when proved, look for the smallest changes that
// remove the conflict.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <modsynth/explanation/explanation.h>
#include <modsynth/prove/wall_witness.h>
#include <modsynth/run/progress.h>
#include <modsynth/synth/status.h>
#include <modsynth/task/part.h>
#include <modsynth/task/spatial_task.h>
#include <modsynth/task/task.h>

namespace modsynth::explanation {

struct Explanation {
    /// Proved infeasible by the proofs alone (and then the suggestions were
    /// looked for); otherwise `status` is what a full synthesis found.
    bool proved = false;
    /// Infeasible when proved so; otherwise what a full synthesis found.
    synth::Status status;
    /// A sentence a person can act on.
    std::string message;
    /// The task parts that conflict.
    std::vector<task::TaskPart> core;
    /// The data of an obstacle proof (formats.md, "explanation.separation",
    /// ".geodesic"), when the task was proved infeasible that way.
    std::optional<prove::SeparationWitness> separation;
    std::optional<prove::GeodesicWitness> geodesic;
    /// A spatial task's closed shell ("explanation.enclosure").
    std::optional<prove::EnclosureWitness> enclosure;
    /// When proved infeasible: the smallest changes of one part each that
    /// remove the conflict, each re-checked with the full pipeline.
    std::vector<Relaxation> suggestions;
};

struct ExplainOptions {
    /// Seconds for the whole flow: the proof, or the full run when there is
    /// none, then the suggestions.
    double time_limit = 60.0;
    /// Seconds of full synthesis tried on each suggested change.
    double solve_seconds = 10.0;
    /// Seconds the proof gets at most: a proof of infeasibility is fast
    /// when it exists (unsat answers of the relaxation stay fast), and the
    /// rest of the time goes to the full run or the suggestions.
    double proof_seconds = 10.0;
    /// Told when the flow moves on: "proving infeasibility", "solving the
    /// task", "looking for the smallest changes".
    run::ProgressSink progress;
    /// Called once the task is proved infeasible, with everything but the
    /// suggestions, before they are looked for (which takes most of the
    /// time).
    std::function<void(const Explanation&)> proved;

    /// False (with `error` naming the field) when some value is out of range.
    bool IsValid(std::string* error) const;
};

/// Throws std::invalid_argument when the options are not valid.
Explanation explain(const task::Task& task, const ExplainOptions& options = {});
/// The same flow for a spatial task: the spatial reach proof and the front
/// stage's core as task parts, else the spatial synthesis, else the
/// changes of robot.max_link_length, robot.dof, robot.twists and the base
/// regions that remove the conflict (spatial_explanation.h).
Explanation explain(const task::SpatialTask& task, const ExplainOptions& options = {});

}  // namespace modsynth::explanation
