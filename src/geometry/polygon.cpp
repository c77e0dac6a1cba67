#include <modsynth/geometry/distance.h>
#include <modsynth/geometry/polygon.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace modsynth::geometry {

namespace {

// Relative slack for boundary points: rounding in the vertices and in p must
// not push a point on an edge outside.
constexpr double kRelTol = 1e-12;

bool lex_less(const Vec2& a, const Vec2& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
}

// Whether p is on the inner side of edge a -> b (or on it, within tolerance).
bool inside_edge(const Vec2& p, const Vec2& a, const Vec2& b) {
    const Vec2 e = b - a;
    const Vec2 w = p - a;
    const double c = cross(e, w);
    if (c >= 0.0) return true;
    return c >= -kRelTol * e.norm() * (e.norm() + w.norm());
}

bool on_point(const Vec2& p, const Vec2& a) {
    const double scale = std::max(p.lpNorm<Eigen::Infinity>(), a.lpNorm<Eigen::Infinity>());
    return (p - a).norm() <= kRelTol * scale;
}

bool on_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
    return point_segment(p, a, b) <= kRelTol * ((b - a).norm() + (p - a).norm());
}

}  // namespace

std::vector<Vec2> convex_hull(std::vector<Vec2> points) {
    std::sort(points.begin(), points.end(), lex_less);
    points.erase(std::unique(points.begin(), points.end()), points.end());
    const std::size_t n = points.size();
    if (n < 3) return points;
    std::vector<Vec2> hull(2 * n);
    std::size_t k = 0;
    // Popping on cross <= 0 drops collinear points along with reflex ones.
    for (std::size_t i = 0; i < n; ++i) {
        while (k >= 2 && cross(hull[k - 1] - hull[k - 2], points[i] - hull[k - 2]) <= 0.0) --k;
        hull[k++] = points[i];
    }
    for (std::size_t i = n - 1, lower = k + 1; i-- > 0;) {
        while (k >= lower && cross(hull[k - 1] - hull[k - 2], points[i] - hull[k - 2]) <= 0.0) --k;
        hull[k++] = points[i];
    }
    // The last point repeats the first.
    hull.resize(k - 1);
    return hull;
}

bool point_in_convex_polygon(const Vec2& p, const std::vector<Vec2>& polygon) {
    const std::size_t n = polygon.size();
    if (n == 0) return false;
    if (n == 1) return on_point(p, polygon[0]);
    if (n == 2) return on_segment(p, polygon[0], polygon[1]);
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
        if (!inside_edge(p, polygon[j], polygon[i])) return false;
    }
    return true;
}

double segment_convex_polygon(const Vec2& a, const Vec2& b, const std::vector<Vec2>& polygon) {
    if (point_in_convex_polygon(a, polygon) || point_in_convex_polygon(b, polygon)) return 0.0;
    if (polygon.size() == 1) return point_segment(polygon[0], a, b);
    double d = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < polygon.size(); ++i)
        d = std::min(d, segment_segment(a, b, polygon[i], polygon[(i + 1) % polygon.size()]));
    return d;
}

double point_convex_polygon(const Vec2& p, const std::vector<Vec2>& polygon) {
    const std::size_t n = polygon.size();
    if (n == 0) return std::numeric_limits<double>::infinity();
    if (n == 1) return (p - polygon[0]).norm();
    if (n == 2) return point_segment(p, polygon[0], polygon[1]);
    if (point_in_convex_polygon(p, polygon)) return 0.0;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
        best = std::min(best, point_segment(p, polygon[j], polygon[i]));
    }
    return best;
}

double disc_convex_polygon(const Vec2& center, double radius, const std::vector<Vec2>& polygon) {
    return std::max(0.0, point_convex_polygon(center, polygon) - radius);
}

}  // namespace modsynth::geometry

namespace modsynth::geometry {

int winding_number(const std::vector<Vec2>& polygon, const Vec2& p) {
    // Signed crossings of the horizontal ray from p to +x (Sunday's
    // algorithm): orientation signs only, no angles.
    int w = 0;
    const std::size_t n = polygon.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2& a = polygon[i];
        const Vec2& b = polygon[(i + 1) % n];
        const double side = cross(b - a, p - a);
        if (a.y() <= p.y()) {
            if (b.y() > p.y() && side > 0.0) ++w;
        } else if (b.y() <= p.y() && side < 0.0) {
            --w;
        }
    }
    return w;
}

}  // namespace modsynth::geometry
