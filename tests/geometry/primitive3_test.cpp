#include <modsynth/geometry/primitive3.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

#include <modsynth/geometry/curve_distance.h>
#include <modsynth/geometry/distance3.h>
#include <modsynth/geometry/vec.h>

namespace {

using namespace modsynth::geometry;

Vec3 random_unit(std::mt19937& rng) {
    std::normal_distribution<double> g(0.0, 1.0);
    for (;;) {
        const Vec3 v(g(rng), g(rng), g(rng));
        if (v.norm() > 1e-6) return v.normalized();
    }
}

Vec3 random_perp(std::mt19937& rng, const Vec3& n) {
    for (;;) {
        const Vec3 v = n.cross(random_unit(rng));
        if (v.norm() > 1e-3) return v.normalized();
    }
}

/// A random line, arc, circle or helix near the origin.
Primitive3 random_primitive(std::mt19937& rng, int kind) {
    std::uniform_real_distribution<double> coord(-0.5, 0.5);
    std::uniform_real_distribution<double> radius(0.02, 0.3);
    std::uniform_real_distribution<double> sweep(0.2, 6.0);
    const Vec3 start(coord(rng), coord(rng), coord(rng));
    const Vec3 n = random_unit(rng);
    const double r = radius(rng);
    const Vec3 center = start + r * random_perp(rng, n);
    const bool ccw = rng() % 2 == 0;
    switch (kind % 4) {
        case 0:
            return Line3{start, Vec3(coord(rng), coord(rng), coord(rng))};
        case 1: {
            // The end at a random angle about the normal.
            const Turn t = make_turn(start, center, n, ccw);
            const double a = sweep(rng);
            const Vec3 end = t.origin() + r * (std::cos(a) * t.u + std::sin(a) * t.v);
            return make_arc3(start, end, center, n, ccw);
        }
        case 2:
            return Circle3{make_turn(start, center, n, ccw)};
        default: {
            std::uniform_real_distribution<double> pitch(0.005, 0.1);
            std::uniform_real_distribution<double> turns(0.2, 3.0);
            return make_helix3(start, center, n, ccw, (rng() % 2 ? 1.0 : -1.0) * pitch(rng),
                               turns(rng));
        }
    }
}

std::vector<std::pair<double, Vec3>> dense(const Primitive3& p, int n) {
    std::vector<std::pair<double, Vec3>> out;
    for (int k = 0; k <= n; ++k) {
        const double s = length(p) * k / n;
        out.push_back({s, point_at(p, s)});
    }
    return out;
}

}  // namespace

TEST_CASE("spatial primitives: lengths, points and tangents", "[geometry]") {
    const Line3 line{Vec3(0, 0, 0), Vec3(3, 4, 0)};
    CHECK(length(line) == Approx(5.0));
    CHECK(point_at(line, 2.5).isApprox(Vec3(1.5, 2, 0)));
    CHECK(tangent_at(line, 1.0).isApprox(Vec3(0.6, 0.8, 0)));
    CHECK(max_curvature(line) == 0.0);

    // A quarter turn about +z from (1, 0, 0): ccw heads towards +y.
    const Arc3 arc = make_arc3(Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 0), Vec3(0, 0, 2), true);
    CHECK(arc.sweep == Approx(kPi / 2));
    CHECK(length(arc) == Approx(kPi / 2));
    CHECK(point_at(arc, kPi / 4).isApprox(Vec3(std::sqrt(0.5), std::sqrt(0.5), 0)));
    CHECK(tangent_at(arc, 0.0).isApprox(Vec3(0, 1, 0)));
    // cw about +z from (1, 0, 0) to (0, 1, 0) is three quarters.
    const Arc3 cw = make_arc3(Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 0), Vec3(0, 0, 1), false);
    CHECK(cw.sweep == Approx(3 * kPi / 2));
    CHECK(point_at(cw, kPi / 2).isApprox(Vec3(0, -1, 0)));
    // Start equal to end: a full turn.
    const Arc3 full = make_arc3(Vec3(1, 0, 0), Vec3(1, 0, 0), Vec3(0, 0, 0), Vec3(0, 0, 1), true);
    CHECK(full.sweep == Approx(kTau));
    CHECK(max_curvature(full) == Approx(1.0));

    // A helix of radius 0.1 rising 0.02 per turn, two turns about +z.
    const Helix3 helix =
        make_helix3(Vec3(0.1, 0, 0), Vec3(0, 0, 0), Vec3(0, 0, 1), true, 0.02, 2.0);
    const double c = 0.02 / kTau;
    CHECK(length(helix) == Approx(2 * kTau * std::hypot(0.1, c)));
    CHECK(end_point(helix).isApprox(Vec3(0.1, 0, 0.04)));
    CHECK(point_at(helix, length(helix) / 4).isApprox(Vec3(-0.1, 0, 0.01)));
    CHECK(max_curvature(helix) == Approx(0.1 / (0.01 + c * c)));
    // The start is returned exactly as given.
    CHECK(point_at(helix, 0.0) == Vec3(0.1, 0, 0));
}

