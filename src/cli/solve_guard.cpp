#include "solve_guard.h"

#include <iostream>
#include <utility>

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

SolveProgress::SolveProgress(const std::string& events_path, bool quiet) : quiet_(quiet) {
    if (events_path.empty()) return;
    events_.open(events_path, std::ios::trunc);
    if (!events_) throw task::InputError(events_path, "cannot be written");
}

run::ProgressSink SolveProgress::sink(SolveGuard& guard) {
    return [this, &guard](const run::ProgressEvent& e) {
        guard.set_stage(e.message);
        if (!quiet_) std::cerr << run::console_line(e) << std::endl;
        if (events_.is_open()) events_ << io::progress_json_line(e) << std::endl;
    };
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
