#include <modsynth/drawing/biarc_fit.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <modsynth/task/input_error.h>
#include <modsynth/text/printable.h>

namespace modsynth::drawing {

namespace {

using geometry::cross;
using geometry::kTau;
using geometry::make_arc;
using geometry::make_circle;
using geometry::make_line;
using geometry::perp;
using geometry::PrimitiveKind;
using task::InputError;

/// Samples of the curve per fitted range when measuring the deviation.
constexpr int kSamples = 48;
/// Pieces are accepted within this share of the tolerance: the deviation is
/// measured on samples, and the curve may stray a little further between
/// them.
constexpr double kMargin = 0.95;
/// Splits deeper than this cannot narrow a range usefully (2^-60).
constexpr int kMaxDepth = 60;
// kMinPiece (biarc_fit.h): shorter pieces would be degenerate primitives
// (formats.md wants length > 0; the task reader treats 1e-9 m as zero).
/// Radii beyond this are straight lines for any robot.
constexpr double kMaxRadius = 1e3;
/// Where no biarc spans anything from a point on (a cusp), the recursive
/// split takes over for a stretch of at least this share of the curve's
/// parameter, so that the greedy walk ends after at most this many such
/// stretches whatever the curve.
constexpr double kMinStretch = 1.0 / 4096;
/// Calls of the recursive split per piece it may add (and a few over): each
/// call that adds nothing splits a range in two, so only ranges of no
/// length (which add nothing) could make more.
constexpr std::size_t kSplitsPerPiece = 4;
constexpr std::size_t kSplitsSpare = 4096;

/// Why a curve is refused when it needs more pieces than it may have: the
/// pieces left for it of what the drawing may have.
std::string too_many(std::size_t left) {
    return "needs more than the " + std::to_string(left) + " primitives left for it";
}

/// The bounding box of samples of segments; size() is its diagonal.
struct Extent {
    Vec2 min = Vec2::Constant(std::numeric_limits<double>::infinity());
    Vec2 max = Vec2::Constant(-std::numeric_limits<double>::infinity());
    void add(const Segment& s) {
        for (int i = 0; i <= 32; ++i) {
            const Vec2 p = point(s, i / 32.0);
            min = min.cwiseMin(p);
            max = max.cwiseMax(p);
        }
    }
    double size() const { return std::hypot(max.x() - min.x(), max.y() - min.y()); }
};

/// Unit tangent at t, from inside [t0, t1]: at a cusp (zero derivative)
/// the direction the curve leaves in, or arrives from.
Vec2 tangent(const Segment& s, double t, double t0, double t1, bool at_start) {
    Vec2 d = derivative(s, t);
    const double scale = std::max((end_point(s) - start_point(s)).norm(), 1e-12);
    if (d.norm() > 1e-9 * scale) return d.normalized();
    for (double h = 1e-6; h <= 0.25; h *= 10.0) {
        const double step = h * (t1 - t0);
        d = at_start ? point(s, t + step) - point(s, t) : point(s, t) - point(s, t - step);
        if (d.norm() > 0.0) return d.normalized();
    }
    return (point(s, t1) - point(s, t0)).normalized();
}

double distance_to(const std::vector<Primitive>& ps, const Vec2& q) {
    double best = std::numeric_limits<double>::infinity();
    for (const Primitive& p : ps) best = std::min(best, geometry::nearest(p, q).distance);
    return best;
}

double distance_to_polyline(const std::vector<Vec2>& pts, const Vec2& q) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
        const Vec2 ab = pts[i + 1] - pts[i];
        const double len2 = ab.squaredNorm();
        const double u = len2 > 0.0 ? std::clamp((q - pts[i]).dot(ab) / len2, 0.0, 1.0) : 0.0;
        best = std::min(best, (pts[i] + u * ab - q).norm());
    }
    return best;
}

struct Measured {
    double deviation = 0.0;
    double worst_t = 0.0;  ///< parameter of the curve sample farthest away
};

