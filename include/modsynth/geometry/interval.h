#pragma once
// Closed intervals of reals with outward rounding: every operation returns
// an interval that contains the exact result for every choice of operands,
// so a bound computed with them survives floating-point rounding. An
// interval with lo > hi (or a NaN bound) is empty.
#include <algorithm>
#include <cmath>
#include <limits>

namespace modsynth::geometry {

struct Interval {
    double lo = 0.0;
    double hi = 0.0;

    Interval() = default;
    Interval(double v) : lo(v), hi(v) {}  // NOLINT: a point is an interval
    Interval(double l, double h) : lo(l), hi(h) {}

    static Interval empty() {
        return {std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
    }
    bool is_empty() const { return !(lo <= hi); }
    double width() const { return hi - lo; }
    double mid() const { return 0.5 * (lo + hi); }
    double radius() const { return 0.5 * (hi - lo); }
    bool contains(double v) const { return lo <= v && v <= hi; }
};

/// One step outward: the bounds of an operation rounded to nearest lie
/// within one unit in the last place of the exact ones.
inline Interval widen(const Interval& a) {
    if (a.is_empty()) return a;
    return {std::nextafter(a.lo, -std::numeric_limits<double>::infinity()),
            std::nextafter(a.hi, std::numeric_limits<double>::infinity())};
}

inline Interval operator+(const Interval& a, const Interval& b) {
    if (a.is_empty() || b.is_empty()) return Interval::empty();
    return widen({a.lo + b.lo, a.hi + b.hi});
}
inline Interval operator-(const Interval& a, const Interval& b) {
    if (a.is_empty() || b.is_empty()) return Interval::empty();
    return widen({a.lo - b.hi, a.hi - b.lo});
}
inline Interval operator-(const Interval& a) { return {-a.hi, -a.lo}; }
inline Interval operator*(const Interval& a, const Interval& b) {
    if (a.is_empty() || b.is_empty()) return Interval::empty();
    const double p[] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
    return widen({*std::min_element(p, p + 4), *std::max_element(p, p + 4)});
}

/// Intersection (may be empty) and hull (the smallest interval holding both).
inline Interval intersect(const Interval& a, const Interval& b) {
    return {std::max(a.lo, b.lo), std::min(a.hi, b.hi)};
}
inline Interval hull(const Interval& a, const Interval& b) {
    if (a.is_empty()) return b;
    if (b.is_empty()) return a;
    return {std::min(a.lo, b.lo), std::max(a.hi, b.hi)};
}

/// x^2 over a, tight (0 when a holds 0).
Interval sqr(const Interval& a);
/// sqrt over the non-negative part of a (empty when a is negative).
Interval sqrt(const Interval& a);
/// cos and sin over a: the extrema a spans are included.
Interval cos(const Interval& a);
Interval sin(const Interval& a);

}  // namespace modsynth::geometry
