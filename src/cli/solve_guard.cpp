#include "solve_guard.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <iostream>
#include <utility>

#include <modsynth/io/atomic_file.h>
#include <modsynth/io/progress_json.h>
#include <modsynth/task/input_error.h>

#include <modsynth/text/format.h>
#include <modsynth/text/printable.h>

#include "exit_code.h"

namespace modsynth::app {
namespace {

// Past the time limit by this much, the watchdog answers for the run.
constexpr double kWatchdogMargin = 0.6;

}  // namespace

SolveGuard::SolveGuard(std::string task_name, double time_limit, double elapsed,
                       std::function<void(const synth::Solution&)> answer)
    : task_name_(std::move(task_name)),
      time_limit_(time_limit),
      answer_(std::move(answer)),
      watchdog_(time_limit + kWatchdogMargin - elapsed, [this] {
          synth::Solution unknown;
          unknown.task_name = task_name_;
          unknown.status =
              synth::Status(synth::Status::Unknown, text::printable(watchdog_.stage(), 200),
                            text::format("time limit (%.3g s)", time_limit_));
          unknown.explanation.message = "No certified robot found within the " +
                                        unknown.status.reason +
                                        "; the last stage reached: " + unknown.status.stage + ".";
          answer_(unknown);
          return int{kUnknown};
      }) {}

SolveProgress::SolveProgress(const std::string& events_path, bool quiet)
    : path_(events_path), quiet_(quiet) {
    if (events_path.empty()) return;
    fd_ = ::open(events_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd_ < 0)
        throw task::InputError("--events " + text::printable(events_path, 200),
                               std::string("cannot be written: ") + std::strerror(errno));
}

SolveProgress::~SolveProgress() {
    if (fd_ >= 0) ::close(fd_);
}

run::ProgressSink SolveProgress::sink(SolveGuard& guard) {
    return [this, &guard](const run::ProgressEvent& e) {
        guard.set_stage(e.message);
        if (!quiet_) std::cerr << run::console_line(e) << std::endl;
        if (fd_ < 0 || error_ != 0) return;
        // A line at a time, whole: a program following the file reads
        // complete events.
        const std::string line = io::progress_json_line(e) + "\n";
        const char* p = line.data();
        std::size_t left = line.size();
        while (left > 0) {
            const ssize_t n = ::write(fd_, p, left);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) {
                error_ = n < 0 ? errno : ENOSPC;
                return;
            }
            p += n;
            left -= static_cast<std::size_t>(n);
        }
    };
}

void SolveProgress::finish() const {
    if (error_ != 0)
        throw io::WriteError("--events " + text::printable(path_, 200) +
                             ": write failed, the events are incomplete (" + std::strerror(error_) +
                             ")");
}

int answer_unchecked(const io::CheckTimeout& timeout, const std::string& output,
                     const output::ExportPaths& exports, double time_limit, double seconds) {
    synth::Solution unknown;
    unknown.task_name = timeout.task_name();
    unknown.status = synth::Status(synth::Status::Unknown, "checking the task",
                                   text::format("time limit (%.3g s)", time_limit));
    unknown.explanation.message = "No certified robot found within the " + unknown.status.reason +
                                  ": the task's checks did not end (" + timeout.what() + ").";
    io::write_solution(unknown, output);
    for (const auto& [path, option] :
         {std::pair{&exports.report, "--report"}, std::pair{&exports.urdf, "--urdf"},
          std::pair{&exports.csv, "--csv"}, std::pair{&exports.build_sheet, "--build-sheet"},
          std::pair{&exports.joint_trajectory, "--joint-trajectory"},
          std::pair{&exports.parts, "--parts"}})
        if (!path->empty())
            std::fprintf(stderr, "note: %s %s: not written; the task was not checked\n", option,
                         text::printable(*path, 200).c_str());
    std::printf("%s: unknown in %.3f s\n  %s\n", text::printable(unknown.task_name, 80).c_str(),
                seconds, text::printable(unknown.explanation.message, 400).c_str());
    return kUnknown;
}

int exit_code(const synth::Status& status) {
    switch (status) {
        case synth::Status::Solved:
            return kOk;
        case synth::Status::Infeasible:
            return kInfeasible;
        case synth::Status::Unknown:
            return kUnknown;
    }
    return kInternal;
}

}  // namespace modsynth::app