Measured measure(const Segment& s, double t0, double t1, const std::vector<Primitive>& ps,
                 int samples) {
    Measured m;
    m.worst_t = (t0 + t1) / 2.0;
    std::vector<Vec2> pts;
    pts.reserve(samples + 1);
    double worst_curve = -1.0;
    for (int i = 0; i <= samples; ++i) {
        const double t = t0 + (t1 - t0) * i / samples;
        pts.push_back(point(s, t));
        const double d = distance_to(ps, pts.back());
        if (d > worst_curve) {
            worst_curve = d;
            if (i > 0 && i < samples) m.worst_t = t;
        }
    }
    m.deviation = worst_curve;
    // Back from the primitives to the curve: catches a biarc that loops
    // away between curve samples that all lie near it.
    for (const Primitive& p : ps) {
        const double len = geometry::length(p);
        for (int i = 1; i < samples; ++i) {
            m.deviation = std::max(
                m.deviation, distance_to_polyline(pts, geometry::point_at(p, len * i / samples)));
        }
    }
    return m;
}

struct Fitter {
    const Segment& segment;
    double tolerance;
    std::size_t max_primitives;
    const std::string& source;
    std::vector<Primitive>& out;
    Clock::time_point deadline;
    double worst = 0.0;
    std::size_t splits = 0;

    void check_time() const { check_deadline(deadline, "fitting " + source); }

    /// One biarc over [t0, t1] when it lies within the tolerance.
    std::optional<std::vector<Primitive>> within(double t0, double t1, double& dev) const {
        const Vec2 p0 = point(segment, t0), p1 = point(segment, t1);
        const auto arcs =
            biarc(p0, tangent(segment, t0, t0, t1, true), p1, tangent(segment, t1, t0, t1, false));
        if (!arcs) return std::nullopt;
        dev = measure(segment, t0, t1, *arcs, kSamples).deviation;
        if (dev > kMargin * tolerance) return std::nullopt;
        return arcs;
    }

