#include <modsynth/run/deadline.h>

#include <algorithm>
#include <limits>

namespace modsynth::run {
namespace {

// Past this many seconds a limit means none: time_point's nanoseconds would
// overflow after about 292 years.
constexpr double kLongest = 1e9;

Deadline::Clock::duration span(double seconds) {
    return std::chrono::duration_cast<Deadline::Clock::duration>(
        std::chrono::duration<double>(seconds));
}

}  // namespace

Deadline Deadline::in(double seconds) {
    if (!(seconds < kLongest)) return never();
    return Deadline(Clock::now() + span(std::max(0.0, seconds)));
}

Deadline Deadline::cancelled_by(const CancelToken& token) const {
    return Deadline(when_, token.flag_);
}

double Deadline::remaining() const {
    if (cancelled()) return 0.0;
    if (is_never()) return std::numeric_limits<double>::infinity();
    return std::chrono::duration<double>(when_ - Clock::now()).count();
}

Deadline Deadline::within(double seconds) const { return earlier(*this, in(seconds)); }

Deadline Deadline::at_least(double seconds) const { return later(*this, in(seconds)); }

Deadline Deadline::reserve(double seconds) const {
    if (is_never() || !(seconds < kLongest)) return *this;
    return moved_to(when_ - span(seconds));
}

Deadline Deadline::share(double fraction) const {
    if (is_never()) return *this;
    const auto now = Clock::now();
    if (when_ <= now) return *this;
    return moved_to(now + span(std::clamp(fraction, 0.0, 1.0) *
                               std::chrono::duration<double>(when_ - now).count()));
}

}  // namespace modsynth::run
