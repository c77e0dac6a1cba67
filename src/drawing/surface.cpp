#include <modsynth/drawing/surface.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

#include <modsynth/drawing/biarc_fit.h>
#include <modsynth/task/input_error.h>
#include <modsynth/task/limits.h>
#include <modsynth/text/format.h>

namespace modsynth::drawing {

namespace {

using geometry::Arc3;
using geometry::Circle3;
using geometry::Line3;
using geometry::Primitive;
using geometry::Primitive3;
using geometry::PrimitiveKind;
using task::InputError;

constexpr double kTwoPi = 2.0 * geometry::kPi;
/// formats.md: a helix climbs at least this much per turn.
constexpr double kMinPitch = 0.005;
/// A line whose ends differ by no more than this round (along) the axis
/// runs along (round) it: the helix it would be strays from the line (the
/// arc) by far less than a nanometre.
constexpr double kStraight = 1e-12;
/// Pieces of a wrapped curve fitted by one biarc turn at most a quarter
/// turn in the drawing and about the axis, so that every biarc is well
/// conditioned from the start.
constexpr double kQuarter = geometry::kPi / 2.0;
/// A fitted piece shorter than this along the drawing is its chord: it
/// strays from the curve by less than curvature * length^2 / 8.
constexpr double kShortestPiece = 1e-6;

Vec3 vec3(const std::vector<double>& n, std::size_t at) { return {n[at], n[at + 1], n[at + 2]}; }

void check_finite(const std::vector<double>& n, std::size_t count, const char* option,
                  const char* layout) {
    if (n.size() != count)
        throw InputError(
            option, text::format("expected %zu numbers (%s), got %zu", count, layout, n.size()));
    for (double x : n)
        if (!std::isfinite(x)) throw InputError(option, "every number must be finite");
}

std::string vector_text(const Vec3& v) {
    return text::format("(%.6g, %.6g, %.6g)", v.x(), v.y(), v.z());
}

/// The drawing's primitive as a curve on the cylinder by its arc length
/// (the wrapping keeps lengths along the surface).
struct WrappedCurve {
    const Primitive& p;
    const CylinderSurface& s;
    double length() const { return geometry::length(p); }
    Vec2 planar(double at) const {
        if (at <= 0.0) return p.start;
        if (at >= length()) return p.end;
        return geometry::point_at(p, at);
    }
    Vec3 point(double at) const { return surface_point(s, planar(at)); }
    Vec3 tangent(double at) const {
        return surface_direction(s, planar(at), geometry::tangent_at(p, at)).normalized();
    }
};

/// The arc (or line) from a, heading along the unit tangent t, to b.
Primitive3 arc_from(const Vec3& a, const Vec3& t, const Vec3& b) {
    const Vec3 w = b - a;
    const Vec3 n = t.cross(w);
    // Sweep 2 phi, phi the angle between t and the chord; below 1e-9 rad the
    // arc is its chord to within |w| * 1e-9 / 8.
    const double sweep = 2.0 * std::atan2(n.norm(), t.dot(w));
    if (!(sweep > 1e-9)) return Line3{a, b};
    const Vec3 normal = n.normalized();
    const Vec3 inward = normal.cross(t);
    const double radius = w.squaredNorm() / (2.0 * w.dot(inward));
    const Vec3 center = a + radius * inward;
    if (!(center.cwiseAbs().maxCoeff() <= task::kMaxCoordinate)) return Line3{a, b};
    return geometry::make_arc3(a, b, center, normal, true);
}

/// The biarc of equal legs from (a, ta) to (b, tb), as two primitives;
/// empty when it does not exist or a half would be shorter than kMinPiece.
std::vector<Primitive3> biarc(const Vec3& a, const Vec3& ta, const Vec3& b, const Vec3& tb) {
    const Vec3 v = b - a;
    const Vec3 t = ta + tb;
    const double vt = v.dot(t);
    const double denom = 2.0 * (1.0 - ta.dot(tb));
    double d;
    if (std::abs(denom) < 1e-12) {
        if (!(vt > 0.0)) return {};
        d = v.squaredNorm() / (2.0 * vt);
    } else {
        d = (-vt + std::sqrt(vt * vt + denom * v.squaredNorm())) / denom;
    }
    if (!(d > 0.0) || !std::isfinite(d)) return {};
    const Vec3 q1 = a + d * ta, q2 = b - d * tb;
    const Vec3 mid = 0.5 * (q1 + q2);
    if ((mid - a).norm() < kMinPiece || (b - mid).norm() < kMinPiece) return {};
    const Vec3 tm = (q2 - q1).normalized();
    if (!tm.allFinite()) return {};
    return {arc_from(a, ta, mid), arc_from(mid, tm, b)};
}

/// Largest distance between the curve over [s0, s1] and the pieces, on
/// samples both ways (the pieces' samples against a fine polyline of the
/// curve).
double piece_deviation(const WrappedCurve& c, double s0, double s1,
                       const std::vector<Primitive3>& pieces) {
    constexpr int kSamples = 24, kPolyline = 96;
    double worst = 0.0;
    for (int i = 0; i <= kSamples; ++i) {
        const Vec3 q = c.point(s0 + (s1 - s0) * i / kSamples);
        double d = INFINITY;
        for (const Primitive3& p : pieces) d = std::min(d, geometry::nearest(p, q).distance);
        worst = std::max(worst, d);
    }
    std::vector<Vec3> line;
    for (int i = 0; i <= kPolyline; ++i) line.push_back(c.point(s0 + (s1 - s0) * i / kPolyline));
    for (const Primitive3& p : pieces) {
        const double len = geometry::length(p);
        for (int k = 1; k < kSamples; ++k) {
            const Vec3 q = geometry::point_at(p, len * k / kSamples);
            double d = INFINITY;
            for (std::size_t i = 1; i < line.size(); ++i) {
                const Vec3 e = line[i] - line[i - 1];
                const double u = std::clamp((q - line[i - 1]).dot(e) / e.squaredNorm(), 0.0, 1.0);
                d = std::min(d, (line[i - 1] + u * e - q).norm());
            }
            worst = std::max(worst, d);
        }
    }
    return worst;
}

struct Fitter {
    const CylinderSurface& s;
    double tolerance;
    std::size_t max_primitives;
    Clock::time_point deadline;
    const char* option;
    std::size_t count = 0;
    double deviation = 0.0;

