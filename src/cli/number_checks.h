#pragma once
// Checks of numeric command-line options. CLI11's own (PositiveNumber,
// Range) compare with < and >, which NaN passes, and let infinity through:
// every number an option takes must be finite, and a duration must also be
// one a deadline and a solver timeout can hold.
#include <cmath>
#include <string>

#include <CLI/CLI.hpp>

#include <modsynth/task/task.h>
#include <modsynth/text/format.h>
#include <modsynth/text/printable.h>

namespace modsynth::app {

/// Longest time limit accepted, in seconds (a week).
constexpr double kMaxSeconds = 7 * 24 * 3600.0;

/// A finite number in [lo, hi]; `open_lo` excludes lo itself.
inline CLI::Validator finite_in(double lo, double hi, bool open_lo, const std::string& name) {
    return CLI::Validator(
        [=](std::string& input) -> std::string {
            double v = 0.0;
            if (!CLI::detail::lexical_cast(input, v) || !std::isfinite(v))
                return "expected a finite number, got '" + text::printable(input) + "'";
            if (open_lo ? v <= lo : v < lo)
                return text::format("must be %s %g, got %g", open_lo ? "greater than" : "at least",
                                    lo, v);
            if (v > hi) return text::format("must be at most %g, got %g", hi, v);
            return {};
        },
        name);
}

/// Seconds: positive, finite, at most kMaxSeconds.
inline CLI::Validator seconds() { return finite_in(0.0, kMaxSeconds, true, "SECONDS"); }
/// Seconds that may be 0 (a grace period).
inline CLI::Validator seconds_or_zero() { return finite_in(0.0, kMaxSeconds, false, "SECONDS"); }
/// A positive finite number (a speed).
inline CLI::Validator positive() { return finite_in(0.0, 1e9, true, "POSITIVE"); }
/// A speed cap beside the joint limits (m/s or rad/s): within the range a
/// joint limit may take (task::kMinJointLimit to kMaxJointLimit).
inline CLI::Validator speed() {
    return finite_in(task::kMinJointLimit, task::kMaxJointLimit, false, "SPEED");
}
/// A finite number in [lo, hi].
inline CLI::Validator within(double lo, double hi) { return finite_in(lo, hi, false, "NUMBER"); }

}  // namespace modsynth::app