    /// Fewer pieces than splitting alone: from the start, the longest span
    /// one biarc covers (found by bisection; every piece taken is
    /// measured), then on from its end. Where no span fits (a cusp), the
    /// recursive split takes over for a short stretch.
    void fit_greedy() {
        double t = 0.0;
        while (t < 1.0) {
            check_time();
            if (out.size() > max_primitives) {
                throw InputError(
                    source, too_many(max_primitives) + " at this tolerance: raise --tolerance");
            }
            double dev = 0.0;
            if (auto whole = within(t, 1.0, dev)) {
                worst = std::max(worst, dev);
                out.insert(out.end(), whole->begin(), whole->end());
                return;
            }
            double lo = t, hi = 1.0, best_dev = 0.0;
            std::optional<std::vector<Primitive>> best;
            for (int i = 0; i < 14; ++i) {
                const double mid = (lo + hi) / 2.0;
                if (auto arcs = within(t, mid, dev)) {
                    best = std::move(arcs);
                    best_dev = dev;
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            if (best && lo > t) {
                worst = std::max(worst, best_dev);
                out.insert(out.end(), best->begin(), best->end());
                t = lo;
                continue;
            }
            const double next = std::min(1.0, t + std::max((1.0 - t) / 64.0, kMinStretch));
            fit(t, next, point(segment, t), tangent(segment, t, t, next, true),
                point(segment, next), tangent(segment, next, t, next, false), 0);
            t = next;
        }
    }

    void fit(double t0, double t1, const Vec2& p0, const Vec2& tan0, const Vec2& p1,
             const Vec2& tan1, int depth) {
        if (out.size() > max_primitives) {
            throw InputError(source,
                             too_many(max_primitives) + " at this tolerance: raise --tolerance");
        }
        if (++splits > kSplitsPerPiece * max_primitives + kSplitsSpare) {
            throw InputError(source,
                             "cannot be followed within the tolerance: it splits into more "
                             "ranges than its pieces can cover; raise --tolerance");
        }
        if (splits % 64 == 0) check_time();
        const auto arcs = biarc(p0, tan0, p1, tan1);
        Measured m;
        if (arcs) {
            m = measure(segment, t0, t1, *arcs, kSamples);
            if (m.deviation <= kMargin * tolerance) {
                worst = std::max(worst, m.deviation);
                out.insert(out.end(), arcs->begin(), arcs->end());
                return;
            }
        } else {
            m.worst_t = (t0 + t1) / 2.0;
        }
        // The length of the range, roughly: a closed range has a zero chord.
        double span = 0.0;
        for (int i = 0; i < 8; ++i) {
            span += (point(segment, t0 + (t1 - t0) * (i + 1) / 8) -
                     point(segment, t0 + (t1 - t0) * i / 8))
                        .norm();
        }
        if (depth >= kMaxDepth || span <= kMinPiece) {
            // Too small to split further: the chord is within reach.
            const std::vector<Primitive> chord{make_line(p0, p1)};
            const Measured c = measure(segment, t0, t1, chord, kSamples);
            if ((p1 - p0).norm() > 0.0 && c.deviation <= tolerance) {
                worst = std::max(worst, c.deviation);
                out.push_back(chord.front());
                return;
            }
            if ((p1 - p0).norm() == 0.0 && c.deviation <= tolerance) return;
            throw InputError(source, "cannot be followed within the tolerance");
        }
        // Split where the biarc strays most, but not at the very ends.
        const double w = t1 - t0;
        const double tm = std::clamp(m.worst_t, t0 + 0.1 * w, t1 - 0.1 * w);
        const Vec2 pm = point(segment, tm);
        fit(t0, tm, p0, tan0, pm, tangent(segment, tm, t0, t1, false), depth + 1);
        fit(tm, t1, pm, tangent(segment, tm, t0, t1, true), p1, tan1, depth + 1);
    }
};

/// Exact primitives for lines and circular arcs; empty otherwise. An arc
/// of a radius beyond kMaxRadius is fitted instead, as lines.
std::optional<Primitive> exact(const Segment& s) {
    if (const auto* l = std::get_if<LineSegment>(&s)) return make_line(l->a, l->b);
    if (const auto* e = std::get_if<EllipticArc>(&s);
        e && is_circular(*e) && e->u.norm() <= kMaxRadius) {
        const bool ccw = (e->t1 - e->t0) * cross(e->u, e->v) > 0.0;
        const Vec2 start = point(s, 0.0);
        if (std::abs(e->t1 - e->t0) >= kTau * (1.0 - 1e-12))
            return make_circle(start, e->center, ccw);
        return make_arc(start, point(s, 1.0), e->center, ccw);
    }
    return std::nullopt;
}

bool same_circle(const Primitive& a, const Primitive& b) {
    const double tol = 1e-9 * std::max({a.radius, a.center.cwiseAbs().maxCoeff(), 1e-3});
    return (a.center - b.center).norm() <= tol && std::abs(a.radius - b.radius) <= tol &&
           (a.sweep > 0.0) == (b.sweep > 0.0);
}

bool is_line(const Primitive& p) {
    switch (p.kind) {
        case PrimitiveKind::Line:
            return true;
        case PrimitiveKind::Arc:
        case PrimitiveKind::Circle:
            return false;
    }
    geometry::invalid_kind(p.kind);
}

bool is_arc(const Primitive& p) {
    switch (p.kind) {
        case PrimitiveKind::Arc:
            return true;
        case PrimitiveKind::Line:
        case PrimitiveKind::Circle:
            return false;
    }
    geometry::invalid_kind(p.kind);
}

/// The one piece that `last` and the next piece `p` make when they lie on
/// one line, or are arcs of one circle; nothing otherwise.
std::optional<Primitive> joined(const Primitive& last, const Primitive& p) {
    switch (last.kind) {
        case PrimitiveKind::Line: {
            if (!is_line(p)) return std::nullopt;
            const Vec2 a = last.end - last.start, b = p.end - p.start;
            if (std::abs(cross(a, b)) <= 1e-12 * a.norm() * b.norm() && a.dot(b) > 0.0)
                return make_line(last.start, p.end);
            return std::nullopt;
        }
        case PrimitiveKind::Arc: {
            if (!is_arc(p) || !same_circle(last, p) ||
                std::abs(last.sweep + p.sweep) > kTau * (1.0 + 1e-9))
                return std::nullopt;
            const bool ccw = last.sweep > 0.0;
            return std::abs(last.sweep + p.sweep) >= kTau * (1.0 - 1e-9)
                       ? make_circle(last.start, last.center, ccw)
                       : make_arc(last.start, p.end, last.center, ccw);
        }
        case PrimitiveKind::Circle:
            return std::nullopt;
    }
    geometry::invalid_kind(last.kind);
}

/// Consecutive pieces of one line or one circle become one piece: a
/// polyline's collinear run, a circle drawn as four arcs.
std::vector<Primitive> merged(const std::vector<Primitive>& ps) {
    std::vector<Primitive> out;
    for (const Primitive& p : ps) {
        if (!out.empty()) {
            if (auto one = joined(out.back(), p)) {
                out.back() = *one;
                continue;
            }
        }
        out.push_back(p);
    }
    return out;
}

/// The primitive that starts at `start` and otherwise follows p.
Primitive started_at(const Primitive& p, const Vec2& start) {
    switch (p.kind) {
        case PrimitiveKind::Line:
            return make_line(start, p.end);
        case PrimitiveKind::Circle:
            return make_circle(start, p.center, p.sweep > 0.0);
        case PrimitiveKind::Arc:
            return make_arc(start, p.end, p.center, p.sweep > 0.0);
    }
    geometry::invalid_kind(p.kind);
}

/// The primitive that starts as p does and ends at `end`.
Primitive ended_at(const Primitive& p, const Vec2& end) {
    switch (p.kind) {
        case PrimitiveKind::Line:
            return make_line(p.start, end);
        case PrimitiveKind::Arc:
        case PrimitiveKind::Circle:
            return make_arc(p.start, end, p.center, p.sweep > 0.0);
    }
    geometry::invalid_kind(p.kind);
}

/// Folds pieces shorter than kMinPiece into the next one (or the one
/// before, at the end), keeping the chain joined.
std::vector<Primitive> without_slivers(const std::vector<Primitive>& ps) {
    std::vector<Primitive> out;
    std::optional<Vec2> carry;  // start of a dropped sliver
    for (Primitive p : ps) {
        if (carry) {
            p = started_at(p, *carry);
            carry.reset();
        }
        if (geometry::length(p) < kMinPiece) {
            carry = p.start;
            continue;
        }
        out.push_back(p);
    }
    if (carry && !out.empty()) {
        Primitive& last = out.back();
        const Vec2 end = ps.back().end;
        last = ended_at(last, end);
    }
    return out;
}

}  // namespace

Primitive arc_through(const Vec2& p, const Vec2& t, const Vec2& q) {
    const Vec2 w = q - p;
    const double den = 2.0 * perp(t).dot(w);
    const double r = std::abs(w.squaredNorm() / den);
    if (!std::isfinite(r) || r > kMaxRadius || std::abs(den) <= 1e-12 * w.norm()) {
        return make_line(p, q);
    }
    const Vec2 center = p + (w.squaredNorm() / den) * perp(t);
    return make_arc(p, q, center, den > 0.0);
}

Primitive arc_into(const Vec2& q, const Vec2& p, const Vec2& t) {
    const Vec2 w = q - p;
    const double den = 2.0 * perp(t).dot(w);
    const double r = std::abs(w.squaredNorm() / den);
    if (!std::isfinite(r) || r > kMaxRadius || std::abs(den) <= 1e-12 * w.norm()) {
        return make_line(q, p);
    }
    const Vec2 center = p + (w.squaredNorm() / den) * perp(t);
    return make_arc(q, p, center, den > 0.0);
}

std::optional<std::vector<Primitive>> biarc(const Vec2& p0, const Vec2& t0, const Vec2& p1,
                                            const Vec2& t1) {
    const Vec2 v = p1 - p0;
    const double chord = v.norm();
    if (chord == 0.0) return std::nullopt;
    // Straight: both tangents along the chord.
    if (std::abs(cross(t0, v)) <= 1e-12 * chord && std::abs(cross(t1, v)) <= 1e-12 * chord &&
        t0.dot(v) > 0.0 && t1.dot(v) > 0.0) {
        return std::vector<Primitive>{make_line(p0, p1)};
    }
    const Vec2 t = t0 + t1;
    const double den = 2.0 * (1.0 - t0.dot(t1));
    double d;
    if (den <= 1e-12) {
        const double vt = v.dot(t1);
        if (!(vt > 0.0)) return std::nullopt;
        d = v.squaredNorm() / (4.0 * vt);
    } else {
        const double vt = v.dot(t);
        d = (-vt + std::sqrt(vt * vt + den * v.squaredNorm())) / den;
    }
    if (!(d > 0.0) || !std::isfinite(d)) return std::nullopt;
    const Vec2 q = (p0 + p1 + d * (t0 - t1)) / 2.0;
    std::vector<Primitive> out;
    if ((q - p0).norm() > kMinPiece) out.push_back(arc_through(p0, t0, q));
    if ((p1 - q).norm() > kMinPiece) {
        out.push_back(out.empty() ? arc_into(p0, p1, t1) : arc_into(q, p1, t1));
    }
    if (out.empty()) out.push_back(make_line(p0, p1));
    return out;
}

double deviation(const Segment& segment, double t0, double t1,
                 const std::vector<Primitive>& primitives, int samples) {
    return measure(segment, t0, t1, primitives, samples).deviation;
}

FittedCurve fit_curve(const Curve& curve, double tolerance, std::size_t max_primitives,
                      Clock::time_point deadline) {
    FittedCurve result;
    // A curve this small (a drawing scaled to 1e-200, coordinates of
    // 1e-160 mm) has nothing a piece could follow, and squared distances
    // across it underflow: refused before any fitting.
    Extent whole;
    for (const Segment& s : curve.segments) whole.add(s);
    if (!(whole.size() >= kMinPiece)) {
        throw InputError(curve.source,
                         "is " + text::compact(whole.size()) +
                             " m across once placed, less than the " + text::compact(kMinPiece) +
                             " m the fitting resolves: check --width, --scale or the file's units");
    }
    std::vector<Primitive> pieces;
    for (const Segment& s : curve.segments) {
        check_deadline(deadline, "fitting " + curve.source);
        // A segment below the resolution is its chord (or nothing), folded
        // into its neighbours below.
        Extent own;
        own.add(s);
        if (!(own.size() >= kMinPiece)) {
            if (start_point(s) != end_point(s))
                pieces.push_back(make_line(start_point(s), end_point(s)));
            continue;
        }
        if (const auto p = exact(s)) {
            pieces.push_back(*p);
            continue;
        }
        std::vector<Primitive> fitted;
        Fitter f{s, tolerance, max_primitives, curve.source, fitted, deadline};
        f.fit_greedy();
        result.deviation = std::max(result.deviation, f.worst);
        pieces.insert(pieces.end(), fitted.begin(), fitted.end());
        if (pieces.size() > max_primitives) {
            throw InputError(curve.source,
                             too_many(max_primitives) + " at this tolerance: raise --tolerance");
        }
    }
    result.primitives = without_slivers(merged(pieces));
    if (result.primitives.empty()) {
        const Vec2 start = start_point(curve.segments.front());
        double reach = 0.0;
        for (const Segment& s : curve.segments) {
            for (int i = 0; i <= kSamples; ++i)
                reach = std::max(reach, (point(s, double(i) / kSamples) - start).norm());
        }
        if (!(reach <= tolerance)) throw InputError(curve.source, "zero-length curve");
        result.dot = true;
        result.deviation = reach;
    }
    return result;
}

Primitive reversed(const Primitive& p) {
    switch (p.kind) {
        case PrimitiveKind::Line:
            return make_line(p.end, p.start);
        case PrimitiveKind::Circle:
            return make_circle(p.start, p.center, p.sweep < 0.0);
        case PrimitiveKind::Arc:
            break;
    }
    return make_arc(p.end, p.start, p.center, p.sweep < 0.0);
}

}  // namespace modsynth::drawing
