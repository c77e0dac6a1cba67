#include "solve_jobs.h"

#include <modsynth/io/progress_json.h>
#include <modsynth/output/exports.h>
#include <modsynth/run/progress.h>
#include <modsynth/text/format.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>

#include "log_follower.h"
#include "process_pool.h"
#include "temp_dir.h"

namespace modsynth::app {
namespace {

// The supervisor's period: progress appears within it, and a cancel takes
// effect within it.
constexpr auto kTick = std::chrono::milliseconds(50);
constexpr std::size_t kLogLines = 60;

// The files a job may hand out, in the order clients list them.
const std::vector<std::string> kFiles = {
    "solution.json",         "report.html",    "robot.urdf", "trajectory.csv",
    "joint-trajectory.yaml", "build-sheet.md", "task.json",  "solve.log"};

std::string number(double v) { return text::format("%.6g", v); }

// Unguessable enough that one page cannot stumble on another's job. Called
// under the jobs' lock, which guards the generator too.
std::string new_id() {
    static std::mt19937_64 rng{std::random_device{}()};
    char buf[20];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(rng()));
    return buf;
}

}  // namespace

const char* to_string(Phase phase) {
    switch (phase) {
        case Phase::Solve:
            return "solve";
        case Phase::Explain:
            return "explain";
        case Phase::Done:
            return "done";
    }
    return "";
}

struct SolveJobs::Job {
    JobState state;
    std::unique_ptr<TempDir> dir;  // before child: the process dies before its folder goes
    std::unique_ptr<ChildProcess> child;
    std::unique_ptr<LogFollower> log;
    std::unique_ptr<LogFollower> events;  ///< the solve's progress events, JSON lines
    Clock::time_point start;
    Clock::time_point last_seen;
    int waiting = 0;  ///< clients in wait_for_change right now
    std::uint64_t finished_order = 0;

    std::string path(const std::string& name) const { return dir->path() + "/" + name; }
};

SolveJobs::SolveJobs(const JobLimits& limits, std::string executable)
    : limits_(limits), executable_(std::move(executable)) {
    supervisor_ = std::thread([this] { supervise(); });
}

SolveJobs::~SolveJobs() {
    shutdown();
    supervisor_.join();
    // Each job's ChildProcess kills its process, then its TempDir goes.
    jobs_.clear();
}

void SolveJobs::shutdown() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stopping_ = true;
    }
    changed_.notify_all();
}

std::string SolveJobs::start(const std::string& task_text, double time_limit) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (stopping_) throw JobsBusy("the server is shutting down");
    int active = 0;
    for (const auto& [id, job] : jobs_) active += job->state.phase != Phase::Done;
    if (active >= limits_.max_solves)
        throw JobsBusy(std::to_string(active) + " solves are running, the most this server allows");

    auto job = std::make_unique<Job>();
    job->state.id = new_id();
    job->state.time_limit =
        time_limit > 0.0 ? std::min(time_limit, limits_.time_limit) : limits_.time_limit;
    job->dir = std::make_unique<TempDir>("modsynth-serve");
    output::write_text_file(job->path("task.json"), task_text);
    job->start = job->last_seen = Clock::now();

    // The child runs in the job's folder and is given names, not paths:
    // what it prints (solve.log is served) must not tell where that is.
    ProcessSpec spec;
    spec.argv = {executable_,
                 "solve",
                 "task.json",
                 "-o",
                 "solution.json",
                 "--time-limit",
                 number(job->state.time_limit),
                 "--report",
                 "report.html",
                 "--urdf",
                 "robot.urdf",
                 "--csv",
                 "trajectory.csv",
                 "--joint-trajectory",
                 "joint-trajectory.yaml",
                 "--build-sheet",
                 "build-sheet.md",
                 "--events",
                 "events.jsonl"};
    spec.working_dir = job->dir->path();
    spec.log_path = job->path("solve.log");
    spec.wall_limit = job->state.time_limit + limits_.grace;
    job->log = std::make_unique<LogFollower>(spec.log_path);
    job->events = std::make_unique<LogFollower>(job->path("events.jsonl"));
    job->state.stage = "starting";
    job->child = std::make_unique<ChildProcess>(spec);

    const std::string id = job->state.id;
    jobs_.emplace(id, std::move(job));
    return id;
}

