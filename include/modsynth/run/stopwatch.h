#pragma once
// Seconds since a start, for the figures a run reports (how long each stage
// took); deadlines are run::Deadline.
#include <chrono>

namespace modsynth::run {

class Stopwatch {
public:
    using Clock = std::chrono::steady_clock;

    Stopwatch() : start_(Clock::now()) {}
    double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }
    Clock::time_point started() const { return start_; }

private:
    Clock::time_point start_;
};

}  // namespace modsynth::run
