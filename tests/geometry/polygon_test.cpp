#include <modsynth/geometry/distance.h>
#include <modsynth/geometry/polygon.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace {

using namespace modsynth::geometry;

const std::vector<Vec2> kSquare{{0, 0}, {2, 0}, {2, 2}, {0, 2}};

bool contains(const std::vector<Vec2>& points, const Vec2& p) {
    return std::find(points.begin(), points.end(), p) != points.end();
}

}  // namespace

TEST_CASE("hull of a square with inner, edge and repeated points", "[geometry]") {
    const std::vector<Vec2> points{{1, 1}, {2, 2}, {0, 0}, {1, 0},     {2, 0}, {0, 2},
                                   {2, 1}, {0, 0}, {2, 2}, {0.5, 1.5}, {0, 1}};
    const std::vector<Vec2> hull = convex_hull(points);
    CHECK(hull == kSquare);
}

TEST_CASE("hulls of degenerate inputs", "[geometry]") {
    CHECK(convex_hull({}).empty());
    CHECK(convex_hull({{1, 2}}) == std::vector<Vec2>{{1, 2}});
    CHECK(convex_hull({{1, 2}, {1, 2}, {1, 2}}) == std::vector<Vec2>{{1, 2}});
    CHECK(convex_hull({{3, 1}, {1, 2}}) == std::vector<Vec2>{{1, 2}, {3, 1}});
    CHECK(convex_hull({{2, 2}, {0, 0}, {1, 1}, {3, 3}, {1, 1}}) ==
          std::vector<Vec2>{{0, 0}, {3, 3}});
    CHECK(convex_hull({{0, 0}, {1, 0}, {0, 1}}).size() == 3);
}

TEST_CASE("random hulls are convex, counter-clockwise and contain every point", "[geometry]") {
    std::mt19937 rng(21);
    std::uniform_real_distribution<double> coord(-1.0, 1.0);
    std::uniform_int_distribution<int> count(1, 60);
    std::uniform_int_distribution<int> grid(-3, 3);
    for (int i = 0; i < 500; ++i) {
        std::vector<Vec2> points(count(rng));
        // Every other set lies on a coarse grid: many collinear points and repeats.
        for (Vec2& p : points) {
            p = i % 2 == 0 ? Vec2(coord(rng), coord(rng)) : Vec2(grid(rng), grid(rng));
        }
        const std::vector<Vec2> hull = convex_hull(points);
        INFO("trial " << i);
        REQUIRE(!hull.empty());
        for (const Vec2& h : hull) CHECK(contains(points, h));
        for (const Vec2& p : points) CHECK(point_in_convex_polygon(p, hull));
        const std::size_t n = hull.size();
        if (n >= 3) {
            for (std::size_t k = 0; k < n; ++k) {
                const Vec2& a = hull[k];
                const Vec2& b = hull[(k + 1) % n];
                const Vec2& c = hull[(k + 2) % n];
                CHECK(cross(b - a, c - b) > 0.0);
            }
        }
    }
}

TEST_CASE("point in a convex polygon, boundary included", "[geometry]") {
    CHECK(point_in_convex_polygon({1, 1}, kSquare));
    CHECK(point_in_convex_polygon({1, 0}, kSquare));
    CHECK(point_in_convex_polygon({2, 2}, kSquare));
    CHECK(point_in_convex_polygon({0, 0.3}, kSquare));
    CHECK_FALSE(point_in_convex_polygon({1, -1e-9}, kSquare));
    CHECK_FALSE(point_in_convex_polygon({3, 1}, kSquare));
    CHECK_FALSE(point_in_convex_polygon({1, 1}, {}));

    // A boundary point computed with rounding still counts.
    const std::vector<Vec2> tri{{0, 0}, {1, 0}, {0.3, 0.7}};
    for (int k = 0; k <= 100; ++k) {
        const Vec2 p = tri[1] + (tri[2] - tri[1]) * (k / 100.0);
        CHECK(point_in_convex_polygon(p, tri));
    }

    const std::vector<Vec2> seg{{0, 0}, {2, 2}};
    CHECK(point_in_convex_polygon({1, 1}, seg));
    CHECK_FALSE(point_in_convex_polygon({1, 1.1}, seg));
    CHECK_FALSE(point_in_convex_polygon({3, 3}, seg));
    CHECK(point_in_convex_polygon({1, 2}, {{1, 2}}));
    CHECK_FALSE(point_in_convex_polygon({1, 2.1}, {{1, 2}}));
}

TEST_CASE("distance and gap to a convex polygon", "[geometry]") {
    CHECK(point_convex_polygon({1, 1}, kSquare) == 0.0);
    CHECK(point_convex_polygon({1, 0}, kSquare) == 0.0);
    CHECK(point_convex_polygon({1, -3}, kSquare) == Approx(3.0));
    CHECK(point_convex_polygon({5, 6}, kSquare) == Approx(5.0));
    CHECK(point_convex_polygon({5, 6}, {{2, 2}}) == Approx(5.0));
    CHECK(point_convex_polygon({1, 3}, {{0, 0}, {2, 0}}) == Approx(3.0));
    CHECK(disc_convex_polygon({1, -3}, 1.0, kSquare) == Approx(2.0));
    CHECK(disc_convex_polygon({1, -3}, 4.0, kSquare) == 0.0);
    CHECK(disc_convex_polygon({1, 1}, 0.1, kSquare) == 0.0);

    std::mt19937 rng(22);
    std::uniform_real_distribution<double> coord(-2.0, 2.0);
    for (int i = 0; i < 200; ++i) {
        std::vector<Vec2> points(8);
        for (Vec2& p : points) p = Vec2(coord(rng), coord(rng)) * 0.5;
        const std::vector<Vec2> hull = convex_hull(points);
        const Vec2 q(coord(rng), coord(rng));
        double edges = std::numeric_limits<double>::infinity();
        for (std::size_t k = 0; k < hull.size(); ++k) {
            edges = std::min(edges, point_segment(q, hull[k], hull[(k + 1) % hull.size()]));
        }
        const double d = point_convex_polygon(q, hull);
        INFO("trial " << i);
        if (point_in_convex_polygon(q, hull)) {
            CHECK(d == 0.0);
        } else {
            CHECK(d == Approx(edges).margin(1e-15));
        }
        CHECK(disc_convex_polygon(q, 0.3, hull) == Approx(std::max(0.0, d - 0.3)).margin(1e-15));
    }
}