    void add(Chain3& out, const Primitive3& p) {
        if (++count > max_primitives)
            throw InputError(option, text::format("the drawing needs more than %zu primitives "
                                                  "round the cylinder: raise --tolerance",
                                                  max_primitives));
        out.push_back(p);
    }

    /// Biarcs from the curve's point a (at s0) to its point at s1, split in
    /// two where one strays beyond 95% of the tolerance.
    void fit(const WrappedCurve& c, double s0, double s1, const Vec3& a, const Vec3& b,
             Chain3& out) {
        check_deadline(deadline, "wrapping the drawing round the cylinder");
        if (s1 - s0 < kShortestPiece) {
            const Primitive3 chord = Line3{a, b};
            deviation = std::max(deviation, piece_deviation(c, s0, s1, {chord}));
            add(out, chord);
            return;
        }
        std::vector<Primitive3> pieces = biarc(a, c.tangent(s0), b, c.tangent(s1));
        double dev = pieces.empty() ? INFINITY : piece_deviation(c, s0, s1, pieces);
        if (!(dev <= 0.95 * tolerance)) {
            const double sm = 0.5 * (s0 + s1);
            const Vec3 m = c.point(sm);
            fit(c, s0, sm, a, m, out);
            fit(c, sm, s1, m, b, out);
            return;
        }
        deviation = std::max(deviation, dev);
        for (const Primitive3& p : pieces) add(out, p);
    }

