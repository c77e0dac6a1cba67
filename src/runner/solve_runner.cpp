#include "solve_runner.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <variant>

#include <modsynth/io/check_timeout.h>
#include <modsynth/io/solution_io.h>
#include <modsynth/io/task_document.h>
#include <modsynth/io/task_io.h>
#include <modsynth/text/format.h>

#include "exit_code.h"
#include "process_pool.h"
#include "task_files.h"

namespace modsynth::app {
namespace {

std::string number(double v) { return text::format("%.17g", v); }

ProcessSpec spec_for(const SolveJob& job, const SolveRunOptions& o, const std::string& self) {
    ProcessSpec spec;
    spec.argv = {self,      "solve",        job.task_path,        "-o",     job.solution_path,
                 "--quiet", "--time-limit", number(o.time_limit), "--seed", std::to_string(o.seed)};
    if (o.swept != "auto") spec.argv.insert(spec.argv.end(), {"--swept", o.swept});
    if (o.shorten_gap) spec.argv.insert(spec.argv.end(), {"--shorten-gap", number(*o.shorten_gap)});
    spec.log_path = job.log_path;
    spec.wall_limit = o.time_limit + o.grace;
    return spec;
}

/// Why a task path cannot be solved at all, or "" when it can be tried: a
/// folder or a missing file named in a task list is one failed task, not
/// the end of the batch.
std::string unreadable_reason(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::file_status st = fs::status(path, ec);
    if (ec && ec != std::errc::no_such_file_or_directory) return "cannot be read: " + ec.message();
    if (!fs::exists(st)) return "no such file";
    if (fs::is_directory(st)) return "is a folder, not a task file";
    if (!fs::is_regular_file(st)) return "is not a regular file";
    if (!std::ifstream(path)) return "cannot be read";
    return "";
}

std::string last_error_line(const std::string& log_path) {
    std::ifstream in(log_path);
    std::string line, last, error;
    while (std::getline(in, line)) {
        if (line.empty()) continue;
        last = line;
        if (line.rfind("error: ", 0) == 0 || line.rfind("internal error: ", 0) == 0) error = line;
    }
    if (error.empty()) return last;
    return error.substr(error.find(':') + 2);
}

RunStatus status_of_exit(int code) {
    using synth::Status;
    switch (code) {
        case kOk:
            return RunStatus::answered(Status::Solved);
        case kInfeasible:
            return RunStatus::answered(Status::Infeasible);
        case kUnknown:
            return RunStatus::answered(Status::Unknown);
        case kInvalid:
            return RunStatus::failed(RunStatus::Failure::Invalid);
        default:
            return RunStatus::failed(RunStatus::Failure::Error);
    }
}

/// The answer's figures from the solution file the run wrote, which must
/// say what its exit code said.
void read_solution(const std::string& path, SolveOutcome& o) {
    io::ParsedSolution parsed;
    try {
        parsed = io::load_solution(path);
    } catch (const task::InputError& e) {
        o.message = "exit code " + std::to_string(o.exit_code) +
                    " but the solution file cannot be read: " + e.what();
        o.status = RunStatus::failed(RunStatus::Failure::Error);
        return;
    }
    const synth::Solution& s = parsed.solution;
    if (s.status.kind != o.status.answer.kind) {
        o.message = "exit code " + std::to_string(o.exit_code) + " but the solution file says '" +
                    synth::to_string(s.status) + "' (" + path + ")";
        o.status = RunStatus::failed(RunStatus::Failure::Error);
        return;
    }
    if (!s.task_name.empty()) o.name = s.task_name;
    o.message = s.explanation.message;
    o.core = task::to_strings(s.explanation.core);
    if (s.status != synth::Status::Solved) return;
    if (s.dh_robot) {  // a spatial solution: its chain is in DH rows
        o.dof = s.dh_robot->dof();
        o.total_link_length = s.dh_robot->total_length();
    } else {
        o.dof = s.robot.dof();
        o.total_link_length = s.robot.total_length();
    }
    if (!s.samples.empty()) o.motion_seconds = s.samples.back().t - s.samples.front().t;
    if (parsed.has_certificate && std::isfinite(s.certificate.min_clearance))
        o.clearance_margin = s.certificate.min_clearance;
}

/// Seconds the name of a task may take to read: its checks are the child
/// solve's business (within its time limit), and a spatial path among many
/// obstacles takes hours to check.
constexpr double kNameSeconds = 0.5;

/// The task's name, or the file's stem when the task cannot be read.
std::string task_name(const std::string& task_path) {
    try {
        return std::visit([](const auto& t) { return t.name; },
                          io::load_task_document(task_path, run::Deadline::in(kNameSeconds)));
    } catch (const io::CheckTimeout& e) {
        return e.task_name();
    } catch (const task::InputError&) {
        return task_stem(task_path);
    }
}

SolveOutcome outcome_of(const SolveJob& job, const ProcessResult& r, const SolveRunOptions& o) {
    SolveOutcome out;
    out.exit_code = r.exit_code;
    out.signal = r.signal;
    out.seconds = r.seconds;
    out.name = task_name(job.task_path);
    char buf[160];
    if (r.timed_out) {
        out.status = RunStatus::failed(RunStatus::Failure::Timeout);
        std::snprintf(buf, sizeof buf, "killed after %.2f s (time limit %g s + grace %g s)",
                      r.seconds, o.time_limit, o.grace);
        out.message = buf;
    } else if (r.signal != 0) {
        out.status = RunStatus::failed(RunStatus::Failure::Crashed);
        out.message = std::string("killed by signal ") + std::to_string(r.signal) + " (" +
                      strsignal(r.signal) + ")";
    } else {
        out.status = status_of_exit(r.exit_code);
        if (out.status.is_answer()) {
            read_solution(job.solution_path, out);
        } else {
            out.message =
                r.exit_code == 127 ? "could not be started" : last_error_line(job.log_path);
        }
    }
    return out;
}

}  // namespace

SolveOutcome read_outcome(const SolveJob& job, const ProcessResult& result,
                          const SolveRunOptions& options) {
    return outcome_of(job, result, options);
}

void run_solves(const std::vector<SolveJob>& jobs, const SolveRunOptions& options,
                const OutcomeHandler& on_done, const std::function<void()>& on_tick) {
    const std::string self = self_executable();
    std::vector<ProcessSpec> specs;
    std::vector<std::size_t> index_of;  // specs[k] runs jobs[index_of[k]]
    for (std::size_t i = 0; i < jobs.size(); ++i) {
        const std::string reason = unreadable_reason(jobs[i].task_path);
        if (reason.empty()) {
            specs.push_back(spec_for(jobs[i], options, self));
            index_of.push_back(i);
            continue;
        }
        SolveOutcome out;
        out.status = RunStatus::failed(RunStatus::Failure::Invalid);
        out.exit_code = kInvalid;
        out.name = task_stem(jobs[i].task_path);
        out.message = jobs[i].task_path + ": " + reason;
        on_done(i, out);
    }
    run_processes(
        specs, options.jobs,
        [&](std::size_t k, const ProcessResult& r) {
            on_done(index_of[k], outcome_of(jobs[index_of[k]], r, options));
        },
        on_tick);
}

}  // namespace modsynth::app
