#include <modsynth/geometry/primitive.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>

namespace {

using namespace modsynth::geometry;
using Where = CriticalPoints::Where;

constexpr double kEps = 1e-12;
constexpr double kInf = std::numeric_limits<double>::infinity();

bool near(const Vec2& a, const Vec2& b, double tol = kEps) { return (a - b).norm() <= tol; }

// A random line, arc (either direction) or circle of moderate size.
Primitive random_primitive(std::mt19937& rng) {
    std::uniform_real_distribution<double> coord(-2.0, 2.0);
    std::uniform_real_distribution<double> radius(0.05, 1.5);
    std::uniform_real_distribution<double> angle(-kPi, kPi);
    std::uniform_int_distribution<int> kind(0, 4);
    const Vec2 a(coord(rng), coord(rng));
    switch (kind(rng)) {
        case 0:
            return make_line(a, Vec2(coord(rng), coord(rng)));
        case 1:
            return make_circle(a + radius(rng) * unit(angle(rng)), a, kind(rng) % 2 == 0);
        default: {
            const double r = radius(rng);
            return make_arc(a + r * unit(angle(rng)), a + r * unit(angle(rng)), a,
                            kind(rng) % 2 == 0);
        }
    }
}

Where expected_where(const Primitive& p, double s) {
    if (s == 0.0) return Where::Start;
    switch (p.kind) {
        case PrimitiveKind::Line:
        case PrimitiveKind::Arc:
            return s == length(p) ? Where::End : Where::Interior;
        case PrimitiveKind::Circle:
            return Where::Interior;  // its end is its start
    }
    modsynth::geometry::invalid_kind(p.kind);
}

// Arcs and circles have a centre and a radius.
bool curved(const Primitive& p) {
    switch (p.kind) {
        case PrimitiveKind::Line:
            return false;
        case PrimitiveKind::Arc:
        case PrimitiveKind::Circle:
            return true;
    }
    modsynth::geometry::invalid_kind(p.kind);
}

}  // namespace

TEST_CASE("a line is parameterised by arc length", "[geometry]") {
    const Primitive l = make_line({1, 1}, {4, 5});
    CHECK(l.kind == PrimitiveKind::Line);
    CHECK(length(l) == Approx(5.0));
    CHECK(near(point_at(l, 0.0), {1, 1}));
    CHECK(near(point_at(l, 2.5), {2.5, 3}));
    CHECK(point_at(l, 5.0) == l.end);
    CHECK(point_at(l, -1.0) == l.start);
    CHECK(point_at(l, 9.0) == l.end);
    CHECK(near(tangent_at(l, 1.0), {0.6, 0.8}));
    CHECK(curvature(l) == 0.0);
}

TEST_CASE("a counter-clockwise quarter arc", "[geometry]") {
    const Primitive a = make_arc({1, 0}, {0, 1}, {0, 0}, true);
    CHECK(a.kind == PrimitiveKind::Arc);
    CHECK(a.radius == Approx(1.0));
    CHECK(a.start_angle == Approx(0.0).margin(kEps));
    CHECK(a.sweep == Approx(kPi / 2));
    CHECK(length(a) == Approx(kPi / 2));
    const double h = std::sqrt(0.5);
    CHECK(near(point_at(a, kPi / 4), {h, h}));
    CHECK(near(tangent_at(a, kPi / 4), {-h, h}));
    CHECK(near(tangent_at(a, 0.0), {0, 1}));
    CHECK(curvature(a) == Approx(1.0));
}

TEST_CASE("a clockwise arc between the same points goes the long way", "[geometry]") {
    const Primitive a = make_arc({1, 0}, {0, 1}, {0, 0}, false);
    CHECK(a.kind == PrimitiveKind::Arc);
    CHECK(a.sweep == Approx(-1.5 * kPi));
    CHECK(length(a) == Approx(1.5 * kPi));
    CHECK(near(point_at(a, kPi / 2), {0, -1}));
    CHECK(near(tangent_at(a, 0.0), {0, -1}));
    CHECK(curvature(a) == Approx(-1.0));
}

