// `modsynth batch`: many tasks solved in parallel processes, one JSON line
// of figures per task. Exit 0 when every task got an answer (solved,
// infeasible or unknown), 1 when any run failed, 2 on bad usage.
#include <modsynth/run/stopwatch.h>
#include <modsynth/task/input_error.h>
#include <modsynth/text/format.h>
#include <modsynth/text/printable.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "command.h"
#include "number_checks.h"
#include "process_pool.h"
#include "solve_runner.h"
#include "task_files.h"
#include "temp_dir.h"

namespace modsynth::app {
namespace {

namespace fs = std::filesystem;

struct BatchArgs {
    std::string input, out, solutions, shard = "1/1";
    SolveRunOptions run;
};

std::vector<std::string> all_tasks(const std::string& input) {
    std::error_code ec;
    if (fs::is_directory(input, ec)) return find_task_files(input);
    if (fs::is_regular_file(input, ec)) return read_task_list(input);
    throw task::InputError(input, "no such folder or task list");
}

// Failures of any kind share one column: a user first wants to know how many
// runs need a look, the results file says why.
constexpr synth::Status::Kind kAnswerColumns[] = {synth::Status::Solved, synth::Status::Infeasible,
                                                  synth::Status::Unknown};
constexpr std::size_t kFailedColumn = std::size(kAnswerColumns);
constexpr std::size_t kColumns = kFailedColumn + 1;

std::size_t column_of(const RunStatus& status) {
    for (std::size_t c = 0; c < kFailedColumn; ++c)
        if (status == kAnswerColumns[c]) return c;
    return kFailedColumn;
}

const char* column_name(std::size_t column) {
    return column == kFailedColumn ? "failed" : synth::to_string(kAnswerColumns[column]);
}

// Dividing by the power of ten gives the double nearest the decimal, which
// JSON then prints without a tail of noise.
double round_to(double v, int decimals) {
    const double scale = std::pow(10.0, decimals);
    return std::round(v * scale) / scale;
}

nlohmann::json optional_json(const std::optional<double>& v, int decimals) {
    return v ? nlohmann::json(round_to(*v, decimals)) : nlohmann::json(nullptr);
}

/// Seconds a run spent in each stage, as its summary line on stdout says
/// them (the solution file does not record them).
struct StageSeconds {
    double front = 0.0, refine = 0.0, verify = 0.0;
};

std::optional<StageSeconds> stage_seconds(const std::string& log_path, const SolveOutcome& o) {
    std::ifstream in(log_path);
    std::string line;
    std::optional<StageSeconds> found;
    while (std::getline(in, line)) {
        // Searched from the end: the task name in front may hold anything.
        const std::size_t at = line.rfind(" s (front stage ");
        if (at == std::string::npos) continue;
        StageSeconds s;
        if (std::sscanf(line.c_str() + at,
                        " s (front stage %lf s, refinement %lf s, verification %lf s)", &s.front,
                        &s.refine, &s.verify) == 3)
            found = s;
    }
    // A time-limit answer comes from the watchdog thread, which has no stage
    // figures and prints zeros; those would claim the run spent no time in any.
    if (found && o.status == synth::Status::Unknown && found->front == 0.0 &&
        found->refine == 0.0 && found->verify == 0.0)
        return std::nullopt;
    return found;
}

nlohmann::ordered_json result_line(const std::string& path, const SolveOutcome& o,
                                   const std::string& kept_solution,
                                   const std::optional<StageSeconds>& stages) {
    nlohmann::ordered_json line;
    line["task"] = path;
    line["name"] = o.name;
    line["status"] = to_string(o.status);
    line["exit_code"] = o.exit_code;
    line["seconds"] = round_to(o.seconds, 3);
    if (stages) {
        line["front_seconds"] = round_to(stages->front, 3);
        line["refine_seconds"] = round_to(stages->refine, 3);
        line["verify_seconds"] = round_to(stages->verify, 3);
    }
    line["dof"] = o.dof ? nlohmann::json(*o.dof) : nlohmann::json(nullptr);
    line["total_link_length"] = optional_json(o.total_link_length, 9);
    line["clearance_margin"] = optional_json(o.clearance_margin, 9);
    line["motion_seconds"] = optional_json(o.motion_seconds, 3);
    if (!o.core.empty()) line["core"] = o.core;
    if (!o.message.empty() && o.status != synth::Status::Solved) line["message"] = o.message;
    if (o.signal != 0) line["signal"] = o.signal;
    line["solution"] = kept_solution.empty() || !o.status.is_answer()
                           ? nlohmann::json(nullptr)
                           : nlohmann::json(kept_solution);
    return line;
}

class Progress {
public:
    explicit Progress(std::size_t total) : total_(total), tty_(isatty(STDERR_FILENO) != 0) {}

