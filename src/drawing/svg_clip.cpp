#include "svg_clip.h"

#include <algorithm>
#include <cmath>
#include <variant>

#include <modsynth/task/input_error.h>

namespace modsynth::drawing::svg_clip {

namespace {

constexpr int kCurveChords = 256;

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

double distance_to_edge(const Vec2& p, const Vec2& a, const Vec2& b) {
    const Vec2 d = b - a;
    const double len2 = d.squaredNorm();
    const double u = len2 > 0.0 ? std::clamp((p - a).dot(d) / len2, 0.0, 1.0) : 0.0;
    return (p - (a + u * d)).norm();
}

bool inside(const Shape& shape, const Vec2& p, double margin) {
    int winding = 0, crossings = 0;
    for (const auto& ring : shape.rings) {
        for (std::size_t i = 0; i < ring.size(); ++i) {
            const Vec2& a = ring[i];
            const Vec2& b = ring[(i + 1) % ring.size()];
            if (distance_to_edge(p, a, b) <= margin) return true;
            if ((a.y() <= p.y()) != (b.y() <= p.y())) {
                const double side = cross(b - a, p - a);
                if (b.y() > a.y() && side > 0.0) ++winding, ++crossings;
                if (b.y() <= a.y() && side < 0.0) --winding, ++crossings;
            }
        }
    }
    return shape.even_odd ? crossings % 2 == 1 : winding != 0;
}

/// The segment between parameters t0 < t1, as a segment of its own kind.
Segment piece(const Segment& s, double t0, double t1, const std::string& source) {
    if (std::holds_alternative<LineSegment>(s)) return LineSegment{point(s, t0), point(s, t1)};
    if (const auto* e = std::get_if<EllipticArc>(&s)) {
        EllipticArc out = *e;
        out.t0 = e->t0 + t0 * (e->t1 - e->t0);
        out.t1 = e->t0 + t1 * (e->t1 - e->t0);
        return out;
    }
    if (const auto* c = std::get_if<CubicBezier>(&s)) {
        // De Casteljau: the part before t1, then that part's after t0 / t1.
        const auto split_before = [](const CubicBezier& b, double t) {
            const Vec2 a = b.p0 + t * (b.p1 - b.p0), m = b.p1 + t * (b.p2 - b.p1),
                       d = b.p2 + t * (b.p3 - b.p2);
            const Vec2 ab = a + t * (m - a), md = m + t * (d - m);
            return CubicBezier{b.p0, a, ab, ab + t * (md - ab)};
        };
        const auto split_after = [](const CubicBezier& b, double t) {
            const Vec2 a = b.p0 + t * (b.p1 - b.p0), m = b.p1 + t * (b.p2 - b.p1),
                       d = b.p2 + t * (b.p3 - b.p2);
            const Vec2 ab = a + t * (m - a), md = m + t * (d - m);
            return CubicBezier{ab + t * (md - ab), md, d, b.p3};
        };
        const CubicBezier before = split_before(*c, t1);
        return t1 > 0.0 ? split_after(before, t0 / t1) : before;
    }
    // SVG draws no splines; a reader that did would have to clip them too.
    throw task::InputError(source, "a spline cannot be clipped");
}

/// Each test of a point against a large region takes as long as its edges:
/// the deadline is asked before each.
void stop_at(Clock::time_point deadline, const Curve& curve) {
    if (deadline != kNoDeadline && Clock::now() >= deadline)
        throw ImportTimeout("the time limit was reached while clipping " + curve.source);
}

}  // namespace

bool inside(const Region& region, const Vec2& p) {
    for (const Shape& s : region.shapes) {
        if (inside(s, p, region.margin)) return true;
    }
    return false;
}

void flatten(const Segment& s, std::vector<Vec2>& ring) {
    if (const auto* l = std::get_if<LineSegment>(&s)) {
        ring.push_back(l->b);
        return;
    }
    for (int i = 1; i <= kCurveChords; ++i) ring.push_back(point(s, double(i) / kCurveChords));
}

std::vector<Curve> clipped(const Curve& curve, const Region& region, Clock::time_point deadline) {
    std::vector<Curve> out;
    Curve current{curve.source, {}};
    const auto close = [&] {
        if (!current.segments.empty()) out.push_back(std::move(current));
        current = Curve{curve.source, {}};
    };
    for (const Segment& s : curve.segments) {
        const bool line = std::holds_alternative<LineSegment>(s);
        const int chords = line ? 1 : kCurveChords / 4;
        std::vector<double> cuts = {0.0, 1.0};
        for (int k = 0; k < chords; ++k) {
            stop_at(deadline, curve);
            const double ta = double(k) / chords, tb = double(k + 1) / chords;
            const Vec2 a = point(s, ta), b = point(s, tb);
            for (const Shape& shape : region.shapes) {
                for (const auto& ring : shape.rings) {
                    for (std::size_t i = 0; i < ring.size(); ++i) {
                        const Vec2& p = ring[i];
                        const Vec2& q = ring[(i + 1) % ring.size()];
                        const double denom = cross(b - a, q - p);
                        if (denom == 0.0) continue;  // parallel: the margin decides
                        const double u = cross(p - a, q - p) / denom;
                        const double v = cross(p - a, b - a) / denom;
                        if (!(u >= 0.0 && u <= 1.0 && v >= 0.0 && v <= 1.0)) continue;
                        double t = ta + u * (tb - ta);
                        if (!line) {
                            stop_at(deadline, curve);
                            // The chord crosses near the curve: bisect on the
                            // curve where its ends lie on either side.
                            double lo = ta, hi = tb;
                            const bool in_lo = inside(region, point(s, lo));
                            if (in_lo != inside(region, point(s, hi))) {
                                for (int it = 0; it < 60; ++it) {
                                    const double mid = 0.5 * (lo + hi);
                                    (inside(region, point(s, mid)) == in_lo ? lo : hi) = mid;
                                }
                                t = 0.5 * (lo + hi);
                            }
                        }
                        cuts.push_back(t);
                    }
                }
            }
        }
        std::sort(cuts.begin(), cuts.end());
        cuts.erase(std::unique(cuts.begin(), cuts.end(),
                               [](double x, double y) { return y - x <= 1e-12; }),
                   cuts.end());
        if (cuts.back() < 1.0) cuts.back() = 1.0;
        for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
            stop_at(deadline, curve);
            if (inside(region, point(s, 0.5 * (cuts[i] + cuts[i + 1])))) {
                current.segments.push_back(piece(s, cuts[i], cuts[i + 1], curve.source));
            } else {
                close();
            }
        }
    }
    close();
    return out;
}

}  // namespace modsynth::drawing::svg_clip
