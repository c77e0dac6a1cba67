#include <modsynth/geometry/distance.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace {

using namespace modsynth::geometry;

constexpr double kInf = std::numeric_limits<double>::infinity();

std::vector<Vec2> sample_segment(const Vec2& a, const Vec2& b, int n) {
    std::vector<Vec2> points;
    points.reserve(n + 1);
    for (int k = 0; k <= n; ++k) points.push_back(a + (b - a) * (double(k) / n));
    return points;
}

std::vector<Vec2> sample_primitive(const Primitive& p, int n) {
    std::vector<Vec2> points;
    points.reserve(n + 1);
    for (int k = 0; k <= n; ++k) points.push_back(point_at(p, length(p) * k / n));
    return points;
}

double sampled_distance(const std::vector<Vec2>& u, const std::vector<Vec2>& v) {
    double best = kInf;
    for (const Vec2& x : u) {
        for (const Vec2& y : v) best = std::min(best, (x - y).squaredNorm());
    }
    return std::sqrt(best);
}

// Random segments biased toward the awkward cases: parallel, collinear,
// touching, degenerate.
struct SegmentPair {
    Vec2 a, b, c, d;
};

SegmentPair random_pair(std::mt19937& rng) {
    std::uniform_real_distribution<double> coord(-1.0, 1.0);
    std::uniform_real_distribution<double> scale(-1.5, 1.5);
    std::uniform_int_distribution<int> kind(0, 5);
    auto point = [&] { return Vec2(coord(rng), coord(rng)); };
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
            s.c = s.a + 0.5 * (scale(rng) / 1.5 + 1.0) * (s.b - s.a);
            break;
        case 3:  // degenerate
            s.d = s.c;
            break;
        default:
            break;
    }
    return s;
}

// A random line, arc or circle near the unit square.
Primitive random_primitive(std::mt19937& rng) {
    std::uniform_real_distribution<double> coord(-1.0, 1.0);
    std::uniform_real_distribution<double> radius(0.1, 1.0);
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

}  // namespace

TEST_CASE("segment parameter and point-segment distance", "[geometry]") {
    const Vec2 a(0, 0), b(4, 0);
    CHECK(segment_parameter({1, 3}, a, b) == Approx(0.25));
    CHECK(segment_parameter({-2, 3}, a, b) == 0.0);
    CHECK(segment_parameter({7, -3}, a, b) == 1.0);
    CHECK(segment_parameter({7, -3}, a, a) == 0.0);
    CHECK(point_segment({1, 3}, a, b) == Approx(3.0));
    CHECK(point_segment({-3, 4}, a, b) == Approx(5.0));
    CHECK(point_segment({7, 4}, a, b) == Approx(5.0));
    CHECK(point_segment({3, 4}, a, a) == Approx(5.0));
}

TEST_CASE("segment-segment distance: analytic cases", "[geometry]") {
    // Crossing, touching in a T, sharing an end point.
    CHECK(segment_segment({-1, 0}, {1, 0}, {0, -1}, {0, 1}) == 0.0);
    CHECK(segment_segment({-1, 0}, {1, 0}, {0, 0}, {0, 1}) == 0.0);
    CHECK(segment_segment({-1, 0}, {1, 0}, {1, 0}, {2, 5}) == 0.0);
    // Parallel.
    CHECK(segment_segment({0, 0}, {2, 0}, {1, 1}, {3, 1}) == Approx(1.0));
    CHECK(segment_segment({0, 0}, {2, 0}, {3, 1}, {5, 1}) == Approx(std::sqrt(2.0)));
    // Collinear, overlapping and apart.
    CHECK(segment_segment({0, 0}, {2, 0}, {1, 0}, {3, 0}) == 0.0);
    CHECK(segment_segment({0, 0}, {2, 0}, {3, 0}, {5, 0}) == Approx(1.0));
    // Degenerate.
    CHECK(segment_segment({0, 0}, {0, 0}, {1, -1}, {1, 1}) == Approx(1.0));
    CHECK(segment_segment({0, 0}, {0, 0}, {3, 4}, {3, 4}) == Approx(5.0));
    // Skew, apart.
    CHECK(segment_segment({0, 0}, {1, 1}, {3, 0}, {2, 0.5}) == Approx(std::sqrt(1.25)));
}

TEST_CASE("segment-segment distance agrees with dense sampling", "[geometry][slow]") {
    std::mt19937 rng(11);
    constexpr int kSamples = 400;
    for (int i = 0; i < 300; ++i) {
        const SegmentPair s = random_pair(rng);
        const double exact = segment_segment(s.a, s.b, s.c, s.d);
        const double sampled = sampled_distance(sample_segment(s.a, s.b, kSamples),
                                                sample_segment(s.c, s.d, kSamples));
        // The closest pair is within half a step of sampled points on each side.
        const double slack = 0.5 * ((s.b - s.a).norm() + (s.d - s.c).norm()) / kSamples;
        INFO("trial " << i);
        CHECK(exact <= sampled + 1e-12);
        CHECK(sampled <= exact + slack + 1e-12);
        CHECK(segment_segment(s.c, s.d, s.a, s.b) == Approx(exact).margin(1e-12));
        CHECK(segment_segment(s.b, s.a, s.c, s.d) == Approx(exact).margin(1e-12));
    }
}