TEST_CASE("spatial primitives: tangents and curvature agree with finite differences",
          "[geometry]") {
    std::mt19937 rng(41);
    for (int i = 0; i < 400; ++i) {
        const Primitive3 p = random_primitive(rng, i);
        const double len = length(p);
        const double h = 1e-5;
        for (double f : {0.1, 0.5, 0.9}) {
            const double s = f * len;
            if (s < 2e-3 || s > len - 2e-3) continue;
            const Vec3 d = (point_at(p, s + h) - point_at(p, s - h)) / (2 * h);
            INFO("trial " << i << " " << type_name(p));
            CHECK((d - tangent_at(p, s)).norm() < 1e-6);
            CHECK(tangent_at(p, s).norm() == Approx(1.0));
            const Vec3 dd =
                (point_at(p, s + 1e-3) - 2 * point_at(p, s) + point_at(p, s - 1e-3)) / 1e-6;
            // The curvature is constant on each kind: the bound is attained.
            CHECK(dd.norm() == Approx(max_curvature(p)).epsilon(1e-3).margin(1e-6));
        }
    }
}

TEST_CASE("spatial primitives: nearest and farthest points are exact", "[geometry]") {
    std::mt19937 rng(42);
    std::uniform_real_distribution<double> coord(-0.8, 0.8);
    for (int i = 0; i < 2000; ++i) {
        const Primitive3 p = random_primitive(rng, i);
        Vec3 q(coord(rng), coord(rng), coord(rng));
        // Points on the axis of a turn, and on the curve itself.
        if (i % 7 == 3) q = point_at(p, 0.37 * length(p));
        const CurvePoint3 near = nearest(p, q);
        const CurvePoint3 far = farthest(p, q);
        INFO("trial " << i << " " << type_name(p));
        REQUIRE(std::isfinite(near.distance));
        REQUIRE(std::isfinite(far.distance));
        CHECK(near.distance == Approx((point_at(p, near.s) - q).norm()).margin(1e-12));
        CHECK(far.distance == Approx((point_at(p, far.s) - q).norm()).margin(1e-12));
        // No dense sample beats them; the nearest dense sample is within
        // half a step (and the curve's bulge) of them.
        const int n = 4000;
        const double step = length(p) / n;
        double lo = 1e9, hi = 0.0;
        for (const auto& [s, x] : dense(p, n)) {
            lo = std::min(lo, (x - q).norm());
            hi = std::max(hi, (x - q).norm());
        }
        CHECK(near.distance <= lo + 1e-9);
        CHECK(far.distance >= hi - 1e-9);
        CHECK(near.distance >= lo - step);
        CHECK(far.distance <= hi + step);
    }
}

TEST_CASE("a helix's nearest point within a window follows its turn", "[geometry]") {
    const Helix3 h = make_helix3(Vec3(0.05, 0, 0), Vec3(0, 0, 0), Vec3(0, 0, 1), true, 0.01, 5.0);
    const double turn = length(h) / 5.0;
    // A point on the third turn: the nearest point overall is there, and a
    // window on the first turn finds the point of that turn.
    const Vec3 q = point_at(h, 2.25 * turn) + Vec3(0, 0, 0.001);
    CHECK(nearest(h, q).s == Approx(2.25 * turn).margin(2e-3));
    const CurvePoint3 first = nearest_between(h, q, 0.0, turn);
    CHECK(first.s <= turn);
    CHECK(first.s == Approx(0.25 * turn).margin(2e-3));
}

TEST_CASE("distances from a primitive to a box", "[geometry]") {
    std::mt19937 rng(43);
    std::uniform_real_distribution<double> coord(-0.6, 0.6);
    std::uniform_real_distribution<double> side(0.01, 0.5);
    for (int i = 0; i < 300; ++i) {
        const Primitive3 p = random_primitive(rng, i);
        Box3 box;
        box.min = Vec3(coord(rng), coord(rng), coord(rng));
        box.max = box.min + Vec3(side(rng), side(rng), side(rng));
        const CurvePoint3 least = least_distance_to_box(p, box);
        const CurvePoint3 largest = largest_distance_to_box(p, box);
        double lo = 1e9, hi = 0.0;
        const int n = 4000;
        for (const auto& [s, x] : dense(p, n)) {
            lo = std::min(lo, point_box(x, box));
            hi = std::max(hi, point_box(x, box));
        }
        INFO("trial " << i << " " << type_name(p));
        // Attained, and no dense sample beats them by more than the tolerance.
        CHECK(least.distance == Approx(point_box(point_at(p, least.s), box)).margin(1e-12));
        CHECK(largest.distance == Approx(point_box(point_at(p, largest.s), box)).margin(1e-12));
        CHECK(least.distance <= lo + 1e-9);
        CHECK(largest.distance >= hi - 1e-9);
        CHECK(least.distance >= lo - length(p) / n);
        CHECK(largest.distance <= hi + length(p) / n);
        // The decision agrees with the least distance.
        const auto to_box = [&](const Vec3& x) { return point_box(x, box); };
        if (least.distance > 1e-6) {
            CHECK_FALSE(comes_within(p, to_box, least.distance - 1e-6));
            CHECK(comes_within(p, to_box, least.distance + 1e-6));
        }
    }
}
