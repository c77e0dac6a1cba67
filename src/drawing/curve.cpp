#include <modsynth/drawing/curve.h>

#include <algorithm>
#include <cmath>

namespace modsynth::drawing {

namespace {

template <class... F>
struct Overload : F... {
    using F::operator()...;
};
template <class... F>
Overload(F...) -> Overload<F...>;

/// De Boor's algorithm in homogeneous coordinates (x w, y w, w), so that
/// rational splines (DXF weights) evaluate exactly.
Vec2 spline_point(const BSpline& b, double t) {
    const int p = b.degree;
    const int n = static_cast<int>(b.control.size());
    const double lo = b.knots[p], hi = b.knots[n];
    const double x = lo + std::clamp(t, 0.0, 1.0) * (hi - lo);
    // The knot span k with knots[k] <= x < knots[k+1], p <= k < n.
    int k =
        static_cast<int>(std::upper_bound(b.knots.begin(), b.knots.end(), x) - b.knots.begin()) - 1;
    k = std::clamp(k, p, n - 1);
    std::vector<Eigen::Vector3d> d(p + 1);
    for (int j = 0; j <= p; ++j) {
        const int i = j + k - p;
        const double w = b.weights[i];
        d[j] = Eigen::Vector3d(b.control[i].x() * w, b.control[i].y() * w, w);
    }
    for (int r = 1; r <= p; ++r) {
        for (int j = p; j >= r; --j) {
            const double left = b.knots[j + k - p], right = b.knots[j + 1 + k - r];
            const double alpha = right > left ? (x - left) / (right - left) : 0.0;
            d[j] = (1.0 - alpha) * d[j - 1] + alpha * d[j];
        }
    }
    return Vec2(d[p].x() / d[p].z(), d[p].y() / d[p].z());
}

}  // namespace

Vec2 point(const Segment& s, double t) {
    return std::visit(Overload{[t](const LineSegment& l) -> Vec2 { return l.a + t * (l.b - l.a); },
                               [t](const CubicBezier& c) -> Vec2 {
                                   const double u = 1.0 - t;
                                   return u * u * u * c.p0 + 3.0 * u * u * t * c.p1 +
                                          3.0 * u * t * t * c.p2 + t * t * t * c.p3;
                               },
                               [t](const EllipticArc& e) -> Vec2 {
                                   const double a = e.t0 + t * (e.t1 - e.t0);
                                   return e.center + std::cos(a) * e.u + std::sin(a) * e.v;
                               },
                               [t](const BSpline& b) -> Vec2 { return spline_point(b, t); }},
                      s);
}

Vec2 derivative(const Segment& s, double t) {
    return std::visit(Overload{[](const LineSegment& l) -> Vec2 { return l.b - l.a; },
                               [t](const CubicBezier& c) -> Vec2 {
                                   const double u = 1.0 - t;
                                   return 3.0 * u * u * (c.p1 - c.p0) +
                                          6.0 * u * t * (c.p2 - c.p1) + 3.0 * t * t * (c.p3 - c.p2);
                               },
                               [t](const EllipticArc& e) -> Vec2 {
                                   const double a = e.t0 + t * (e.t1 - e.t0);
                                   return (e.t1 - e.t0) * (-std::sin(a) * e.u + std::cos(a) * e.v);
                               },
                               [&s, t](const BSpline&) -> Vec2 {
                                   // One-sided near the ends, central inside: the spline
                                   // is only C^(degree-1) at its knots.
                                   constexpr double h = 1e-7;
                                   const double a = std::max(0.0, t - h), b = std::min(1.0, t + h);
                                   return (point(s, b) - point(s, a)) / (b - a);
                               }},
                      s);
}

Vec2 start_point(const Segment& s) {
    if (const auto* l = std::get_if<LineSegment>(&s)) return l->a;
    if (const auto* c = std::get_if<CubicBezier>(&s)) return c->p0;
    return point(s, 0.0);
}

Vec2 end_point(const Segment& s) {
    if (const auto* l = std::get_if<LineSegment>(&s)) return l->b;
    if (const auto* c = std::get_if<CubicBezier>(&s)) return c->p3;
    return point(s, 1.0);
}

Segment transformed(const Segment& s, const Affine& a) {
    return std::visit(
        Overload{[&a](const LineSegment& l) -> Segment {
                     return LineSegment{a(l.a), a(l.b)};
                 },
                 [&a](const CubicBezier& c) -> Segment {
                     return CubicBezier{a(c.p0), a(c.p1), a(c.p2), a(c.p3)};
                 },
                 [&a](const EllipticArc& e) -> Segment {
                     return EllipticArc{a(e.center), a.m * e.u, a.m * e.v, e.t0, e.t1};
                 },
                 [&a](const BSpline& b) -> Segment {
                     BSpline out = b;
                     for (Vec2& p : out.control) p = a(p);
                     return out;
                 }},
        s);
}

bool is_circular(const EllipticArc& e) {
    const double scale = std::max(e.u.squaredNorm(), e.v.squaredNorm());
    return std::abs(e.u.dot(e.v)) <= 1e-12 * scale &&
           std::abs(e.u.squaredNorm() - e.v.squaredNorm()) <= 1e-12 * scale;
}

double approximate_length(const Segment& s, int pieces) {
    double total = 0.0;
    Vec2 prev = point(s, 0.0);
    for (int i = 1; i <= pieces; ++i) {
        const Vec2 next = point(s, static_cast<double>(i) / pieces);
        total += (next - prev).norm();
        prev = next;
    }
    return total;
}

}  // namespace modsynth::drawing
