#include <modsynth/geometry/farthest_reach.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <stdexcept>

namespace modsynth::geometry {
namespace {

struct Value {
    double f = 0.0;
    Vec2 gradient = Vec2::Zero();  ///< a subgradient of F at the point
};

Value farthest_reach(const std::vector<Primitive>& path, const Vec2& b) {
    Value v;
    v.f = -1.0;
    for (const Primitive& p : path) {
        const NearestPoint q = farthest(p, b);
        if (q.distance > v.f) {
            v.f = q.distance;
            v.gradient = q.distance > 0.0 ? Vec2((b - q.point) / q.distance) : Vec2::Zero();
        }
    }
    return v;
}

struct Cell {
    Vec2 center;
    Vec2 half;     ///< half-widths
    double bound;  ///< F >= bound everywhere in the cell
    bool operator>(const Cell& o) const { return bound > o.bound; }
};

}  // namespace

// Branch and bound over the box. A cell's bound comes from the supporting
// plane at its centre c: F(b) >= F(c) + g.(b - c) >= F(c) - |g_x| h_x - |g_y| h_y,
// which for a convex F holds over the cell, and is tighter than the
// Lipschitz bound F(c) - |h| wherever the farthest point is not straight
// along the cell's diagonal.
FarthestReach least_farthest_reach(const std::vector<Primitive>& path, const Vec2& lo,
                                   const Vec2& hi, const FarthestReachOptions& options) {
    if (path.empty()) throw std::invalid_argument("least_farthest_reach: the path is empty");
    if (!(lo.x() <= hi.x() && lo.y() <= hi.y()))
        throw std::invalid_argument("least_farthest_reach: the box is empty");
    FarthestReach out;
    out.upper = std::numeric_limits<double>::infinity();
    const int max_evaluations = static_cast<int>(
        std::min(static_cast<double>(options.max_evaluations),
                 std::max(16.0, options.max_visits / static_cast<double>(path.size()))));
    int evaluations = 0;
    // F is computed in floating point; a relative margin keeps the bound a
    // bound after rounding.
    const auto slack = [](double f) { return 1e-12 * (1.0 + f); };
    const auto make = [&](const Vec2& center, const Vec2& half, double inherited) {
        const Value v = farthest_reach(path, center);
        ++evaluations;
        if (v.f < out.upper) {
            out.upper = v.f;
            out.at = center;
        }
        const double plane = v.f - std::abs(v.gradient.x()) * half.x() -
                             std::abs(v.gradient.y()) * half.y() - slack(v.f);
        return Cell{center, half, std::max(inherited, plane)};
    };
    std::priority_queue<Cell, std::vector<Cell>, std::greater<>> open;
    open.push(make(0.5 * (lo + hi), 0.5 * (hi - lo), 0.0));
    while (true) {
        const Cell cell = open.top();
        // The cell of least bound bounds every other one too.
        out.lower = std::max(0.0, cell.bound);
        if (cell.bound >= out.upper - options.tolerance || evaluations + 4 > max_evaluations ||
            (cell.half.x() == 0.0 && cell.half.y() == 0.0))
            return out;
        open.pop();
        // Halve the wider side (both when they are alike): cells stay square-ish.
        const bool split_x = cell.half.x() >= 0.5 * cell.half.y();
        const bool split_y = cell.half.y() >= 0.5 * cell.half.x();
        const Vec2 half(split_x ? 0.5 * cell.half.x() : cell.half.x(),
                        split_y ? 0.5 * cell.half.y() : cell.half.y());
        for (int i = 0; i < (split_x ? 2 : 1); ++i)
            for (int j = 0; j < (split_y ? 2 : 1); ++j) {
                const Vec2 offset(split_x ? (i ? half.x() : -half.x()) : 0.0,
                                  split_y ? (j ? half.y() : -half.y()) : 0.0);
                open.push(make(cell.center + offset, half, cell.bound));
            }
    }
}

// The least enclosing circle's centre lies in the path's convex hull, so in
// any box around the path; arcs are boxed by their whole circle.
FarthestReach least_farthest_reach(const std::vector<Primitive>& path,
                                   const FarthestReachOptions& options) {
    if (path.empty()) throw std::invalid_argument("least_farthest_reach: the path is empty");
    Vec2 lo = path.front().start, hi = lo;
    for (const Primitive& p : path) {
        lo = lo.cwiseMin(p.start).cwiseMin(p.end);
        hi = hi.cwiseMax(p.start).cwiseMax(p.end);
        switch (p.kind) {
            case PrimitiveKind::Line:
                break;
            case PrimitiveKind::Arc:
            case PrimitiveKind::Circle: {
                const Vec2 r(p.radius, p.radius);
                lo = lo.cwiseMin(p.center - r);
                hi = hi.cwiseMax(p.center + r);
                break;
            }
        }
    }
    return least_farthest_reach(path, lo, hi, options);
}

}  // namespace modsynth::geometry
