#pragma once
// Many `modsynth solve` runs, each in its own process of this executable
// under a watchdog, and what each one answered, read back from its exit code
// and its solution file.
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "process_pool.h"
#include "run_status.h"

namespace modsynth::app {

struct SolveJob {
    std::string task_path;
    std::string solution_path;
    std::string log_path;  ///< the child's stdout and stderr
};

struct SolveRunOptions {
    double time_limit = 60.0;  ///< passed to each solve
    double grace = 10.0;       ///< seconds past time_limit before the watchdog kills
    unsigned seed = 0;
    std::string swept = "auto";  ///< passed to each solve (solve --swept)
    /// Passed to each solve (solve --shorten-gap) when set.
    std::optional<double> shorten_gap;
    int jobs = 1;
};

struct SolveOutcome {
    RunStatus status;
    int exit_code = -1;
    int signal = 0;
    double seconds = 0.0;
    std::string name;  ///< the task's name, or the file's stem if unreadable
    std::optional<int> dof;
    std::optional<double> total_link_length;
    std::optional<double> clearance_margin;  ///< certified; none when no obstacle bounds it
    std::optional<double> motion_seconds;    ///< the timed motion's duration (solved)
    std::vector<std::string> core;
    std::string message;  ///< explanation, or the error a failed run printed
};

using OutcomeHandler = std::function<void(std::size_t index, const SolveOutcome& outcome)>;

/// What one finished run answered, read from how it ended and from its
/// solution file, as run_solves reports it (for callers that run the
/// process themselves).
SolveOutcome read_outcome(const SolveJob& job, const ProcessResult& result,
                          const SolveRunOptions& options);

/// Runs the jobs, options.jobs at a time; on_done is called as each ends.
/// Throws Interrupted (process_pool.h) on SIGINT/SIGTERM.
void run_solves(const std::vector<SolveJob>& jobs, const SolveRunOptions& options,
                const OutcomeHandler& on_done, const std::function<void()>& on_tick = {});

}  // namespace modsynth::app