    void wrap(const Primitive& p, Chain3& out) {
        const Vec3 a = surface_point(s, p.start), b = surface_point(s, p.end);
        if (p.kind == PrimitiveKind::Line) {
            const double dx = p.end.x() - p.start.x(), dy = p.end.y() - p.start.y();
            if (std::abs(dx) <= kStraight) {
                add(out, Line3{a, b});
                return;
            }
            const Vec3 level = s.center + p.start.y() * s.axis;
            if (std::abs(dy) <= kStraight) {
                add(out, geometry::make_arc3(a, b, level, s.axis, dx > 0.0));
                return;
            }
            const double turns = std::abs(dx) / (kTwoPi * s.radius);
            const double pitch = dy / turns;
            if (std::abs(pitch) >= kMinPitch && std::abs(pitch) <= task::kMaxLength) {
                add(out, geometry::make_helix3(a, level, s.axis, dx > 0.0, pitch, turns));
                return;
            }
            // Nearly along the axis: a helix of a pitch no task may hold
            // (past kMaxLength), which strays from its chord by its sagitta
            // only. Within the tolerance that chord is the primitive;
            // otherwise the fit below follows it.
            const double half_sweep_sine = std::sin(0.5 * geometry::kPi * turns);
            const double sagitta = 2.0 * s.radius * half_sweep_sine * half_sweep_sine;
            if (std::abs(pitch) > task::kMaxLength && sagitta <= 0.5 * tolerance) {
                deviation = std::max(deviation, sagitta);
                add(out, Line3{a, b});
                return;
            }
        }
        // Curves: in pieces of at most a quarter turn in the drawing and
        // about the axis, each fitted.
        const WrappedCurve c{p, s};
        const double len = c.length();
        const double turn = p.kind == PrimitiveKind::Line ? 0.0 : std::abs(p.sweep);
        const int pieces = std::max(
            {1, static_cast<int>(std::ceil(turn / kQuarter)),
             static_cast<int>(std::ceil(std::abs(p.end.x() - p.start.x()) / s.radius / kQuarter)),
             static_cast<int>(std::ceil(len / (s.radius * kQuarter)))});
        Vec3 from = a;
        for (int k = 0; k < pieces; ++k) {
            const double s0 = len * k / pieces, s1 = len * (k + 1) / pieces;
            const Vec3 to = k + 1 == pieces ? b : c.point(s1);
            fit(c, s0, s1, from, to, out);
            from = to;
        }
    }
};

/// True when the turn from a0 by sweep (signed) passes the angle a.
bool passes(double a, double a0, double sweep) {
    double t = std::fmod((sweep >= 0.0 ? a - a0 : a0 - a), kTwoPi);
    if (t < 0.0) t += kTwoPi;
    return t <= std::abs(sweep);
}

}  // namespace

PlaneSurface plane_surface(const std::vector<double>& numbers, const char* option) {
    check_finite(numbers, 9, option, "ORIGIN,U,V: x,y,z of each");
    PlaneSurface s;
    s.origin = vec3(numbers, 0);
    const Vec3 u = vec3(numbers, 3), v = vec3(numbers, 6);
    if (!(s.origin.cwiseAbs().maxCoeff() <= task::kMaxCoordinate))
        throw InputError(option, text::format("the origin lies beyond %g m of the task's origin",
                                              task::kMaxCoordinate));
    for (const auto& [name, d] : {std::pair{"U", u}, std::pair{"V", v}}) {
        if (!(std::abs(d.norm() - 1.0) <= kDirectionTolerance))
            throw InputError(
                option, text::format("%s %s is not a unit vector (length %.6g; "
                                     "within %g of 1 is taken)",
                                     name, vector_text(d).c_str(), d.norm(), kDirectionTolerance));
    }
    if (!(std::abs(u.dot(v)) <= kDirectionTolerance))
        throw InputError(option, text::format("U %s and V %s are not perpendicular (U . V = %.6g; "
                                              "within %g of 0 is taken)",
                                              vector_text(u).c_str(), vector_text(v).c_str(),
                                              u.dot(v), kDirectionTolerance));
    s.u = u.normalized();
    s.v = (v - v.dot(s.u) * s.u).normalized();
    return s;
}

CylinderSurface cylinder_surface(const std::vector<double>& numbers, const Vec3& towards,
                                 const char* option) {
    check_finite(numbers, 7, option, "CENTER,AXIS,RADIUS: x,y,z, x,y,z, r");
    CylinderSurface s;
    s.center = vec3(numbers, 0);
    const Vec3 axis = vec3(numbers, 3);
    s.radius = numbers[6];
    if (!(s.center.cwiseAbs().maxCoeff() <= task::kMaxCoordinate))
        throw InputError(option, text::format("the centre lies beyond %g m of the task's origin",
                                              task::kMaxCoordinate));
    if (!(axis.cwiseAbs().maxCoeff() > 0.0))
        throw InputError(option, "the axis " + vector_text(axis) + " has no direction");
    if (!(s.radius > 0.0 && s.radius <= task::kMaxCoordinate))
        throw InputError(option, text::format("the radius %.6g must be positive and at most %g m",
                                              s.radius, task::kMaxCoordinate));
    s.axis = geometry::unit_vector(axis);
    Vec3 out = towards - s.center;
    out -= out.dot(s.axis) * s.axis;
    if (!(out.norm() > 1e-9)) {
        out = std::abs(s.axis.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
        out -= out.dot(s.axis) * s.axis;
    }
    s.facing = out.normalized();
    return s;
}

Vec3 surface_point(const PlaneSurface& s, const Vec2& p) {
    return s.origin + p.x() * s.u + p.y() * s.v;
}

Vec3 surface_point(const CylinderSurface& s, const Vec2& p) {
    const double a = p.x() / s.radius;
    return s.center + p.y() * s.axis +
           s.radius * (std::cos(a) * s.facing + std::sin(a) * s.axis.cross(s.facing));
}

Vec3 surface_direction(const CylinderSurface& s, const Vec2& p, const Vec2& t) {
    const double a = p.x() / s.radius;
    return t.x() * (-std::sin(a) * s.facing + std::cos(a) * s.axis.cross(s.facing)) +
           t.y() * s.axis;
}

static Primitive3 on_plane(const PlaneSurface& s, const Vec3& normal, const Primitive& p) {
    const Vec3 a = surface_point(s, p.start);
    switch (p.kind) {
        case PrimitiveKind::Line:
            return Line3{a, surface_point(s, p.end)};
        case PrimitiveKind::Arc:
            return geometry::make_arc3(a, surface_point(s, p.end), surface_point(s, p.center),
                                       normal, p.sweep > 0.0);
        case PrimitiveKind::Circle:
            return Circle3{
                geometry::make_turn(a, surface_point(s, p.center), normal, p.sweep > 0.0)};
    }
    geometry::invalid_kind(p.kind);
}

PlacedStrokes place_on_plane(const std::vector<Chain>& strokes, const PlaneSurface& s) {
    const Vec3 normal = s.u.cross(s.v);
    PlacedStrokes out;
    for (const Chain& chain : strokes) {
        Chain3 placed;
        for (const Primitive& p : chain) placed.push_back(on_plane(s, normal, p));
        out.strokes.push_back(std::move(placed));
    }
    return out;
}

double drawing_width(const std::vector<Chain>& strokes) {
    double lo = INFINITY, hi = -INFINITY;
    for (const Chain& chain : strokes) {
        for (const Primitive& p : chain) {
            lo = std::min({lo, p.start.x(), p.end.x()});
            hi = std::max({hi, p.start.x(), p.end.x()});
            if (p.kind == PrimitiveKind::Line) continue;
            if (passes(0.0, p.start_angle, p.sweep)) hi = std::max(hi, p.center.x() + p.radius);
            if (passes(geometry::kPi, p.start_angle, p.sweep))
                lo = std::min(lo, p.center.x() - p.radius);
        }
    }
    return hi > lo ? hi - lo : 0.0;
}

PlacedStrokes place_on_cylinder(const std::vector<Chain>& strokes, const CylinderSurface& s,
                                double tolerance, std::size_t max_primitives,
                                Clock::time_point deadline, const char* option) {
    const double width = drawing_width(strokes);
    const double circumference = kTwoPi * s.radius;
    if (width > circumference * (1.0 + 1e-12))
        throw InputError(option, text::format("the drawing is %.6g m wide, more than the "
                                              "cylinder's circumference of %.6g m (radius "
                                              "%.6g m): give a smaller --width or a larger radius",
                                              width, circumference, s.radius));
    Fitter fitter{s, tolerance, max_primitives, deadline, option};
    PlacedStrokes out;
    for (const Chain& chain : strokes) {
        Chain3 placed;
        for (const Primitive& p : chain) fitter.wrap(p, placed);
        out.strokes.push_back(std::move(placed));
    }
    out.deviation = fitter.deviation;
    return out;
}

}  // namespace modsynth::drawing