TEST_CASE("a half arc and the sweep range", "[geometry]") {
    const Primitive ccw = make_arc({2, 0}, {-2, 0}, {0, 0}, true);
    const Primitive cw = make_arc({2, 0}, {-2, 0}, {0, 0}, false);
    CHECK(ccw.sweep == Approx(kPi));
    CHECK(cw.sweep == Approx(-kPi));
    CHECK(near(point_at(ccw, kPi), {0, 2}));
    CHECK(near(point_at(cw, kPi), {0, -2}));
}

TEST_CASE("an arc's end is projected onto the circle through its start", "[geometry]") {
    const Primitive a = make_arc({1, 0}, {0, 3}, {0, 0}, true);
    CHECK(near(a.end, {0, 1}));
    CHECK(a.sweep == Approx(kPi / 2));
}

TEST_CASE("make_arc gives a full circle when start equals end", "[geometry]") {
    for (const bool ccw : {true, false}) {
        const Primitive c = make_arc({1, 2}, {1, 2 + 1e-10}, {1, 1}, ccw);
        CHECK(c.kind == PrimitiveKind::Circle);
        CHECK(c.sweep == (ccw ? kTau : -kTau));
        CHECK(c.end == c.start);
        CHECK(length(c) == Approx(kTau));
    }
    // Same ray, other radius: the projected end is the start.
    CHECK(make_arc({1, 0}, {2, 0}, {0, 0}, true).kind == PrimitiveKind::Circle);
}

TEST_CASE("a circle", "[geometry]") {
    const Primitive c = make_circle({0, -1}, {0, 0}, false);
    CHECK(c.kind == PrimitiveKind::Circle);
    CHECK(c.radius == Approx(1.0));
    CHECK(c.sweep == -kTau);
    CHECK(near(point_at(c, kPi / 2), {-1, 0}));
    CHECK(point_at(c, kTau) == c.start);
    CHECK(curvature(c) == Approx(-1.0));
}

TEST_CASE("nearest points: analytic cases", "[geometry]") {
    const Primitive l = make_line({0, 0}, {2, 0});
    CHECK(nearest(l, {1, 3}).s == Approx(1.0));
    CHECK(nearest(l, {1, 3}).distance == Approx(3.0));
    CHECK(nearest(l, {-1, 1}).s == 0.0);
    CHECK(nearest(l, {5, 4}).s == 2.0);
    CHECK(nearest(l, {5, 4}).distance == Approx(5.0));

    const Primitive c = make_circle({1, 0}, {0, 0}, true);
    CHECK(nearest(c, {0, 0}).s == 0.0);
    CHECK(nearest(c, {0, 0}).distance == Approx(1.0));
    CHECK(nearest(c, {0, 3}).s == Approx(kPi / 2));
    CHECK(nearest(c, {0, 3}).distance == Approx(2.0));
    CHECK(nearest(c, {0, -3}).s == Approx(1.5 * kPi));
    CHECK(nearest(c, {3, 0}).s == 0.0);

    const Primitive a = make_arc({1, 0}, {0, 1}, {0, 0}, true);
    CHECK(nearest(a, {2, 2}).s == Approx(kPi / 4));
    CHECK(nearest(a, {0.1, 0.1}).distance == Approx(1.0 - std::sqrt(0.02)));
    // Outside the sweep: the nearer end point, the start on a tie.
    CHECK(nearest(a, {-1, 0.5}).s == Approx(kPi / 2));
    CHECK(nearest(a, {0.5, -1}).s == 0.0);
    CHECK(nearest(a, {-1, -1}).s == 0.0);
    CHECK(nearest(a, {-1, -1}).distance == Approx(std::sqrt(5.0)));
}

