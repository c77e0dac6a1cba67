#include <modsynth/geometry/obstacle3.h>

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <string>

#include <modsynth/geometry/distance3.h>

namespace {

using namespace modsynth::geometry;

/// Distance from segment ab to the obstacle's surface by dense sampling of
/// the segment (each point measured exactly).
double sampled_gap(const Vec3& a, const Vec3& b, const Obstacle3& o, int n) {
    double best = 1e9;
    for (int k = 0; k <= n; ++k) best = std::min(best, point_gap(a + (b - a) * (double(k) / n), o));
    return best;
}

}  // namespace

TEST_CASE("segment gaps to spheres, capsules and boxes", "[geometry]") {
    const Obstacle3 sphere = Sphere{Vec3(0, 0, 1), 0.5};
    CHECK(segment_gap(Vec3(-1, 0, 0), Vec3(1, 0, 0), sphere) == Approx(0.5));
    CHECK(segment_gap(Vec3(-1, 0, 1), Vec3(1, 0, 1), sphere) == Approx(-0.5));  // through it
    const Obstacle3 capsule = Capsule{Vec3(0, -1, 1), Vec3(0, 1, 1), 0.25};
    CHECK(segment_gap(Vec3(-1, 0, 0), Vec3(1, 0, 0), capsule) == Approx(0.75));
    // A capsule of one point is a sphere.
    const Obstacle3 dot = Capsule{Vec3(0, 0, 1), Vec3(0, 0, 1), 0.5};
    CHECK(segment_gap(Vec3(-1, 0, 0), Vec3(1, 0, 0), dot) == Approx(0.5));
    const Obstacle3 box = Box3{Vec3(-1, -1, 0.5), Vec3(1, 1, 1)};
    CHECK(segment_gap(Vec3(-2, 0, 0), Vec3(2, 0, 0), box) == Approx(0.5));
    CHECK(segment_gap(Vec3(0, 0, 0), Vec3(0, 0, 3), box) == 0.0);
    CHECK(segment_gap(Vec3(0, 0, 0.7), Vec3(0, 0, 0.8), box) == 0.0);  // inside
    CHECK(std::string(type_name(box)) == "box");
    CHECK(core_of(box).count == 8);
    CHECK(core_of(capsule).radius == 0.25);

    std::mt19937 rng(61);
    std::uniform_real_distribution<double> coord(-1.0, 1.0);
    std::uniform_real_distribution<double> radius(0.01, 0.4);
    for (int i = 0; i < 3000; ++i) {
        const Vec3 a(coord(rng), coord(rng), coord(rng));
        Vec3 b(coord(rng), coord(rng), coord(rng));
        if (i % 6 == 0) b = a;  // a point-like segment
        Obstacle3 o;
        const Vec3 c(coord(rng), coord(rng), coord(rng));
        switch (i % 3) {
            case 0:
                o = Sphere{c, radius(rng)};
                break;
            case 1: {
                Vec3 d(coord(rng), coord(rng), coord(rng));
                if (i % 4 == 1) d = c + (b - a);  // parallel to the segment
                o = Capsule{c, d, radius(rng)};
                break;
            }
            default: {
                const Vec3 side(radius(rng), radius(rng), radius(rng));
                o = Box3{c, c + side};
            }
        }
        const double exact = segment_gap(a, b, o);
        const int n = 4000;
        const double sampled = sampled_gap(a, b, o, n);
        INFO("trial " << i << " " << type_name(o));
        REQUIRE(std::isfinite(exact));
        CHECK(exact <= sampled + 1e-12);
        // The nearest point is within half a step of a sample, and the gap
        // is 1-Lipschitz along the segment.
        CHECK(sampled <= exact + 0.5 * (b - a).norm() / n + 1e-12);
        // The obstacle's core and radius describe it: the gap is the core's
        // distance less the radius, but for a box inside which a segment is 0.
        const ObstacleCore core = core_of(o);
        const double via_core = hull_distance(std::array<Vec3, 2>{a, b}, core.span()) - core.radius;
        CHECK(via_core <= std::max(exact, -core.radius) + 1e-9);
        if (exact > 1e-9) CHECK(via_core == Approx(exact).margin(1e-9));
        // The bounding sphere holds the obstacle.
        const Sphere around = bounding_sphere(o);
        for (std::size_t k = 0; k < core.count; ++k)
            CHECK((core.points[k] - around.center).norm() + core.radius <= around.radius + 1e-12);
    }
}
