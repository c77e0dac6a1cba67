#include <modsynth/geometry/distance_contractor.h>
#include <modsynth/geometry/interval.h>
#include <modsynth/geometry/vec.h>

#include <catch2/catch.hpp>
#include <random>

using namespace modsynth::geometry;

namespace {

double draw(std::mt19937& rng, const Interval& a) {
    return std::uniform_real_distribution<double>(a.lo, a.hi)(rng);
}

Interval random_interval(std::mt19937& rng, double lo, double hi) {
    std::uniform_real_distribution<double> u(lo, hi);
    const double a = u(rng), b = u(rng);
    return {std::min(a, b), std::max(a, b)};
}

}  // namespace

TEST_CASE("interval arithmetic holds every result of its operands", "[interval]") {
    std::mt19937 rng(7);
    for (int trial = 0; trial < 2000; ++trial) {
        const Interval a = random_interval(rng, -8.0, 8.0);
        const Interval b = random_interval(rng, -8.0, 8.0);
        for (int k = 0; k < 5; ++k) {
            const double x = draw(rng, a), y = draw(rng, b);
            CHECK((a + b).contains(x + y));
            CHECK((a - b).contains(x - y));
            CHECK((a * b).contains(x * y));
            CHECK(sqr(a).contains(x * x));
            CHECK(cos(a).contains(std::cos(x)));
            CHECK(sin(a).contains(std::sin(x)));
            if (x >= 0) CHECK(modsynth::geometry::sqrt(a).contains(std::sqrt(x)));
        }
    }
}

TEST_CASE("interval functions are tight where they can be", "[interval]") {
    CHECK(sqr(Interval(-1.0, 2.0)).lo == 0.0);
    CHECK(sqr(Interval(-1.0, 2.0)).hi == Approx(4.0));
    const Interval c = cos(Interval(0.1, kPi - 0.1));
    CHECK(c.lo == Approx(std::cos(kPi - 0.1)));
    CHECK(c.hi == Approx(std::cos(0.1)));
    CHECK(cos(Interval(-0.1, 0.1)).hi == 1.0);
    CHECK(sin(Interval(1.0, 2.0)).hi == 1.0);
    CHECK(sin(Interval(-2.0, -1.0)).lo == -1.0);
    CHECK(cos(Interval(0.0, 7.0)).lo == -1.0);
    CHECK(modsynth::geometry::sqrt(Interval(-2.0, -1.0)).is_empty());
    CHECK(intersect(Interval(0, 1), Interval(2, 3)).is_empty());
    CHECK(hull(Interval::empty(), Interval(2, 3)).lo == 2.0);
}

TEST_CASE("the distance contractor keeps every solution in its boxes", "[interval]") {
    std::mt19937 rng(11);
    int narrowed = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        IntervalPoint a{random_interval(rng, -2, 2), random_interval(rng, -2, 2)};
        IntervalPoint b{random_interval(rng, -2, 2), random_interval(rng, -2, 2)};
        Interval r = random_interval(rng, 0, 3);
        // A solution inside the boxes, when the draw finds one.
        const Vec2 pa(draw(rng, a.x), draw(rng, a.y));
        const Vec2 pb(draw(rng, b.x), draw(rng, b.y));
        const double d = (pa - pb).norm();
        const bool has = r.contains(d);
        const double before = a.x.width() + a.y.width() + b.x.width() + b.y.width() + r.width();
        const bool kept = contract_distance(a, b, r);
        if (!has) continue;
        REQUIRE(kept);
        CHECK(a.x.contains(pa.x()));
        CHECK(a.y.contains(pa.y()));
        CHECK(b.x.contains(pb.x()));
        CHECK(b.y.contains(pb.y()));
        CHECK(r.contains(d));
        if (a.x.width() + a.y.width() + b.x.width() + b.y.width() + r.width() < before - 1e-9)
            ++narrowed;
    }
    CHECK(narrowed > 100);  // it does contract, not only keep
}

TEST_CASE("the distance contractor narrows to the circle and refutes the impossible",
          "[interval]") {
    IntervalPoint a{Interval(0.0), Interval(0.0)};
    IntervalPoint b{Interval(-10, 10), Interval(0.5, 10)};
    Interval r(1.0);
    REQUIRE(contract_distance(a, b, r));
    CHECK(b.x.lo == Approx(-std::sqrt(0.75)).margin(1e-12));
    CHECK(b.x.hi == Approx(std::sqrt(0.75)).margin(1e-12));
    CHECK(b.y.hi == Approx(1.0).margin(1e-12));

    IntervalPoint c{Interval(0.0), Interval(0.0)};
    IntervalPoint far{Interval(5, 6), Interval(5, 6)};
    Interval short_r(0.0, 1.0);
    CHECK_FALSE(contract_distance(c, far, short_r));

    // Inside the inner radius: |a - b| <= 0.1 cannot be 1.
    IntervalPoint near{Interval(-0.05, 0.05), Interval(-0.05, 0.05)};
    IntervalPoint origin{Interval(0.0), Interval(0.0)};
    Interval one(1.0);
    CHECK_FALSE(contract_distance(origin, near, one));

    Interval x(-3, 1);
    REQUIRE(contract_sqr(x, Interval(1.0, 4.0)));
    CHECK(x.lo == Approx(-2.0));
    CHECK(x.hi == Approx(1.0));
    Interval y(0.5, 0.8);
    CHECK_FALSE(contract_sqr(y, Interval(1.0, 4.0)));
}
