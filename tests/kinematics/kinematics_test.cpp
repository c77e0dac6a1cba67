#include <modsynth/kinematics/kinematics.h>

#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

namespace {

using namespace modsynth::kinematics;
using modsynth::geometry::cross;
using modsynth::geometry::kPi;
using modsynth::geometry::kTau;

bool near(const Vec2& a, const Vec2& b, double tol = 1e-12) { return (a - b).norm() <= tol; }

}  // namespace

TEST_CASE("forward kinematics", "[kinematics]") {
    const std::array<double, 2> lengths{1.0, 2.0};
    const std::array<double, 2> q{kPi / 2, -kPi / 2};
    const std::vector<Vec2> s = forward({1, 2}, lengths, q);
    REQUIRE(s.size() == 3);
    CHECK(s[0] == Vec2(1, 2));
    CHECK(near(s[1], {1, 3}));
    CHECK(near(s[2], {3, 3}));

    const std::array<double, 3> l3{1.0, 1.0, 1.0};
    const std::array<double, 3> q3{0.0, kPi / 2, kPi / 2};
    const std::vector<Vec2> s3 = forward({0, 0}, l3, q3);
    REQUIRE(s3.size() == 4);
    CHECK(near(s3[3], {0, 1}));

    CHECK(forward({4, 5}, {}, {}) == std::vector<Vec2>{{4, 5}});
}

TEST_CASE("absolute angles are prefix sums", "[kinematics]") {
    const std::array<double, 3> q{0.5, -0.25, 2.0};
    const std::vector<double> phi = absolute_angles(q);
    REQUIRE(phi.size() == 3);
    CHECK(phi[0] == 0.5);
    CHECK(phi[1] == 0.25);
    CHECK(phi[2] == 2.25);
}

TEST_CASE("elbow sign", "[kinematics]") {
    CHECK(elbow_sign(0.0) == 0);
    CHECK(elbow_sign(kPi) == 0);
    CHECK(elbow_sign(-kPi) == 0);
    CHECK(elbow_sign(1e-13) == 0);
    CHECK(elbow_sign(1e-9) == 1);
    CHECK(elbow_sign(1.0) == 1);
    CHECK(elbow_sign(-1.0) == -1);
    CHECK(elbow_sign(kTau + 1.0) == 1);
    CHECK(elbow_sign(kPi + 0.5) == -1);

    // The sign of eq. 5's cross product of the distal pair.
    std::mt19937 rng(31);
    std::uniform_real_distribution<double> angle(-7.0, 7.0);
    for (int i = 0; i < 1000; ++i) {
        const std::array<double, 2> lengths{0.7, 0.4};
        const std::array<double, 2> q{angle(rng), angle(rng)};
        const std::vector<Vec2> s = forward({0.1, -0.2}, lengths, q);
        const double c = cross(s[1] - s[0], s[2] - s[0]);
        CHECK(elbow_sign(q[1]) == (c > 0.0 ? 1 : -1));
    }
}

TEST_CASE("two-link inverse kinematics: analytic cases", "[kinematics]") {
    const Vec2 origin(1, 1);
    const Vec2 target = origin + Vec2(std::sqrt(2.0), 0.0);
    auto up = inverse_two_link(origin, 1.0, 1.0, target, +1);
    auto down = inverse_two_link(origin, 1.0, 1.0, target, -1);
    REQUIRE(up);
    REQUIRE(down);
    CHECK(up->q2 == Approx(kPi / 2));
    CHECK(up->phi1 == Approx(-kPi / 4));
    CHECK(down->q2 == Approx(-kPi / 2));
    CHECK(down->phi1 == Approx(kPi / 4));

    // Outside the annulus.
    CHECK_FALSE(inverse_two_link(origin, 1.0, 0.5, origin + Vec2(1.6, 0), 1));
    CHECK_FALSE(inverse_two_link(origin, 1.0, 0.5, origin + Vec2(0, 0.4), 1));
    CHECK_FALSE(inverse_two_link(origin, 1.0, 0.5, origin + Vec2(1.5 + 1e-9, 0), 1));

    // On the boundary, or within the tolerance beyond it: straight or folded.
    auto straight = inverse_two_link(origin, 1.0, 0.5, origin + Vec2(0, 1.5 + 5e-13), 1);
    REQUIRE(straight);
    CHECK(straight->q2 == 0.0);
    CHECK(straight->phi1 == Approx(kPi / 2));
    auto folded = inverse_two_link(origin, 1.0, 0.5, origin + Vec2(-0.5 + 5e-13, 0), -1);
    REQUIRE(folded);
    CHECK(std::abs(folded->q2) == Approx(kPi));
    CHECK(std::remainder(folded->phi1 - kPi, kTau) == Approx(0.0).margin(1e-12));

    // Equal links reach their own base.
    auto home = inverse_two_link(origin, 0.5, 0.5, origin, 1);
    REQUIRE(home);
    CHECK(std::abs(home->q2) == Approx(kPi));
}

