#include <modsynth/geometry/farthest_reach.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <stdexcept>

namespace {

using namespace modsynth::geometry;

// F(b) = max over the path of |p - b|, by dense sampling of the path (never
// above the true F).
double sampled_reach(const std::vector<Primitive>& path, const Vec2& b) {
    double f = 0.0;
    for (const Primitive& p : path)
        for (int k = 0; k <= 400; ++k)
            f = std::max(f, (point_at(p, length(p) * k / 400.0) - b).norm());
    return f;
}

}  // namespace

TEST_CASE("least farthest reach: a circle about a point of the box needs its radius") {
    const std::vector<Primitive> path{make_circle(Vec2(1.0, 0.0), Vec2(0.0, 0.0), true)};
    const FarthestReach r = least_farthest_reach(path, Vec2(-0.5, -0.5), Vec2(0.5, 0.5));
    CHECK(r.lower <= 1.0);
    CHECK(r.lower >= 1.0 - 1e-4);
    CHECK(r.upper >= r.lower);
    CHECK(r.at.norm() <= 1e-3);
}

TEST_CASE("least farthest reach: a box beside the path is bounded at its nearest corner") {
    // The base may only stand on [3, 4] x [1, 2]: the best is (3, 1), whose
    // farthest point of the unit circle about the origin is sqrt(10) + 1 away.
    const std::vector<Primitive> path{make_circle(Vec2(1.0, 0.0), Vec2(0.0, 0.0), false)};
    const FarthestReach r = least_farthest_reach(path, Vec2(3.0, 1.0), Vec2(4.0, 2.0));
    const double exact = std::sqrt(10.0) + 1.0;
    CHECK(r.lower <= exact);
    CHECK(r.lower >= exact - 1e-4);
    CHECK((r.at - Vec2(3.0, 1.0)).norm() <= 1e-3);
}

TEST_CASE("least farthest reach over the plane: the least circle around a triangle") {
    // An acute triangle's least enclosing circle is its circumcircle.
    const Vec2 a(0.0, 0.0), b(0.4, 0.0), c(0.15, 0.3);
    const std::vector<Primitive> path{make_line(a, b), make_line(b, c), make_line(c, a)};
    const double d =
        2.0 * (a.x() * (b.y() - c.y()) + b.x() * (c.y() - a.y()) + c.x() * (a.y() - b.y()));
    const double ux = (a.squaredNorm() * (b.y() - c.y()) + b.squaredNorm() * (c.y() - a.y()) +
                       c.squaredNorm() * (a.y() - b.y())) /
                      d;
    const double uy = (a.squaredNorm() * (c.x() - b.x()) + b.squaredNorm() * (a.x() - c.x()) +
                       c.squaredNorm() * (b.x() - a.x())) /
                      d;
    const double circumradius = (Vec2(ux, uy) - a).norm();
    const FarthestReach r = least_farthest_reach(path);
    CHECK(r.lower <= circumradius);
    CHECK(r.lower >= circumradius - 1e-4);
}

TEST_CASE("least farthest reach: a bound below F everywhere in the box, and tight") {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> coord(-1.0, 1.0), size(0.0, 0.6);
    for (int trial = 0; trial < 40; ++trial) {
        std::vector<Primitive> path;
        Vec2 at(coord(rng), coord(rng));
        for (int k = 0; k < 3; ++k) {
            const Vec2 next(coord(rng), coord(rng));
            if (k == 1)
                path.push_back(
                    make_arc(at, next, 0.5 * (at + next) + Vec2(0.2, -0.1), trial % 2 == 0));
            else
                path.push_back(make_line(at, next));
            at = path.back().end;
        }
        const Vec2 lo(coord(rng), coord(rng));
        const Vec2 hi = lo + Vec2(size(rng), trial % 5 == 0 ? 0.0 : size(rng));
        const FarthestReach r = least_farthest_reach(path, lo, hi);
        INFO("trial " << trial);
        double least = std::numeric_limits<double>::infinity();
        for (int i = 0; i <= 12; ++i)
            for (int j = 0; j <= 12; ++j) {
                const Vec2 b = lo + Vec2((hi - lo).x() * i / 12.0, (hi - lo).y() * j / 12.0);
                const double f = sampled_reach(path, b);
                least = std::min(least, f);
                // Sampling sees F from below, by at most the chord's sagitta.
                CHECK(r.lower <= f + 1e-5);
            }
        // upper is F at a point of the box, within the tolerance of its least.
        CHECK(r.upper <= least + 1e-4 + 1e-5);
        CHECK(r.upper - r.lower <= 1e-4 + 1e-12);
        CHECK(r.at.x() >= lo.x());
        CHECK(r.at.y() <= hi.y());
    }
}

TEST_CASE("least farthest reach: an evaluation cap loosens the bound, never breaks it") {
    const std::vector<Primitive> path{make_line(Vec2(-1.0, 0.3), Vec2(2.0, -0.7)),
                                      make_circle(Vec2(0.5, 0.5), Vec2(0.2, 0.1), true)};
    FarthestReachOptions capped;
    capped.max_evaluations = 9;
    const FarthestReach loose =
        least_farthest_reach(path, Vec2(-3.0, -3.0), Vec2(3.0, 3.0), capped);
    const FarthestReach tight = least_farthest_reach(path, Vec2(-3.0, -3.0), Vec2(3.0, 3.0));
    CHECK(loose.lower <= tight.lower);
    CHECK(loose.lower >= 0.0);
    FarthestReachOptions few_visits;  // 16 evaluations of this 2-primitive path
    few_visits.max_visits = 2.0;
    const FarthestReach visited =
        least_farthest_reach(path, Vec2(-3.0, -3.0), Vec2(3.0, 3.0), few_visits);
    CHECK(visited.lower <= tight.lower);
    CHECK(visited.lower >= loose.lower - 1e-12);
    CHECK(tight.upper - tight.lower <= 1e-4);
}

TEST_CASE("least farthest reach: an empty path or box is an error") {
    CHECK_THROWS_AS(least_farthest_reach({}, Vec2(0, 0), Vec2(1, 1)), std::invalid_argument);
    CHECK_THROWS_AS(
        least_farthest_reach({make_line(Vec2(0, 0), Vec2(1, 0))}, Vec2(1, 1), Vec2(0, 0)),
        std::invalid_argument);
}