std::optional<JobState> SolveJobs::state(const std::string& id) {
    std::lock_guard<std::mutex> lock(mutex_);
    Job* job = find(id);
    if (!job) return std::nullopt;
    job->last_seen = Clock::now();
    return snapshot(*job);
}

std::optional<JobState> SolveJobs::wait_for_change(const std::string& id, std::uint64_t seen,
                                                   std::chrono::milliseconds timeout) {
    std::unique_lock<std::mutex> lock(mutex_);
    const auto settled = [&] {
        const Job* job = find(id);
        return stopping_ || !job || job->state.version != seen || job->state.phase == Phase::Done;
    };
    // A client waiting here is still there, however long the wait.
    Job* job = find(id);
    if (!job) return std::nullopt;
    ++job->waiting;
    changed_.wait_for(lock, timeout, settled);
    job = find(id);
    if (!job) return std::nullopt;
    --job->waiting;
    job->last_seen = Clock::now();
    return snapshot(*job);
}

bool SolveJobs::cancel(const std::string& id, const std::string& reason) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        Job* job = find(id);
        if (!job) return false;
        if (job->state.phase != Phase::Done) stop(*job, reason);
    }
    changed_.notify_all();
    return true;
}

std::optional<std::string> SolveJobs::file(const std::string& id, const std::string& name) {
    if (std::find(kFiles.begin(), kFiles.end(), name) == kFiles.end()) return std::nullopt;
    std::lock_guard<std::mutex> lock(mutex_);
    const Job* job = find(id);
    if (!job) return std::nullopt;
    const std::string path = job->path(name);
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
    return path;
}

int SolveJobs::running() {
    std::lock_guard<std::mutex> lock(mutex_);
    int active = 0;
    for (const auto& [id, job] : jobs_) active += job->state.phase != Phase::Done;
    return active;
}

// ------------------------------------------------------------- supervisor

void SolveJobs::supervise() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!stopping_) {
        const auto now = Clock::now();
        for (auto& [id, job] : jobs_)
            if (job->state.phase != Phase::Done) tick(*job, now);
        evict_finished();
        changed_.notify_all();
        changed_.wait_for(lock, kTick, [this] { return stopping_; });
    }
}

void SolveJobs::tick(Job& job, Clock::time_point now) {
    follow_log(job, false);
    if (job.waiting == 0 &&
        std::chrono::duration<double>(now - job.last_seen).count() > limits_.client_timeout) {
        stop(job, "the client left: no word from it for " + number(limits_.client_timeout) + " s");
        return;
    }
    if (!job.child->poll()) return;
    follow_log(job, true);
    if (job.state.phase == Phase::Solve) {
        end_solve(job);
    } else {
        end_explain(job);
    }
}

void SolveJobs::stop(Job& job, const std::string& reason) {
    job.child->kill_now();
    follow_log(job, true);
    job.state.cancel_reason = reason;
    if (job.state.phase == Phase::Explain) {
        // The answer stands; only the suggestions are missing.
        job.state.explanation_note = "no suggestions: " + reason;
        finish(job, job.state.outcome->status);
    } else {
        finish(job, RunStatus::failed(RunStatus::Failure::Cancelled));
    }
}

void SolveJobs::follow_log(Job& job, bool final) {
    if (job.state.phase == Phase::Solve) {
        for (const auto& line : job.events->new_lines(final))
            if (const auto event = io::parse_progress_json_line(line)) {
                job.state.stage = event->message;
                const std::string name = run::to_string(event->stage);
                auto& stages = job.state.stages;
                if (std::find(stages.begin(), stages.end(), name) == stages.end())
                    stages.push_back(name);
                ++job.state.version;
            }
    }
    for (auto& line : job.log->new_lines(final)) {
        job.state.log.push_back(std::move(line));
        ++job.state.version;
    }
    auto& log = job.state.log;
    if (log.size() > kLogLines) log.erase(log.begin(), log.end() - kLogLines);
}

