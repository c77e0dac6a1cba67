#include <modsynth/geometry/distance3.h>

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

namespace {

using namespace modsynth::geometry;

/// Least value of a convex function on [0, 1]: golden-section search, an
/// independent reference for the closed forms.
template <class F>
double golden_min(F f) {
    const double g = (std::sqrt(5.0) - 1.0) / 2.0;
    double a = 0.0, b = 1.0, c = b - g * (b - a), d = a + g * (b - a);
    double fc = f(c), fd = f(d);
    for (int i = 0; i < 120; ++i) {
        if (fc < fd) {
            b = d, d = c, fd = fc;
            c = b - g * (b - a);
            fc = f(c);
        } else {
            a = c, c = d, fc = fd;
            d = a + g * (b - a);
            fd = f(d);
        }
    }
    return std::min({fc, fd, f(0.0), f(1.0)});
}

Vec3 lerp(const Vec3& a, const Vec3& b, double t) { return a + t * (b - a); }

/// Random segments biased toward the awkward cases: parallel, collinear,
/// touching, crossing, degenerate, both degenerate.
struct SegmentPair {
    Vec3 a, b, c, d;
};

SegmentPair random_pair(std::mt19937& rng) {
    std::uniform_real_distribution<double> coord(-1.0, 1.0);
    std::uniform_real_distribution<double> scale(-1.5, 1.5);
    std::uniform_int_distribution<int> kind(0, 7);
    auto point = [&] { return Vec3(coord(rng), coord(rng), coord(rng)); };
    SegmentPair s{point(), point(), point(), point()};
    switch (kind(rng)) {
        case 0:  // parallel
            s.d = s.c + scale(rng) * (s.b - s.a);
            break;
        case 1:  // collinear
            s.c = s.a + scale(rng) * (s.b - s.a);
            s.d = s.a + scale(rng) * (s.b - s.a);
            break;
        case 2:  // an end point on the other segment
            s.c = lerp(s.a, s.b, 0.5 * (scale(rng) / 1.5 + 1.0));
            break;
        case 3:  // degenerate
            s.d = s.c;
            break;
        case 4:  // both degenerate
            s.b = s.a;
            s.d = s.c;
            break;
        case 5:  // crossing: coplanar, through a common point
        {
            const Vec3 x = lerp(s.a, s.b, 0.3);
            s.d = x + (x - s.c);
            break;
        }
        case 6:  // nearly parallel
            s.d = s.c + (s.b - s.a) + 1e-7 * point();
            break;
        default:
            break;
    }
    return s;
}

Box3 random_box(std::mt19937& rng) {
    std::uniform_real_distribution<double> coord(-0.6, 0.6);
    std::uniform_real_distribution<double> side(0.0, 0.8);
    Box3 b;
    b.min = Vec3(coord(rng), coord(rng), coord(rng));
    b.max = b.min + Vec3(side(rng), side(rng), side(rng));
    return b;
}

}  // namespace

TEST_CASE("point-segment distance in space", "[geometry]") {
    const Vec3 a(0, 0, 0), b(4, 0, 0);
    CHECK(segment_parameter(Vec3(1, 3, 4), a, b) == Approx(0.25));
    CHECK(segment_parameter(Vec3(-2, 3, 0), a, b) == 0.0);
    CHECK(segment_parameter(Vec3(7, 0, -3), a, b) == 1.0);
    CHECK(segment_parameter(Vec3(7, 0, -3), a, a) == 0.0);
    CHECK(point_segment(Vec3(1, 3, 4), a, b) == Approx(5.0));
    CHECK(point_segment(Vec3(-3, 0, 4), a, b) == Approx(5.0));
    CHECK(point_segment(Vec3(3, 4, 0), a, a) == Approx(5.0));
}

