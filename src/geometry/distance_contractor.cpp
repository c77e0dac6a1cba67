#include <modsynth/geometry/distance_contractor.h>

namespace modsynth::geometry {

bool contract_sqr(Interval& x, const Interval& s) {
    const Interval root = sqrt(s);
    if (root.is_empty()) return false;
    const Interval pos = intersect(x, root);
    const Interval neg = intersect(x, -root);
    x = hull(pos.is_empty() ? Interval::empty() : pos, neg.is_empty() ? Interval::empty() : neg);
    return !x.is_empty();
}

bool contract_distance(IntervalPoint& a, IntervalPoint& b, Interval& r) {
    r = intersect(r, Interval(0.0, std::numeric_limits<double>::infinity()));
    if (a.is_empty() || b.is_empty() || r.is_empty()) return false;
    // Forward: dx = ax - bx, dy = ay - by, s = dx^2 + dy^2, and s = r^2.
    Interval dx = a.x - b.x;
    Interval dy = a.y - b.y;
    Interval sx = sqr(dx);
    Interval sy = sqr(dy);
    Interval s = intersect(sx + sy, sqr(r));
    if (s.is_empty()) return false;
    // Backward, node by node down to the leaves.
    r = intersect(r, sqrt(s));
    sx = intersect(sx, s - sy);
    sy = intersect(sy, s - sx);
    if (r.is_empty() || sx.is_empty() || sy.is_empty()) return false;
    if (!contract_sqr(dx, sx) || !contract_sqr(dy, sy)) return false;
    a.x = intersect(a.x, b.x + dx);
    a.y = intersect(a.y, b.y + dy);
    b.x = intersect(b.x, a.x - dx);
    b.y = intersect(b.y, a.y - dy);
    return !a.is_empty() && !b.is_empty();
}

}  // namespace modsynth::geometry
