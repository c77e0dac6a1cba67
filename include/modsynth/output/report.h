#pragma once
// A visual report: one self-contained HTML file (inline SVG, a little inline
// script, nothing fetched) showing the task, the robot, its obstacle-free
// reachable space, the region swept during each primitive, an animation of
// the whole motion and a table of figures. For an infeasible (or unknown)
// task it shows the explanation and highlights the task parts of its core.
#include <optional>
#include <string>

#include <modsynth/baseline/comparison.h>
#include <modsynth/synth/solution.h>
#include <modsynth/task/task.h>

namespace modsynth::output {

/// What the solution itself does not record.
struct ReportFigures {
    /// Seconds per synthesis stage; unknown for a saved solution ("n/a").
    std::optional<double> front_seconds;
    std::optional<double> refine_seconds;
    std::optional<double> verify_seconds;
    /// Where the certificate's figures come from, when not from synthesis
    /// (e.g. "recomputed on export: the solution file carried none").
    std::string certificate_note;
    /// When given, the report also shows the discretized baseline's robot,
    /// its executed path and the figures of both methods.
    const baseline::Comparison* comparison = nullptr;
};

std::string html_report(const task::Task& task, const synth::Solution& solution,
                        const ReportFigures& figures);

}  // namespace modsynth::output