TEST_CASE("critical points of a line", "[geometry]") {
    const Primitive l = make_line({-1, 1}, {3, 1});
    auto c = critical_points(l, {0, 0});
    CHECK(c.closest_at == Where::Interior);
    CHECK(near(c.closest.point, {0, 1}));
    CHECK(c.closest.s == Approx(1.0));
    CHECK(c.farthest_at == Where::End);
    CHECK(c.farthest.point == l.end);
    CHECK(c.farthest.distance == Approx(std::sqrt(10.0)));

    c = critical_points(l, {5, 0});
    CHECK(c.closest_at == Where::End);
    CHECK(c.closest.s == Approx(4.0));
    CHECK(c.farthest_at == Where::Start);
    CHECK(c.farthest.s == 0.0);
}

TEST_CASE("critical points of a circle", "[geometry]") {
    const Primitive c = make_circle({0, -1}, {0, 0}, true);
    auto k = critical_points(c, {3, 0});
    CHECK(k.closest_at == Where::Interior);
    CHECK(near(k.closest.point, {1, 0}));
    CHECK(k.closest.s == Approx(kPi / 2));
    CHECK(k.closest.distance == Approx(2.0));
    CHECK(k.farthest_at == Where::Interior);
    CHECK(near(k.farthest.point, {-1, 0}));
    CHECK(k.farthest.s == Approx(1.5 * kPi));
    CHECK(k.farthest.distance == Approx(4.0));

    // Straight below the start: the farthest point is the start itself.
    k = critical_points(c, {0, 2});
    CHECK(k.farthest_at == Where::Start);
    CHECK(k.farthest.s == 0.0);
    CHECK(k.closest.s == Approx(kPi));

    k = critical_points(c, {0, 0});
    CHECK(k.closest.s == 0.0);
    CHECK(k.farthest.s == 0.0);
    CHECK(k.closest_at == Where::Start);
    CHECK(k.farthest.distance == Approx(1.0));
}

TEST_CASE("critical points of an arc where an end point is the extreme", "[geometry]") {
    const Primitive a = make_arc({1, 0}, {0, 1}, {0, 0}, true);

    // Radial point inside, antipode outside: the farthest is an end point.
    auto k = critical_points(a, {2, 1});
    CHECK(k.closest_at == Where::Interior);
    CHECK(near(k.closest.point, Vec2(2, 1).normalized()));
    CHECK(k.farthest_at == Where::End);
    CHECK(k.farthest.s == Approx(kPi / 2));
    CHECK(k.farthest.distance == Approx(2.0));

    // Radial point outside, antipode inside: the closest is an end point.
    k = critical_points(a, {-1, -2});
    CHECK(k.closest_at == Where::Start);
    CHECK(k.closest.distance == Approx(std::sqrt(8.0)));
    CHECK(k.farthest_at == Where::Interior);
    CHECK(near(k.farthest.point, Vec2(1, 2).normalized()));
    CHECK(k.farthest.distance == Approx(1.0 + std::sqrt(5.0)));

    // Both outside the sweep: both extremes are end points.
    const Primitive small = make_arc(unit(0.1), unit(0.3), {0, 0}, true);
    k = critical_points(small, 3.0 * unit(1.0));
    CHECK(k.closest_at == Where::End);
    CHECK(k.farthest_at == Where::Start);

    // Equidistant end points: the start wins.
    k = critical_points(a, {-1, -1});
    CHECK(k.closest_at == Where::Start);
    CHECK(k.farthest_at == Where::Interior);
    k = critical_points(a, {1, 1});
    CHECK(k.closest_at == Where::Interior);
    CHECK(k.farthest_at == Where::Start);
}

