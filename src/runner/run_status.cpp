#include "run_status.h"

#include <modsynth/task/input_error.h>
#include <modsynth/text/printable.h>

namespace modsynth::app {
namespace {

using Failure = RunStatus::Failure;

constexpr Failure kFailures[] = {Failure::Invalid, Failure::Error, Failure::Timeout,
                                 Failure::Crashed, Failure::Cancelled};

const char* failure_name(Failure failure) {
    switch (failure) {
        case Failure::None:
            break;
        case Failure::Invalid:
            return "invalid";
        case Failure::Error:
            return "error";
        case Failure::Timeout:
            return "timeout";
        case Failure::Crashed:
            return "crashed";
        case Failure::Cancelled:
            return "cancelled";
    }
    return "";
}

}  // namespace

std::string to_string(const RunStatus& status) {
    return status.is_answer() ? synth::to_string(status.answer.kind) : failure_name(status.failure);
}

RunStatus run_status_from_string(std::string_view text, const std::string& part) {
    for (const Failure f : kFailures) {
        if (text == failure_name(f)) return RunStatus::failed(f);
    }
    for (const auto kind :
         {synth::Status::Solved, synth::Status::Infeasible, synth::Status::Unknown}) {
        if (text == synth::to_string(kind)) return RunStatus::answered(kind);
    }
    throw task::InputError(
        part,
        "expected \"solved\", \"infeasible\", \"unknown\" or how a run failed "
        "(\"invalid\", \"error\", \"timeout\", \"crashed\", \"cancelled\"), got \"" +
            text::printable(text) + "\"");
}

}  // namespace modsynth::app