TEST_CASE("two-link inverse kinematics round-trips through forward", "[kinematics]") {
    std::mt19937 rng(32);
    std::uniform_real_distribution<double> coord(-2.0, 2.0);
    std::uniform_real_distribution<double> link(0.05, 1.0);
    std::uniform_real_distribution<double> fraction(0.0, 1.0);
    std::uniform_real_distribution<double> angle(-kPi, kPi);
    for (int i = 0; i < 5000; ++i) {
        const Vec2 base(coord(rng), coord(rng));
        const double r1 = link(rng);
        const double r2 = link(rng);
        const double lo = std::abs(r1 - r2);
        const double hi = r1 + r2;
        // Strictly inside the annulus so that the elbow side is defined.
        const double d = lo + (hi - lo) * (1e-6 + (1.0 - 2e-6) * fraction(rng));
        const Vec2 target = base + d * modsynth::geometry::unit(angle(rng));
        for (const int elbow : {1, -1}) {
            const auto ik = inverse_two_link(base, r1, r2, target, elbow);
            INFO("trial " << i << " elbow " << elbow);
            REQUIRE(ik);
            const std::array<double, 2> lengths{r1, r2};
            const std::array<double, 2> q{ik->phi1, ik->q2};
            const std::vector<Vec2> s = forward(base, lengths, q);
            CHECK(near(s[2], target, 1e-9));
            CHECK(elbow_sign(ik->q2) == elbow);
            CHECK(std::abs(ik->q2) <= kPi);
            CHECK(cross(s[1] - s[0], s[2] - s[0]) * elbow > 0.0);
        }
    }
}

TEST_CASE("unwrapping keeps angles near the reference", "[kinematics]") {
    CHECK(unwrap_near(0.1, kTau) == Approx(kTau + 0.1));
    CHECK(unwrap_near(-3.0, 3.0) == Approx(kTau - 3.0));
    CHECK(unwrap_near(1.0, 1.0) == 1.0);

    std::mt19937 rng(33);
    std::uniform_real_distribution<double> wide(-100.0, 100.0);
    for (int i = 0; i < 10000; ++i) {
        const double angle = wide(rng);
        const double reference = wide(rng);
        const double u = unwrap_near(angle, reference);
        INFO("angle " << angle << " reference " << reference);
        CHECK(std::abs(u - reference) <= kPi + 1e-12);
        const double turns = (u - angle) / kTau;
        CHECK(turns == Approx(std::round(turns)).margin(1e-12));
    }
}

TEST_CASE("elbow_towards: the IK elbow in reach, a bent pose on the same side beyond it",
          "[kinematics]") {
    const Vec2 o(0.1, -0.2);
    for (int elbow : {1, -1}) {
        const Vec2 near(0.5, 0.1);
        const Vec2 e = elbow_towards(o, 0.3, 0.25, near, elbow);
        CHECK((e - o).norm() == Approx(0.3));
        CHECK((near - e).norm() == Approx(0.25));
        CHECK(elbow_sign(std::atan2(cross(e - o, near - e), (e - o).dot(near - e))) == elbow);
        const Vec2 far(2.0, 1.0);
        const Vec2 f = elbow_towards(o, 0.3, 0.25, far, elbow);
        CHECK((f - o).norm() == Approx(0.3));
        // Bent to the requested side of the line towards the target.
        CHECK(elbow * cross(f - o, far - o) > 0.0);
    }
}
