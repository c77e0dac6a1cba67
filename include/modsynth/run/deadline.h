#pragma once
// When a run must stop, as one value handed down the stages (after OMPL's
// PlannerTerminationCondition): a stage asks how much is left, gives a step
// its own budget within what is left, or keeps a reserve for what must
// follow the step. A default Deadline never expires.
#include <chrono>

namespace modsynth::run {

class Deadline {
public:
    using Clock = std::chrono::steady_clock;

    /// Never expires: remaining() is infinite.
    Deadline() = default;
    static Deadline never() { return {}; }
    /// `seconds` from now (0 or less: already expired). Limits of 1e9 s and
    /// more (decades) mean none, so the clock's arithmetic cannot overflow.
    static Deadline in(double seconds);
    static Deadline at(Clock::time_point when) { return Deadline(when); }

    bool is_never() const { return when_ == Clock::time_point::max(); }
    bool expired() const { return !is_never() && Clock::now() >= when_; }
    /// Seconds left (0 or less once expired); infinity for never.
    double remaining() const;
    /// The earlier of this deadline and `seconds` from now: a step's own
    /// budget inside the run's.
    Deadline within(double seconds) const;
    /// This deadline moved `seconds` earlier: time kept back for what must
    /// come after the step (never stays never).
    Deadline reserve(double seconds) const;
    /// A `fraction` (0 to 1) of the time left now.
    Deadline share(double fraction) const;
    /// The later of this deadline and `seconds` from now: a step once
    /// started gets at least that long.
    Deadline at_least(double seconds) const;
    Clock::time_point when() const { return when_; }

    friend Deadline earlier(const Deadline& a, const Deadline& b) {
        return a.when_ <= b.when_ ? a : b;
    }
    friend Deadline later(const Deadline& a, const Deadline& b) {
        return a.when_ >= b.when_ ? a : b;
    }

private:
    explicit Deadline(Clock::time_point when) : when_(when) {}
    Clock::time_point when_ = Clock::time_point::max();
};

}  // namespace modsynth::run