TEST_CASE("segment-segment distance in space: analytic cases", "[geometry]") {
    // Skew lines crossing above each other: the common perpendicular.
    CHECK(segment_segment(Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, -1, 2), Vec3(0, 1, 2)) ==
          Approx(2.0));
    // Crossing in a plane, sharing an end point.
    CHECK(segment_segment(Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, -1, 0), Vec3(0, 1, 0)) == 0.0);
    CHECK(segment_segment(Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(1, 0, 0), Vec3(2, 5, 1)) == 0.0);
    // Parallel, overlapping and apart along their direction.
    CHECK(segment_segment(Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(1, 1, 1), Vec3(3, 1, 1)) ==
          Approx(std::sqrt(2.0)));
    CHECK(segment_segment(Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(3, 0, 1), Vec3(5, 0, 1)) ==
          Approx(std::sqrt(2.0)));
    // Collinear.
    CHECK(segment_segment(Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(1, 0, 0), Vec3(3, 0, 0)) == 0.0);
    CHECK(segment_segment(Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(3, 0, 0), Vec3(5, 0, 0)) ==
          Approx(1.0));
    // Points.
    CHECK(segment_segment(Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(1, -1, 0), Vec3(1, 1, 0)) ==
          Approx(1.0));
    CHECK(segment_segment(Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(0, 3, 4), Vec3(0, 3, 4)) ==
          Approx(5.0));
    // The closest points of the lines lie outside one segment.
    CHECK(segment_segment(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(3, -1, 1), Vec3(3, 1, 1)) ==
          Approx(std::sqrt(5.0)));
}

TEST_CASE("segment-segment distance in space agrees with a golden-section search", "[geometry]") {
    std::mt19937 rng(31);
    for (int i = 0; i < 5000; ++i) {
        const SegmentPair s = random_pair(rng);
        const double exact = segment_segment(s.a, s.b, s.c, s.d);
        // t -> dist(a + t (b - a), cd) is convex.
        const double reference =
            golden_min([&](double t) { return point_segment(lerp(s.a, s.b, t), s.c, s.d); });
        INFO("trial " << i);
        REQUIRE(std::isfinite(exact));
        CHECK(exact == Approx(reference).margin(1e-9));
        CHECK(segment_segment(s.c, s.d, s.a, s.b) == Approx(exact).margin(1e-12));
        CHECK(segment_segment(s.b, s.a, s.d, s.c) == Approx(exact).margin(1e-12));
    }
}

TEST_CASE("point-box distance, points on faces and inside", "[geometry]") {
    const Box3 box{Vec3(0, 0, 0), Vec3(1, 2, 3)};
    CHECK(point_box(Vec3(0.5, 1, 1), box) == 0.0);
    CHECK(point_box(Vec3(1, 1, 1), box) == 0.0);  // on a face
    CHECK(point_box(Vec3(1, 2, 3), box) == 0.0);  // a corner
    CHECK(point_box(Vec3(2, 1, 1), box) == Approx(1.0));
    CHECK(point_box(Vec3(2, 3, 1), box) == Approx(std::sqrt(2.0)));
    CHECK(point_box(Vec3(-1, -1, -1), box) == Approx(std::sqrt(3.0)));
    CHECK(nearest_in_box(Vec3(2, -1, 1), box) == Vec3(1, 0, 1));
    // A flat box (a plate).
    const Box3 plate{Vec3(0, 0, 0), Vec3(1, 1, 0)};
    CHECK(point_box(Vec3(0.5, 0.5, 0.2), plate) == Approx(0.2));
}

TEST_CASE("segment-box distance agrees with a golden-section search", "[geometry]") {
    std::mt19937 rng(32);
    for (int i = 0; i < 5000; ++i) {
        const Box3 box = random_box(rng);
        SegmentPair s = random_pair(rng);
        // Some segments run along a face or end on one.
        if (i % 5 == 1) s.a.x() = s.b.x() = box.max.x();
        if (i % 5 == 2) s.b = Vec3(box.min.x(), s.b.y(), s.b.z());
        double t = -1.0;
        const double exact = segment_box(s.a, s.b, box, &t);
        const double reference =
            golden_min([&](double u) { return point_box(lerp(s.a, s.b, u), box); });
        INFO("trial " << i);
        REQUIRE(std::isfinite(exact));
        CHECK(exact == Approx(reference).margin(1e-9));
        CHECK(t >= 0.0);
        CHECK(t <= 1.0);
        CHECK(point_box(lerp(s.a, s.b, t), box) == Approx(exact).margin(1e-12));
        CHECK(segment_box(s.b, s.a, box) == Approx(exact).margin(1e-12));
    }
    const Box3 unit{Vec3(0, 0, 0), Vec3(1, 1, 1)};
    // Through the box without an end inside it; along an edge; a point.
    CHECK(segment_box(Vec3(-1, 0.5, 0.5), Vec3(2, 0.5, 0.5), unit) == 0.0);
    CHECK(segment_box(Vec3(-1, 1, 1), Vec3(2, 1, 1), unit) == 0.0);
    CHECK(segment_box(Vec3(2, 2, 2), Vec3(2, 2, 2), unit) == Approx(std::sqrt(3.0)));
    CHECK(segment_box(Vec3(-1, 2, 0.5), Vec3(2, 2, 0.5), unit) == Approx(1.0));
}

