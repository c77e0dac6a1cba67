#pragma once
// How long an import may take: a point in time past which reading and
// fitting a drawing stop, so that an import returns within its time limit
// whatever the file holds.
#include <chrono>
#include <stdexcept>
#include <string>

namespace modsynth::drawing {

using Clock = std::chrono::steady_clock;

/// No time limit.
constexpr Clock::time_point kNoDeadline = Clock::time_point::max();

/// The import ran out of time; what() says what it was doing.
class ImportTimeout : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// Throws ImportTimeout saying it was `doing` that (e.g. "fitting path#p3
/// (line 12)") once `deadline` has passed.
inline void check_deadline(Clock::time_point deadline, const std::string& doing) {
    if (deadline != kNoDeadline && Clock::now() >= deadline)
        throw ImportTimeout("the time limit was reached while " + doing);
}

}  // namespace modsynth::drawing
