#include <modsynth/nlp/progress_watch.h>

#include <algorithm>

#include <modsynth/text/format.h>
#include <modsynth/text/option_check.h>

namespace modsynth::nlp {

bool ProgressWatchOptions::IsValid(std::string* error) const {
    return text::OptionCheck("ProgressWatchOptions", error)
        .greater("diverging_dual", diverging_dual, 0.0)
        .greater("stalled_primal", stalled_primal, 0.0)
        .at_least("stall_window", stall_window, 1)
        .greater("flat_ratio", flat_ratio, 1.0)
        .at_least("diverging_window", diverging_window, 1)
        .at_least("min_variables", min_variables, 0)
        .ok();
}

ProgressWatch::ProgressWatch(ProgressWatchOptions options) : o_(options) {
    text::require_valid(o_);
}

void ProgressWatch::observe(int iteration, double primal, double dual) {
    if (!reason_.empty()) return;
    window_.push_back(primal);
    if (static_cast<int>(window_.size()) > o_.stall_window + 1) window_.pop_front();
    if (static_cast<int>(window_.size()) == o_.stall_window + 1) {
        const auto [lo, hi] = std::minmax_element(window_.begin(), window_.end());
        if (*lo > o_.stalled_primal && *hi <= o_.flat_ratio * *lo) {
            reason_ = text::format(
                "stalled: primal infeasibility between %.3g and %.3g for %d iterations", *lo, *hi,
                o_.stall_window);
            return;
        }
    }
    if (dual <= o_.diverging_dual) {
        diverging_since_ = -1;
        return;
    }
    if (diverging_since_ < 0) {
        diverging_since_ = iteration;
        primal_then_ = primal;
    } else if (iteration - diverging_since_ >= o_.diverging_window && primal > o_.stalled_primal &&
               primal > 0.5 * primal_then_) {
        reason_ = text::format(
            "diverging: dual infeasibility %.3g, primal infeasibility %.3g not halved in %d "
            "iterations",
            dual, primal, iteration - diverging_since_);
    }
}

}  // namespace modsynth::nlp
