#pragma once
// What `solve` does the same for planar and spatial tasks: the answer it
// writes when its time limit passes inside a library call (the watchdog),
// and the exit code an answer ends the command with (README, "Exit codes").
#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <modsynth/io/check_timeout.h>
#include <modsynth/io/solution_io.h>
#include <modsynth/output/exports.h>
#include <modsynth/output/parts_export.h>
#include <modsynth/run/progress.h>
#include <modsynth/synth/solution.h>

#include "watchdog.h"

namespace modsynth::app {

/// Past the time limit plus a margin, gives `answer` the solution "unknown:
/// time limit" at the last stage reported, and ends the process with
/// kUnknown; claim() stands it down once the run answers by itself.
class SolveGuard {
public:
    /// `time_limit` counts from the command's start, `elapsed` seconds ago.
    SolveGuard(std::string task_name, double time_limit, double elapsed,
               std::function<void(const synth::Solution&)> answer);

    void set_stage(const std::string& stage) { watchdog_.set_stage(stage); }
    /// As Watchdog::claim.
    void claim() { watchdog_.claim(); }

private:
    std::string task_name_;
    double time_limit_;
    std::function<void(const synth::Solution&)> answer_;
    Watchdog watchdog_;  // last: its thread may use the members above
};

/// Where a solve's progress events go: the guard's stage, the console
/// unless quiet, and the events file (JSON lines, io/progress_json.h) when
/// one is asked for (a regular file or a new one: io::check_outputs).
class SolveProgress {
public:
    /// Throws task::InputError naming `events_path` when it cannot be opened.
    SolveProgress(const std::string& events_path, bool quiet);
    ~SolveProgress();
    SolveProgress(const SolveProgress&) = delete;
    SolveProgress& operator=(const SolveProgress&) = delete;
    run::ProgressSink sink(SolveGuard& guard);
    /// Throws io::WriteError naming the events file when a line of it could
    /// not be written (a full disk): the run's events are then incomplete.
    void finish() const;

private:
    std::string path_;
    int fd_ = -1;
    int error_ = 0;  ///< errno of the first line that failed
    bool quiet_;
};

/// The solution file and the files asked for beside it, each export's note
/// on stderr: what every answer of `solve` writes, the watchdog's too.
template <class TaskT>
void write_answer(const TaskT& task, const synth::Solution& solution, const std::string& output,
                  const output::ExportPaths& exports, const output::ReportFigures& figures = {},
                  const parts::PrintedParts* printed = nullptr) {
    io::write_solution(solution, output);
    for (const auto& note : output::write_exports(task, solution, exports, figures, printed))
        std::fprintf(stderr, "note: %s\n", note.c_str());
}

/// --parts: the printed parts of a solved arm, written before the solution
/// and the build sheet so that both carry the modules the printed links
/// call for; what they could not do is a note. None without --parts.
template <class TaskT>
std::optional<parts::PrintedParts> print_parts(const TaskT& task,
                                               const std::optional<hardware::Catalog>& catalog,
                                               synth::Solution& solution,
                                               const std::string& folder) {
    if (folder.empty()) return std::nullopt;
    std::vector<std::string> notes;
    std::optional<parts::PrintedParts> printed =
        output::export_parts(task, catalog, solution, folder, notes);
    for (const auto& n : notes) std::fprintf(stderr, "note: %s\n", n.c_str());
    return printed;
}

/// kOk, kInfeasible or kUnknown.
int exit_code(const synth::Status& status);

/// The answer of a solve whose task was not checked within its time limit
/// (io::CheckTimeout): the solution file says "unknown" and why, the other
/// outputs are not written (each a note), the summary line is printed.
/// Returns kUnknown.
int answer_unchecked(const io::CheckTimeout& timeout, const std::string& output,
                     const output::ExportPaths& exports, double time_limit, double seconds);

}  // namespace modsynth::app
