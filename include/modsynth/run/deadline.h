#pragma once
// When a run must stop, as one value handed down the stages (after OMPL's
// PlannerTerminationCondition): a stage asks how much is left, gives a step
// its own budget within what is left, or keeps a reserve for what must
// follow the step. A default Deadline never expires.
//
// A deadline may also carry a CancelToken: once it is cancelled the
// deadline has expired, with nothing remaining, and so has every deadline
// derived from it (within, reserve, share, at_least, earlier, later). The
// stages poll expired() and remaining() already, so cancellation needs no
// second mechanism.
#include <atomic>
#include <chrono>
#include <memory>

#include <modsynth/run/cancel.h>

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

    /// This deadline, also expired once `token` is cancelled.
    Deadline cancelled_by(const CancelToken& token) const;
    bool cancelled() const { return cancel_ && cancel_->load(std::memory_order_relaxed); }
    /// Whether a token may cancel it (what a blocking call that cannot
    /// poll, such as a Z3 check, needs a watcher for).
    bool can_be_cancelled() const { return cancel_ != nullptr; }

    /// No time limit (a cancel token may still end it).
    bool is_never() const { return when_ == Clock::time_point::max(); }
    bool expired() const { return cancelled() || (!is_never() && Clock::now() >= when_); }
    /// Seconds left (0 or less once expired or cancelled); infinity for never.
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

    /// The earlier time; cancelled when either one is.
    friend Deadline earlier(const Deadline& a, const Deadline& b) {
        return (a.when_ <= b.when_ ? a : b).with_cancel_of(a, b);
    }
    /// The later time; cancelled when either one is (a cancel is never
    /// postponed).
    friend Deadline later(const Deadline& a, const Deadline& b) {
        return (a.when_ >= b.when_ ? a : b).with_cancel_of(a, b);
    }

private:
    using Flag = std::shared_ptr<const std::atomic<bool>>;
    Deadline(Clock::time_point when, Flag cancel) : when_(when), cancel_(std::move(cancel)) {}
    explicit Deadline(Clock::time_point when) : when_(when) {}
    Deadline moved_to(Clock::time_point when) const { return Deadline(when, cancel_); }
    /// This time with a token of a or b (a's first); two different tokens
    /// are not combined, which no caller needs.
    Deadline with_cancel_of(const Deadline& a, const Deadline& b) const {
        return Deadline(when_, a.cancel_ ? a.cancel_ : b.cancel_);
    }

    Clock::time_point when_ = Clock::time_point::max();
    Flag cancel_;
};

}  // namespace modsynth::run
