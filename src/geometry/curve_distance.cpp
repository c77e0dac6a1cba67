#include <modsynth/geometry/curve_distance.h>

#include <algorithm>
#include <cmath>
#include <queue>
#include <vector>

#include <modsynth/geometry/distance3.h>
#include <modsynth/geometry/vec.h>

namespace modsynth::geometry {
namespace {

/// Evaluations a search may spend before it answers with the best point
/// found (which is still a point of the primitive).
constexpr int kMaxEvaluations = 200'000;

/// A stretch [s0, s1] of the primitive with the distances at its ends and a
/// bound on the distance inside it (below for the least, above for the
/// largest).
struct Node {
    double s0, s1, d0, d1, bound;
};

/// h = d^2 along a unit-speed curve of curvature k has h'' <= 2 + 2 k d (the
/// Hessian of the squared distance to a convex set is at most 2 I, and its
/// gradient, of length 2 d, meets the curve's acceleration, of length k), so
/// h lies above its chord minus (2 + 2 k dmax) / 2 t (w - t); and d is
/// 1-Lipschitz in s.
double lower_bound(double w, double d0, double d1, double curvature) {
    if (!(w > 0.0)) return std::min(d0, d1);
    const double lipschitz = 0.5 * (d0 + d1 - w);
    const double m = 2.0 + 2.0 * curvature * 0.5 * (d0 + d1 + w);
    const double h0 = d0 * d0, h1 = d1 * d1;
    const double t = std::clamp(0.5 * w - (h1 - h0) / (m * w), 0.0, w);
    const double q = h0 + (h1 - h0) * t / w - 0.5 * m * t * (w - t);
    return std::max({0.0, lipschitz, std::sqrt(std::max(q, 0.0))});
}

/// h'' >= -2 k d, so h lies below its chord plus k dmax t (w - t).
double upper_bound(double w, double d0, double d1, double curvature) {
    if (!(w > 0.0)) return std::max(d0, d1);
    const double lipschitz = 0.5 * (d0 + d1 + w);
    const double m = 2.0 * curvature * lipschitz;
    const double h0 = d0 * d0, h1 = d1 * d1;
    const double t =
        m > 0.0 ? std::clamp(0.5 * w + (h1 - h0) / (m * w), 0.0, w) : (h1 > h0 ? w : 0.0);
    const double q = h0 + (h1 - h0) * t / w + 0.5 * m * t * (w - t);
    return std::min(lipschitz, std::sqrt(std::max(q, 0.0)));
}

enum class Goal { Least, Largest, Within };

/// Branch and bound over arc length. Least: smallest bound first, stop when
/// no stretch can beat the best point by more than `tolerance`. Largest: the
/// mirror image. Within: least, stopping as soon as the answer to "is the
/// least distance <= gap" is known (`within` receives it).
CurvePoint3 search(const Primitive3& p, const ConvexDistance& distance, Goal goal, double tolerance,
                   double gap = 0.0, bool* within = nullptr) {
    const double len = length(p);
    const double curvature = max_curvature(p);
    const bool largest = goal == Goal::Largest;
    CurvePoint3 best{0.0, point_at(p, 0.0), 0.0};
    best.distance = distance(best.point);
    int evaluations = 1;
    auto evaluate = [&](double s) {
        const Vec3 x = point_at(p, s);
        const double d = distance(x);
        ++evaluations;
        if (largest ? d > best.distance : d < best.distance) best = {s, x, d};
        return d;
    };
    auto bound = [&](double s0, double s1, double d0, double d1) {
        return largest ? upper_bound(s1 - s0, d0, d1, curvature)
                       : lower_bound(s1 - s0, d0, d1, curvature);
    };
    auto order = [&](const Node& a, const Node& b) {
        return largest ? a.bound < b.bound : a.bound > b.bound;
    };
    std::priority_queue<Node, std::vector<Node>, decltype(order)> open(order);
    // Worth splitting: might beat the best by more than the tolerance (or,
    // deciding "within", might still hold a point within the gap).
    auto promising = [&](double b) {
        if (goal == Goal::Within) return b <= gap + 1e-12;
        return largest ? b > best.distance + tolerance : b < best.distance - tolerance;
    };
    auto decided = [&] { return goal == Goal::Within && best.distance <= gap + 1e-12; };
    // Eight pieces per full turn at least, so that every stretch is nearly
    // straight before any bound is used.
    const int pieces =
        static_cast<int>(std::clamp(std::ceil(len * curvature * 8.0 / kTau), 4.0, 65536.0));
    double s_prev = 0.0, d_prev = best.distance;
    for (int i = 1; i <= pieces && !decided(); ++i) {
        const double s = i == pieces ? len : len * i / pieces;
        const double d = evaluate(s);
        const double b = bound(s_prev, s, d_prev, d);
        if (promising(b)) open.push({s_prev, s, d_prev, d, b});
        s_prev = s, d_prev = d;
    }
    while (!open.empty() && !decided() && evaluations < kMaxEvaluations) {
        const Node n = open.top();
        open.pop();
        if (!promising(n.bound)) break;  // the best of the rest cannot do better
        const double s = 0.5 * (n.s0 + n.s1);
        if (!(s > n.s0 && s < n.s1)) continue;
        const double d = evaluate(s);
        for (const Node c : {Node{n.s0, s, n.d0, d, 0.0}, Node{s, n.s1, d, n.d1, 0.0}}) {
            const double b = bound(c.s0, c.s1, c.d0, c.d1);
            if (promising(b)) open.push({c.s0, c.s1, c.d0, c.d1, b});
        }
    }
    if (within) *within = best.distance <= gap + 1e-12;
    return best;
}

}  // namespace

CurvePoint3 least_distance(const Primitive3& p, const ConvexDistance& distance, double tolerance) {
    return search(p, distance, Goal::Least, tolerance);
}

CurvePoint3 largest_distance(const Primitive3& p, const ConvexDistance& distance,
                             double tolerance) {
    if (const auto* line = std::get_if<Line3>(&p)) {
        const double d0 = distance(line->start), d1 = distance(line->end);
        return d1 > d0 ? CurvePoint3{length(p), line->end, d1} : CurvePoint3{0.0, line->start, d0};
    }
    return search(p, distance, Goal::Largest, tolerance);
}

bool comes_within(const Primitive3& p, const ConvexDistance& distance, double gap) {
    bool within = false;
    search(p, distance, Goal::Within, 0.0, gap, &within);
    return within;
}

CurvePoint3 least_distance_to_box(const Primitive3& p, const Box3& box) {
    if (const auto* line = std::get_if<Line3>(&p)) {
        double t = 0.0;
        const double d = segment_box(line->start, line->end, box, &t);
        const double s = t * length(p);
        return {s, point_at(p, s), d};
    }
    return least_distance(p, [&](const Vec3& x) { return point_box(x, box); });
}

CurvePoint3 largest_distance_to_box(const Primitive3& p, const Box3& box) {
    return largest_distance(p, [&](const Vec3& x) { return point_box(x, box); });
}

}  // namespace modsynth::geometry