TEST_CASE("point-primitive distance", "[geometry]") {
    const Primitive arc = make_arc({1, 0}, {0, 1}, {0, 0}, true);
    CHECK(point_primitive({2, 2}, arc) == Approx(std::sqrt(8.0) - 1.0));
    CHECK(point_primitive({0, 0}, arc) == Approx(1.0));
    CHECK(point_primitive({-1, -1}, arc) == Approx(std::sqrt(5.0)));
    CHECK(point_primitive({0, -2}, make_circle({1, 0}, {0, 0}, false)) == Approx(1.0));
    CHECK(point_primitive({1, 2}, make_line({0, 0}, {2, 0})) == Approx(2.0));

    std::mt19937 rng(12);
    std::uniform_real_distribution<double> coord(-2.0, 2.0);
    for (int i = 0; i < 2000; ++i) {
        const Primitive p = random_primitive(rng);
        const Vec2 q(coord(rng), coord(rng));
        INFO("trial " << i);
        CHECK(point_primitive(q, p) == Approx(nearest(p, q).distance).margin(1e-12));
    }
}

TEST_CASE("segment-primitive distance: analytic cases", "[geometry]") {
    const Primitive circle = make_circle({1, 0}, {0, 0}, true);
    // Through the circle, inside it, outside it.
    CHECK(segment_primitive({-2, 0}, {2, 0}, circle) == 0.0);
    CHECK(segment_primitive({0, 0}, {2, 0}, circle) == 0.0);
    CHECK(segment_primitive({-0.5, 0.1}, {0.5, 0.1}, circle) == Approx(1.0 - std::sqrt(0.26)));
    CHECK(segment_primitive({-2, 3}, {2, 3}, circle) == Approx(2.0));
    CHECK(segment_primitive({3, 3}, {3, 5}, circle) == Approx(std::sqrt(18.0) - 1.0));

    const Primitive upper = make_arc({1, 0}, {-1, 0}, {0, 0}, true);
    // The chord-parallel segment below the upper half circle: only its ends
    // come near.
    CHECK(segment_primitive({-2, -0.5}, {2, -0.5}, upper) == Approx(0.5));
    // Crossing the circle only where the arc is absent.
    CHECK(segment_primitive({0, -2}, {0, -0.5}, upper) == Approx(std::sqrt(1.25)));
    CHECK(segment_primitive({0, -2}, {0, 0.5}, upper) == Approx(0.5));
    CHECK(segment_primitive({0, -2}, {0, 2}, upper) == 0.0);
    // Above: the foot of the center is the closest point.
    CHECK(segment_primitive({-3, 2}, {3, 2}, upper) == Approx(1.0));

    // Only an end of the arc is near: the segment's ends and the foot of the
    // center are all far from it.
    const Primitive lower = make_arc(unit(-kPi / 3), unit(-kPi / 9), {0, 0}, true);
    const double expected = 2.0 - std::sin(kPi / 3);
    CHECK(segment_primitive({-10, -2}, {10, -2}, lower) == Approx(expected));

    const Primitive line = make_line({0, 0}, {1, 1});
    CHECK(segment_primitive({1, 0}, {0, 1}, line) == 0.0);
    CHECK(segment_primitive({2, 0}, {3, 0}, line) == Approx(std::sqrt(2.0)));

    CHECK(segment_primitive({0.5, 0.5}, {0.5, 0.5}, circle) == Approx(1.0 - std::sqrt(0.5)));
}

TEST_CASE("segment-primitive distance agrees with dense sampling", "[geometry][slow]") {
    std::mt19937 rng(13);
    constexpr int kSamples = 600;
    for (int i = 0; i < 400; ++i) {
        const Primitive p = random_primitive(rng);
        SegmentPair s = random_pair(rng);
        // Some segments pass near the center or touch the curve.
        if (i % 4 == 1) {
            switch (p.kind) {
                case PrimitiveKind::Line:
                    break;
                case PrimitiveKind::Arc:
                case PrimitiveKind::Circle:
                    s.c = p.center;
                    break;
            }
        }
        if (i % 4 == 2) s.a = point_at(p, 0.4 * length(p));
        const double exact = segment_primitive(s.a, s.b, p);
        const double sampled =
            sampled_distance(sample_segment(s.a, s.b, kSamples), sample_primitive(p, kSamples));
        const double slack = 0.5 * ((s.b - s.a).norm() + length(p)) / kSamples;
        INFO("trial " << i);
        CHECK(exact <= sampled + 1e-9);
        CHECK(sampled <= exact + slack + 1e-12);
        // Also against the exact point distance along a dense segment.
        double along = kInf;
        for (const Vec2& x : sample_segment(s.a, s.b, 20000)) {
            along = std::min(along, point_primitive(x, p));
        }
        CHECK(exact <= along + 1e-9);
        CHECK(along <= exact + 0.5 * (s.b - s.a).norm() / 20000 + 1e-12);
    }
}

TEST_CASE("disc-segment gap", "[geometry]") {
    CHECK(disc_segment({0, 2}, 0.5, {-1, 0}, {1, 0}) == Approx(1.5));
    CHECK(disc_segment({0, 2}, 2.5, {-1, 0}, {1, 0}) == 0.0);
    CHECK(disc_segment({3, 4}, 1.0, {0, 0}, {0, 0}) == Approx(4.0));
}