void SolveJobs::end_solve(Job& job) {
    SolveRunOptions options;
    options.time_limit = job.state.time_limit;
    options.grace = limits_.grace;
    const SolveJob files{job.path("task.json"), job.path("solution.json"), job.path("solve.log")};
    job.state.outcome = read_outcome(files, *job.child->poll(), options);
    ++job.state.version;
    if (job.state.outcome->status != synth::Status::Infeasible) {
        finish(job, job.state.outcome->status);
        return;
    }
    ProcessSpec spec;
    spec.argv = {
        executable_,       "explain",
        "task.json",       "--json",
        "--time-limit",    number(std::min(limits_.explain_time_limit, job.state.time_limit)),
        "--solve-seconds", number(limits_.relaxation_seconds)};
    spec.log_path = job.path("explain.json");
    spec.stderr_path = job.path("explain.log");
    spec.wall_limit = limits_.explain_limit;
    spec.working_dir = job.dir->path();
    job.child = std::make_unique<ChildProcess>(spec);
    job.state.phase = Phase::Explain;
    job.state.stage = "looking for the smallest changes that remove the conflict";
    job.state.stages.push_back(run::to_string(run::Stage::Explanation));
}

void SolveJobs::end_explain(Job& job) {
    const ProcessResult r = *job.child->poll();
    std::ifstream in(job.path("explain.json"));
    auto doc = nlohmann::json::parse(in, nullptr, false);
    if (r.timed_out) {
        job.state.explanation_note = "no suggestions: looking for them took longer than " +
                                     number(limits_.explain_limit) + " s";
    } else if (doc.is_object()) {
        // An explain that ran out of time before finding a change says so
        // in its own note: the page shows that as the reason for none.
        const auto suggestions = doc.find("suggestions");
        const auto note = doc.find("note");
        if ((suggestions == doc.end() || suggestions->empty()) && note != doc.end() &&
            note->is_string() && !note->get<std::string>().empty()) {
            job.state.explanation_note = "no suggestions: " + note->get<std::string>();
        }
        job.state.explanation = std::move(doc);
    } else {
        job.state.explanation_note = "no suggestions: `modsynth explain` ended with exit code " +
                                     std::to_string(r.exit_code);
    }
    finish(job, job.state.outcome->status);
}

void SolveJobs::finish(Job& job, const RunStatus& status) {
    job.state.phase = Phase::Done;
    job.state.status = status;
    job.state.elapsed = std::chrono::duration<double>(Clock::now() - job.start).count();
    job.state.stage = to_string(status);
    job.state.files.clear();
    for (const auto& name : kFiles) {
        std::error_code ec;
        if (std::filesystem::is_regular_file(job.path(name), ec)) job.state.files.push_back(name);
    }
    job.finished_order = ++finished_count_;
    ++job.state.version;
}

void SolveJobs::evict_finished() {
    std::vector<std::pair<std::uint64_t, std::string>> done;
    for (const auto& [id, job] : jobs_)
        if (job->state.phase == Phase::Done) done.emplace_back(job->finished_order, id);
    if (done.size() <= limits_.keep_finished) return;
    std::sort(done.begin(), done.end());
    for (std::size_t i = 0; i + limits_.keep_finished < done.size(); ++i)
        jobs_.erase(done[i].second);
}

JobState SolveJobs::snapshot(const Job& job) const {
    JobState s = job.state;
    if (s.phase != Phase::Done)
        s.elapsed = std::chrono::duration<double>(Clock::now() - job.start).count();
    return s;
}

SolveJobs::Job* SolveJobs::find(const std::string& id) {
    const auto it = jobs_.find(id);
    return it == jobs_.end() ? nullptr : it->second.get();
}

}  // namespace modsynth::app
