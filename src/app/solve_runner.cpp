#include "solve_runner.h"

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include <modsynth/text/format.h>

#include "command.h"
#include "process_pool.h"
#include "task_files.h"

namespace modsynth::app {
namespace {

std::string number(double v) { return text::format("%.17g", v); }

ProcessSpec spec_for(const SolveJob& job, const SolveRunOptions& o, const std::string& self) {
    ProcessSpec spec;
    spec.argv = {self,      "solve",        job.task_path,        "-o",     job.solution_path,
                 "--quiet", "--time-limit", number(o.time_limit), "--seed", std::to_string(o.seed)};
    spec.log_path = job.log_path;
    spec.wall_limit = o.time_limit + o.grace;
    return spec;
}

// Unparsable input yields an empty object: the caller then falls back to
// what the exit code says.
nlohmann::json read_json(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return nlohmann::json::object();
    std::ifstream in(path);
    if (!in) return nlohmann::json::object();
    try {
        auto doc = nlohmann::json::parse(in, nullptr, false);
        return doc.is_object() ? doc : nlohmann::json::object();
    } catch (const std::exception&) {
        // A read error (the file vanished, an I/O error) is unparsable too.
        return nlohmann::json::object();
    }
}

/// Why a task path cannot be solved at all, or "" when it can be tried: a
/// folder or a missing file named in a task list is one failed task, not
/// the end of the batch.
std::string unreadable_reason(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::file_status st = fs::status(path, ec);
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

std::string status_of_exit(int code) {
    switch (code) {
        case kOk:
            return "solved";
        case kInfeasible:
            return "infeasible";
        case kUnknown:
            return "unknown";
        case kInvalid:
            return "invalid";
        default:
            return "error";
    }
}

std::optional<double> optional_number(const nlohmann::json& doc, const char* key) {
    const auto it = doc.find(key);
    if (it == doc.end() || !it->is_number()) return std::nullopt;
    return it->get<double>();
}

void read_solution(const std::string& path, SolveOutcome& o) {
    const nlohmann::json doc = read_json(path);
    const std::string status = doc.value("status", "");
    if (status != o.status) {
        o.message = "exit code " + std::to_string(o.exit_code) + " but the solution file says '" +
                    status + "' (" + path + ")";
        o.status = "error";
        return;
    }
    o.name = doc.value("task", o.name);
    if (const auto e = doc.find("explanation"); e != doc.end() && e->is_object()) {
        o.message = e->value("message", "");
        if (const auto c = e->find("core"); c != e->end() && c->is_array())
            for (const auto& part : *c)
                if (part.is_string()) o.core.push_back(part.get<std::string>());
    }
    const auto robot = doc.find("robot");
    if (robot != doc.end() && robot->is_object()) {
        if (const auto d = robot->find("dof"); d != robot->end() && d->is_number_integer())
            o.dof = d->get<int>();
        if (const auto l = robot->find("link_lengths"); l != robot->end() && l->is_array()) {
            double sum = 0.0;
            for (const auto& r : *l) sum += r.is_number() ? r.get<double>() : 0.0;
            o.total_link_length = sum;
        }
    }
    if (const auto c = doc.find("certificate"); c != doc.end() && c->is_object())
        o.clearance_margin = optional_number(*c, "min_clearance_margin");
}

std::string task_name(const std::string& task_path) {
    const nlohmann::json doc = read_json(task_path);
    const auto it = doc.find("name");
    return it != doc.end() && it->is_string() ? it->get<std::string>() : task_stem(task_path);
}

SolveOutcome outcome_of(const SolveJob& job, const ProcessResult& r, const SolveRunOptions& o) {
    SolveOutcome out;
    out.exit_code = r.exit_code;
    out.signal = r.signal;
    out.seconds = r.seconds;
    out.name = task_name(job.task_path);
    char buf[160];
    if (r.timed_out) {
        out.status = "timeout";
        std::snprintf(buf, sizeof buf, "killed after %.2f s (time limit %g s + grace %g s)",
                      r.seconds, o.time_limit, o.grace);
        out.message = buf;
    } else if (r.signal != 0) {
        out.status = "crashed";
        out.message = std::string("killed by signal ") + std::to_string(r.signal) + " (" +
                      strsignal(r.signal) + ")";
    } else {
        out.status = status_of_exit(r.exit_code);
        if (is_answer(out.status)) {
            read_solution(job.solution_path, out);
        } else {
            out.message =
                r.exit_code == 127 ? "could not be started" : last_error_line(job.log_path);
        }
    }
    return out;
}

}  // namespace

bool is_answer(const std::string& status) {
    return status == "solved" || status == "infeasible" || status == "unknown";
}

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
        out.status = "invalid";
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
