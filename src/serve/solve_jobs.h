#pragma once
// The solves a server runs for its clients. Each job is a `modsynth solve`
// process in its own scratch folder (Ipopt is not thread-safe, and only a
// kill from outside bounds a run for sure), followed for an infeasible task
// by `modsynth explain` for the changes that would remove the conflict. A
// supervisor thread follows their progress lines, enforces the time limits,
// and cancels a job whose client asked to or stopped asking about it.
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "solve_runner.h"

namespace modsynth::app {

struct JobLimits {
    int max_solves = 2;            ///< jobs running at once; more are refused
    double time_limit = 60.0;      ///< the default and the longest solve a client may ask
    double grace = 5.0;            ///< seconds past the time limit before the kill
    double client_timeout = 15.0;  ///< no word from the client for this long: it left
    /// `explain`'s --time-limit for an infeasible task (the proof again, then
    /// the suggestions; at most the job's own time limit): the answer is
    /// known by then, and the page should not wait long for suggestions.
    double explain_time_limit = 10.0;
    double explain_limit = 60.0;      ///< wall clock for the suggested changes
    double relaxation_seconds = 5.0;  ///< full synthesis tried on each suggested change
    std::size_t keep_finished = 32;   ///< finished jobs kept for their downloads
};

enum class Phase { Solve, Explain, Done };

const char* to_string(Phase phase);

/// A job as a client sees it at one moment.
struct JobState {
    std::string id;
    Phase phase = Phase::Solve;
    std::uint64_t version = 0;  ///< grows with every change worth telling
    double elapsed = 0.0;       ///< seconds since the start (until the end once done)
    double time_limit = 0.0;
    std::string stage;  ///< the latest progress event's message
    /// The pipeline stages (run::to_string) the run has reached, in the
    /// order first reached; "explanation" once an infeasible task is
    /// explained.
    std::vector<std::string> stages;
    std::vector<std::string> log;         ///< the latest output lines
    std::optional<SolveOutcome> outcome;  ///< once the solve has ended
    /// Once done: the outcome's status, or Cancelled.
    std::optional<RunStatus> status;
    std::string cancel_reason;
    std::optional<nlohmann::json> explanation;  ///< `explain --json`'s answer
    std::string explanation_note;               ///< why there is none, or what is missing
    std::vector<std::string> files;             ///< downloadable files that exist
};

/// Every slot is taken: the client should try again later (HTTP 429).
class JobsBusy : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class SolveJobs {
public:
    /// `executable` is the modsynth binary that runs the solves.
    SolveJobs(const JobLimits& limits, std::string executable);
    ~SolveJobs();
    SolveJobs(const SolveJobs&) = delete;
    SolveJobs& operator=(const SolveJobs&) = delete;

    /// Starts solving a task document (already validated); time_limit <= 0
    /// or above the limit means the limit. Returns the job's id; throws
    /// JobsBusy when max_solves jobs are running.
    std::string start(const std::string& task_text, double time_limit);

    /// The job's state, or nothing for an unknown id. Every question about a
    /// job tells that its client is still there.
    std::optional<JobState> state(const std::string& id);

    /// Waits until the job's version differs from `seen`, the job is done,
    /// or `timeout` passes, then returns its state.
    std::optional<JobState> wait_for_change(const std::string& id, std::uint64_t seen,
                                            std::chrono::milliseconds timeout);

    /// Stops a running job at once (no-op once done); false for an unknown id.
    bool cancel(const std::string& id, const std::string& reason);

    /// The path of one of the job's files, when it exists.
    std::optional<std::string> file(const std::string& id, const std::string& name);

    int running();
    const JobLimits& limits() const { return limits_; }

    /// From now on no job starts and every wait returns at once, so that a
    /// server stopping is not held by a long poll; the destructor kills the
    /// jobs still running.
    void shutdown();

private:
    struct Job;
    using Clock = std::chrono::steady_clock;

    void supervise();
    void tick(Job& job, Clock::time_point now);
    void stop(Job& job, const std::string& reason);
    void follow_log(Job& job, bool final);
    void end_solve(Job& job);
    void end_explain(Job& job);
    void finish(Job& job, const RunStatus& status);
    void evict_finished();
    JobState snapshot(const Job& job) const;
    Job* find(const std::string& id);

    JobLimits limits_;
    std::string executable_;
    std::mutex mutex_;
    std::condition_variable changed_;
    std::map<std::string, std::unique_ptr<Job>> jobs_;
    std::uint64_t finished_count_ = 0;
    bool stopping_ = false;
    std::thread supervisor_;
};

}  // namespace modsynth::app