TEST_CASE("end points and clamping hold for random primitives", "[geometry]") {
    std::mt19937 rng(1);
    for (int i = 0; i < 2000; ++i) {
        const Primitive p = random_primitive(rng);
        INFO("trial " << i);
        CHECK(point_at(p, 0.0) == p.start);
        CHECK(point_at(p, length(p)) == p.end);
        CHECK(point_at(p, length(p) + 1.0) == p.end);
        CHECK(point_at(p, -1.0) == p.start);
        if (curved(p)) {
            CHECK(std::abs((p.end - p.center).norm() - p.radius) <= kEps);
            // The end computed from angles matches the stored end.
            CHECK(near(p.center + p.radius * unit(p.start_angle + p.sweep), p.end, 1e-9));
            CHECK(std::abs(p.sweep) > 0.0);
            CHECK(std::abs(p.sweep) <= kTau);
        }
    }
}

TEST_CASE("the tangent is the derivative of point_at", "[geometry]") {
    std::mt19937 rng(2);
    std::uniform_real_distribution<double> unit_interval(0.01, 0.99);
    const double h = 1e-6;
    for (int i = 0; i < 2000; ++i) {
        const Primitive p = random_primitive(rng);
        const double s = unit_interval(rng) * length(p);
        const Vec2 derivative = (point_at(p, s + h) - point_at(p, s - h)) / (2.0 * h);
        INFO("trial " << i);
        CHECK(near(derivative, tangent_at(p, s), 1e-6));
        CHECK(tangent_at(p, s).norm() == Approx(1.0));
        // Curvature: the tangent turns at rate kappa.
        const double turn = cross(tangent_at(p, s - h), tangent_at(p, s + h)) / (2.0 * h);
        CHECK(turn == Approx(curvature(p)).margin(1e-5));
    }
}

TEST_CASE("nearest agrees with dense sampling", "[geometry][slow]") {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> coord(-3.0, 3.0);
    constexpr int kSamples = 10000;
    for (int i = 0; i < 300; ++i) {
        const Primitive p = random_primitive(rng);
        const Vec2 q(coord(rng), coord(rng));
        const NearestPoint n = nearest(p, q);
        double best = kInf;
        for (int k = 0; k <= kSamples; ++k) {
            best = std::min(best, (point_at(p, length(p) * k / kSamples) - q).norm());
        }
        INFO("trial " << i);
        CHECK(n.distance <= best + 1e-9);
        // Some sample lies within half a step of the nearest point.
        CHECK(best <= n.distance + 0.5 * length(p) / kSamples + 1e-12);
        CHECK(n.distance == Approx((n.point - q).norm()).margin(kEps));
        CHECK(near(point_at(p, n.s), n.point, 1e-9));
    }
}

TEST_CASE("critical points really minimise and maximise the distance", "[geometry][slow]") {
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> coord(-3.0, 3.0);
    constexpr int kSamples = 10000;
    for (int i = 0; i < 300; ++i) {
        const Primitive p = random_primitive(rng);
        // Every third origin sits on the primitive's own circle or line.
        Vec2 o(coord(rng), coord(rng));
        if (i % 3 == 0) o = point_at(p, 0.37 * length(p));
        const CriticalPoints c = critical_points(p, o);
        double lo = kInf;
        double hi = 0.0;
        for (int k = 0; k <= kSamples; ++k) {
            const double d = (point_at(p, length(p) * k / kSamples) - o).norm();
            lo = std::min(lo, d);
            hi = std::max(hi, d);
        }
        INFO("trial " << i);
        CHECK(c.closest.distance <= lo + 1e-9);
        CHECK(c.farthest.distance >= hi - 1e-9);
        CHECK(c.closest.distance == Approx((c.closest.point - o).norm()).margin(1e-12));
        CHECK(c.farthest.distance == Approx((c.farthest.point - o).norm()).margin(1e-12));
        CHECK(near(point_at(p, c.closest.s), c.closest.point, 1e-9));
        CHECK(near(point_at(p, c.farthest.s), c.farthest.point, 1e-9));
        CHECK(c.closest_at == expected_where(p, c.closest.s));
        CHECK(c.farthest_at == expected_where(p, c.farthest.s));
        CHECK(c.closest.s == nearest(p, o).s);
    }
}
