#pragma once
// How one `modsynth solve` run ended, as the batch, the regression suite and
// the server see it: the answer it gave (synth::Status), or why it gave none.
#include <string>
#include <string_view>

#include <modsynth/synth/status.h>

namespace modsynth::app {

struct RunStatus {
    /// Why a run gave no answer: a bad task, an internal error, killed by
    /// the watchdog, killed by another signal, or stopped on request.
    enum class Failure { None, Invalid, Error, Timeout, Crashed, Cancelled };

    synth::Status answer;  ///< what the run concluded, when failure is None
    Failure failure = Failure::None;

    static RunStatus answered(synth::Status answer) { return {std::move(answer), Failure::None}; }
    static RunStatus failed(Failure failure) { return {{}, failure}; }

    bool is_answer() const { return failure == Failure::None; }
    /// An answer of that kind: `status == synth::Status::Solved`.
    bool operator==(synth::Status::Kind kind) const { return is_answer() && answer.kind == kind; }
    bool operator==(Failure f) const { return failure == f; }
    /// The same answer kind, or the same failure.
    bool operator==(const RunStatus& other) const {
        return failure == other.failure && (!is_answer() || answer.kind == other.answer.kind);
    }
};

/// An answer's word ("solved", formats.md) or a failure's ("invalid",
/// "error", "timeout", "crashed", "cancelled"), as results lines and the
/// server's replies carry it.
std::string to_string(const RunStatus& status);

/// The inverse of to_string; other text throws task::InputError naming
/// `part` and the words it may be.
RunStatus run_status_from_string(std::string_view text, const std::string& part);

}  // namespace modsynth::app
