#include <modsynth/geometry/interval.h>
#include <modsynth/geometry/vec.h>

namespace modsynth::geometry {

namespace {

// libm's cos and sin are within an ulp or two of the exact value; the bound
// here is generous and still far below any length the proofs compare.
constexpr double kTrigSlack = 4e-16;

// Whether [lo, hi] holds a point phase + k * period for a whole k.
bool spans(double lo, double hi, double phase, double period) {
    const double k = std::ceil((lo - phase) / period);
    return phase + k * period <= hi;
}

}  // namespace

Interval sqr(const Interval& a) {
    if (a.is_empty()) return a;
    const double l = a.lo * a.lo;
    const double h = a.hi * a.hi;
    if (a.lo >= 0.0) return widen({l, h});
    if (a.hi <= 0.0) return widen({h, l});
    return {0.0, std::nextafter(std::max(l, h), std::numeric_limits<double>::infinity())};
}

Interval sqrt(const Interval& a) {
    if (a.is_empty() || a.hi < 0.0) return Interval::empty();
    return {std::max(0.0, std::nextafter(std::sqrt(std::max(a.lo, 0.0)), 0.0)),
            std::nextafter(std::sqrt(a.hi), std::numeric_limits<double>::infinity())};
}

Interval cos(const Interval& a) {
    if (a.is_empty()) return a;
    if (a.width() >= kTau) return {-1.0, 1.0};
    const double cl = std::cos(a.lo);
    const double ch = std::cos(a.hi);
    double lo = std::min(cl, ch) - kTrigSlack;
    double hi = std::max(cl, ch) + kTrigSlack;
    // A little slack on the extrema's positions keeps kPi's rounding harmless.
    if (spans(a.lo - 1e-15, a.hi + 1e-15, 0.0, kTau)) hi = 1.0;
    if (spans(a.lo - 1e-15, a.hi + 1e-15, kPi, kTau)) lo = -1.0;
    return {std::max(lo, -1.0), std::min(hi, 1.0)};
}

Interval sin(const Interval& a) {
    if (a.is_empty()) return a;
    return cos(a - Interval(kPi / 2));
}

}  // namespace modsynth::geometry