TEST_CASE("hull distance is a tight lower bound", "[geometry]") {
    std::mt19937 rng(33);
    std::uniform_real_distribution<double> coord(-1.0, 1.0);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::uniform_int_distribution<int> count(1, 4);
    auto point = [&] { return Vec3(coord(rng), coord(rng), coord(rng)); };
    for (int i = 0; i < 3000; ++i) {
        // A hull of up to four points (a moving segment's two positions,
        // often degenerate) against a point, a segment or a box's corners.
        std::vector<Vec3> a, b;
        const int na = count(rng);
        for (int k = 0; k < na; ++k) a.push_back(point());
        if (i % 4 == 0 && na >= 2) a[1] = a[0] + 1e-9 * point();        // nearly a point
        if (i % 4 == 1 && na >= 3) a[2] = lerp(a[0], a[1], unit(rng));  // collinear
        const int kind = i % 3;
        if (kind == 0) {
            b = {2.0 * point()};
        } else if (kind == 1) {
            b = {2.0 * point(), 2.0 * point()};
        } else {
            const Box3 box = random_box(rng);
            for (int k = 0; k < 8; ++k)
                b.push_back(Vec3(k & 1 ? box.max.x() : box.min.x(),
                                 k & 2 ? box.max.y() : box.min.y(),
                                 k & 4 ? box.max.z() : box.min.z()));
        }
        const double bound = hull_distance(a, b);
        INFO("trial " << i);
        REQUIRE(std::isfinite(bound));
        REQUIRE(bound >= 0.0);
        // A lower bound: no pair of sampled hull points comes nearer.
        std::uniform_real_distribution<double> w(0.0, 1.0);
        double sampled = 1e9;
        for (int k = 0; k < 400; ++k) {
            auto combination = [&](const std::vector<Vec3>& set) {
                std::vector<double> weights;
                double sum = 0.0;
                for (std::size_t m = 0; m < set.size(); ++m) {
                    weights.push_back(-std::log(std::max(w(rng), 1e-300)));
                    sum += weights.back();
                }
                Vec3 x = Vec3::Zero();
                for (std::size_t m = 0; m < set.size(); ++m) x += weights[m] / sum * set[m];
                return x;
            };
            sampled = std::min(sampled, (combination(a) - combination(b)).norm());
        }
        for (const Vec3& p : a)
            for (const Vec3& q : b) sampled = std::min(sampled, (p - q).norm());
        CHECK(bound <= sampled + 1e-12);
        // Tight: against a point or a segment the exact distance is known
        // where the hull is a point or a segment.
        if (na == 1 && kind == 0) CHECK(bound == Approx((a[0] - b[0]).norm()).margin(1e-12));
        if (na == 1 && kind == 1)
            CHECK(bound == Approx(point_segment(a[0], b[0], b[1])).margin(1e-9));
        if (na == 2 && kind == 1)
            CHECK(bound == Approx(segment_segment(a[0], a[1], b[0], b[1])).margin(1e-9));
        if (na == 2 && kind == 2) {
            const Box3 box{b[0], b[7]};
            CHECK(bound == Approx(segment_box(a[0], a[1], box)).margin(1e-9));
        }
    }
    // A tetrahedron around the point: 0.
    const std::vector<Vec3> tet{Vec3(1, 0, 0), Vec3(-1, 1, 0), Vec3(-1, -1, 1), Vec3(-1, -1, -1)};
    CHECK(hull_distance(tet, std::vector<Vec3>{Vec3(0, 0, 0)}) == 0.0);
    // A face of it towards the point: the plane distance.
    const std::vector<Vec3> tri{Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
    CHECK(hull_distance(tri, std::vector<Vec3>{Vec3(0, 0, 0)}) == Approx(1.0 / std::sqrt(3.0)));
}