    void finished(const SolveOutcome& o) {
        ++done_;
        ++counts_[column_of(o.status)];
        if (tty_) {
            draw("");
        } else {
            // A task's name is the task's to choose: escaped, as validate
            // and solve print it, so that it cannot move the cursor or
            // fake a line.
            draw(text::format("  %s: %s %.2f s", text::printable(o.name, 80).c_str(),
                              to_string(o.status).c_str(), o.seconds));
        }
    }
    void tick() {
        if (tty_) draw("");
    }
    void close() {
        if (tty_ && total_ > 0) std::fputc('\n', stderr);
    }
    double elapsed() const { return clock_.seconds(); }

private:
    void draw(const std::string& tail) {
        const int width = static_cast<int>(std::to_string(total_).size());
        std::fprintf(stderr,
                     "%s[%*zu/%zu] solved %d, infeasible %d, unknown %d, failed %d, %.1f s%s%s",
                     tty_ ? "\r" : "", width, done_, total_, counts_[0], counts_[1], counts_[2],
                     counts_[kFailedColumn], elapsed(), tail.c_str(), tty_ ? "\033[K" : "\n");
        std::fflush(stderr);
    }

    std::size_t total_, done_ = 0;
    bool tty_;
    std::array<int, kColumns> counts_{};  // by column_of
    run::Stopwatch clock_;
};

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

void print_row(const char* label, const std::vector<double>& seconds) {
    if (seconds.empty()) {
        std::printf("  %-11s %6d %10s %9s\n", label, 0, "-", "-");
        return;
    }
    std::printf("  %-11s %6zu %10.2f %9.2f\n", label, seconds.size(), median(seconds),
                *std::max_element(seconds.begin(), seconds.end()));
}

void print_summary(const BatchArgs& a, const Shard& shard, const std::vector<std::string>& paths,
                   const std::vector<SolveOutcome>& outcomes, double wall) {
    std::printf("batch: %zu tasks (shard %d/%d) in %.1f s with %d jobs\n", outcomes.size(),
                shard.index, shard.count, wall, a.run.jobs);
    std::printf("  %-11s %6s %10s %9s\n", "status", "tasks", "median s", "max s");
    std::array<std::vector<double>, kColumns> by_column;
    std::vector<double> all;
    for (const auto& o : outcomes) {
        by_column[column_of(o.status)].push_back(o.seconds);
        all.push_back(o.seconds);
    }
    for (std::size_t c = 0; c < kColumns; ++c) print_row(column_name(c), by_column[c]);
    print_row("all", all);
    for (std::size_t i = 0; i < outcomes.size(); ++i)
        if (!outcomes[i].status.is_answer())
            std::printf("  failed: %s: %s: %s\n", paths[i].c_str(),
                        to_string(outcomes[i].status).c_str(), outcomes[i].message.c_str());
    std::printf("results: %s\n", a.out.c_str());
}

// Lines go out in task order as soon as every earlier task is done, so the
// file is the same whatever order the runs end in, and a killed batch still
// leaves a usable prefix.
class OrderedWriter {
public:
    OrderedWriter(const std::string& path, std::size_t count) : out_(path), lines_(count) {
        if (!out_) throw std::runtime_error(path + ": cannot open for writing");
    }
    void put(std::size_t i, const std::string& line) {
        lines_[i] = line;
        while (next_ < lines_.size() && lines_[next_]) out_ << *lines_[next_++] << '\n';
        out_.flush();
        if (!out_) throw std::runtime_error("results file: write failed");
    }

private:
    std::ofstream out_;
    std::vector<std::optional<std::string>> lines_;
    std::size_t next_ = 0;
};

int run_batch(const BatchArgs& a) {
    const Shard shard = parse_shard(a.shard);
    const std::vector<std::string> all = all_tasks(a.input);
    {
        std::vector<std::string> inputs = all;
        inputs.push_back(a.input);
        io::check_outputs({{"--out", a.out}}, inputs);
    }
    std::error_code ignored;
    // Named after the path below the suite folder, so that a/x and b/x
    // keep apart and a task's files keep their names as the suite grows.
    const std::vector<std::string> names =
        output_names(all, fs::is_directory(a.input, ignored) ? a.input : std::string());
    std::optional<TempDir> scratch;
    std::string dir = a.solutions;
    if (dir.empty()) {
        scratch.emplace("modsynth-batch");
        dir = scratch->path();
    } else {
        fs::create_directories(dir);
    }
    std::vector<std::string> paths;
    std::vector<SolveJob> jobs;
    for (std::size_t i : shard_positions(all.size(), shard)) {
        paths.push_back(all[i]);
        const fs::path base_path = fs::path(dir) / names[i];
        fs::create_directories(base_path.parent_path());
        const std::string base = base_path.string();
        jobs.push_back({all[i], base + ".solution.json", base + ".log"});
    }
    OrderedWriter writer(a.out, jobs.size());
    Progress progress(jobs.size());
    std::vector<SolveOutcome> outcomes(jobs.size());
    try {
        run_solves(
            jobs, a.run,
            [&](std::size_t i, const SolveOutcome& o) {
                outcomes[i] = o;
                writer.put(i, result_line(paths[i], o, scratch ? "" : jobs[i].solution_path,
                                          stage_seconds(jobs[i].log_path, o))
                                  .dump());
                progress.finished(o);
            },
            [&] { progress.tick(); });
    } catch (const Interrupted&) {
        progress.close();
        std::fprintf(stderr, "batch: interrupted; the finished tasks are in %s\n", a.out.c_str());
        return kInternal;
    }
    progress.close();
    print_summary(a, shard, paths, outcomes, progress.elapsed());
    const bool all_answered =
        std::all_of(outcomes.begin(), outcomes.end(),
                    [](const SolveOutcome& o) { return o.status.is_answer(); });
    return all_answered ? kOk : kInternal;
}

}  // namespace

Command add_batch(CLI::App& parent) {
    auto a = std::make_shared<BatchArgs>();
    a->run.jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    CLI::App* sub = parent.add_subcommand(
        "batch",
        "Solve many tasks in parallel processes (exit 0: every task answered, 1: some failed)");
    sub->add_option(
           "INPUT", a->input,
           "a folder (every *.json task in it, recursively; only *.task.json where present) "
           "or a text file listing one task path per line")
        ->required();
    sub->add_option("--out", a->out, "results, one JSON object per task and line")->required();
    sub->add_option("-j,--jobs", a->run.jobs, "solves at once (default: the number of CPUs)")
        ->check(CLI::Range(1, 4096));
    sub->add_option("--shard", a->shard,
                    "K/N: of the tasks sorted by path, take every N-th starting at the K-th");
    sub->add_option("--time-limit", a->run.time_limit, "seconds per task (default 60)")
        ->check(seconds());
    sub->add_option("--grace", a->run.grace,
                    "seconds past the time limit before a run is killed (default 10)")
        ->check(seconds_or_zero());
    sub->add_option(
        "--solutions", a->solutions,
        "keep each solution (NAME.solution.json) and run log (NAME.log) in this folder; NAME "
        "is the task's path below the suite folder (or the listed tasks' common folder) "
        "without .task.json or .json");
    sub->add_option("--seed", a->run.seed, "passed to every solve (default 0)");
    sub->add_option("--swept", a->run.swept, "passed to every solve (default auto)")
        ->check(CLI::IsMember({"auto", "app", "over", "lines"}));
    sub->add_option("--shorten-gap", a->run.shorten_gap,
                    "passed to every solve (solve --shorten-gap; default 0.0005)")
        ->check(within(0.0, 10.0));
    return {sub, [a] { return run_batch(*a); }};
}

}  // namespace modsynth::app
