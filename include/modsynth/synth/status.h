#pragma once
// What a synthesis run concluded, as one value from the synthesizer to the
// documents and the console (after OMPL's PlannerStatus): solved, proved
// infeasible, or unknown. An unknown answer is an orderly one, so it says how
// far the run got and why it stopped there.
#include <string>
#include <string_view>

namespace modsynth::synth {

struct Status {
    enum class Kind { Solved, Infeasible, Unknown };
    using enum Kind;

    Kind kind = Unknown;
    std::string stage;   ///< Unknown only: the last stage reached ("3 joints: front stage")
    std::string reason;  ///< Unknown only: why the run stopped there ("time limit")

    // Implicit both ways, so that `status == Status::Solved` and
    // `switch (status)` read as they would on the bare enum.
    Status(Kind k = Unknown, std::string stage = {}, std::string reason = {})
        : kind(k), stage(std::move(stage)), reason(std::move(reason)) {}
    operator Kind() const { return kind; }
};

/// "solved", "infeasible", "unknown": the words of formats.md.
const char* to_string(Status::Kind kind);

/// The inverse of to_string. Other text throws task::InputError naming
/// `part` (the JSON path the text came from) and the words it may be.
Status::Kind status_from_string(std::string_view text, const std::string& part);

}  // namespace modsynth::synth
