#pragma once
// The search for the smallest change of each core part, for planar and
// spatial tasks alike: each relaxer bisects one number of the task until
// the conflict is gone (`Check`), and a change is offered only once
// re-checked and tried with the full pipeline (`Attempt`).
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <modsynth/explanation/explanation.h>
#include <modsynth/run/deadline.h>
#include <modsynth/synth/solution.h>
#include <modsynth/task/part.h>
#include <modsynth/text/format.h>

namespace modsynth::explanation {

/// What a full run on a relaxed task that was not solved concluded, in a
/// sentence.
inline std::pair<synth::Status, std::string> unsolved_outcome(const synth::Solution& s,
                                                              double seconds) {
    if (s.status == synth::Status::Infeasible)
        return {s.status, "still infeasible: " + s.explanation.message};
    return {s.status, text::format("not confirmed in %.0f s: the conflict is gone, but the "
                                   "synthesis found no robot in that time",
                                   seconds)};
}

template <typename TaskT>
class RelaxationSearch {
public:
    /// Whether a relaxed task is free of the conflict.
    using Check = bool (*)(const TaskT&, double check_seconds, const run::Deadline&);
    /// The full pipeline on a relaxed task: its status and a sentence.
    using Attempt = std::pair<synth::Status, std::string> (*)(const TaskT&, double seconds);

    RelaxationSearch(const TaskT& task, const std::vector<task::TaskPart>& core,
                     double solve_seconds, double time_limit, const RelaxationOptions& options,
                     Check check, Attempt attempt)
        : task_(task),
          core_(core),
          solve_seconds_(solve_seconds),
          options_(options),
          deadline_(run::Deadline::in(time_limit)),
          check_(check),
          attempt_(attempt) {}

protected:
    bool free(const TaskT& t) const { return check_(t, options_.check_seconds, deadline_); }

    // Smallest value in [lo, hi] (by bisection to `tolerance`) for which
    // `is_free(value)` holds, assuming monotonicity; nullopt if not even at
    // hi, or when the deadline passes first.
    template <typename Free>
    std::optional<double> smallest(double lo, double hi, double tolerance, Free is_free) const {
        if (!is_free(hi)) return std::nullopt;
        while (hi - lo > tolerance) {
            if (deadline_.expired()) return std::nullopt;
            const double mid = 0.5 * (lo + hi);
            (is_free(mid) ? hi : lo) = mid;
        }
        return hi;
    }

    // Re-checked here, whatever the search that found it assumed.
    bool offer(const task::TaskPart& part, const std::string& change, const TaskT& relaxed) {
        if (!free(relaxed)) return false;
        auto [status, outcome] = attempt_(relaxed, std::min(solve_seconds_, deadline_.remaining()));
        out_.push_back({part, change, relaxed, std::move(status), std::move(outcome)});
        return true;
    }

    const TaskT& task_;
    const std::vector<task::TaskPart>& core_;
    const double solve_seconds_;
    const RelaxationOptions& options_;
    const run::Deadline deadline_;
    std::vector<Relaxation> out_;

private:
    Check check_;
    Attempt attempt_;
};

}  // namespace modsynth::explanation
