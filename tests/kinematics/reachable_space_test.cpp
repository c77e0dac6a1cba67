#include <catch2/catch.hpp>

#include <vector>

#include <modsynth/kinematics/reachable_space.h>

using modsynth::kinematics::DistalPair;
using modsynth::kinematics::reachable_space;
using modsynth::kinematics::reaches_clear;
using Obstacle = modsynth::geometry::Disc;

namespace {

constexpr double kDiameter = 0.03175;

DistalPair arm() {
    DistalPair a;
    a.r1 = 0.30;
    a.r2 = 0.20;
    return a;
}

}  // namespace

TEST_CASE("reachable points lie in the annulus of the two links", "[output]") {
    const std::vector<Obstacle> none;
    CHECK(reaches_clear(arm(), none, kDiameter, {0.40, 0.0}));
    CHECK(reaches_clear(arm(), none, kDiameter, {0.0, -0.45}));
    CHECK_FALSE(reaches_clear(arm(), none, kDiameter, {0.51, 0.0}));  // beyond r1 + r2
    CHECK_FALSE(reaches_clear(arm(), none, kDiameter, {0.09, 0.0}));  // inside r1 - r2
}

TEST_CASE("a folded arm whose end-effector touches link 1 does not count", "[output]") {
    // At 0.105 m the arm is nearly folded: the EE is 26 mm from link 1, less
    // than the 31.75 mm diameter, on both branches.
    CHECK_FALSE(reaches_clear(arm(), {}, kDiameter, {0.105, 0.0}));
    CHECK(reaches_clear(arm(), {}, 0.02, {0.105, 0.0}));
}

TEST_CASE("an obstacle blocking both elbow branches makes a point unreachable", "[output]") {
    // Both branches' link 1 passes 70.7 mm from (0.2, 0).
    const std::vector<Obstacle> small{{{0.20, 0.0}, 0.02}};
    const std::vector<Obstacle> large{{{0.20, 0.0}, 0.06}};
    CHECK(reaches_clear(arm(), small, kDiameter, {0.45, 0.0}));
    CHECK_FALSE(reaches_clear(arm(), large, kDiameter, {0.45, 0.0}));
    // Obstacles on the middle of link 1 of one branch: the other one still reaches.
    const Obstacle up{{0.140, 0.053}, 0.02};
    const Obstacle down{{0.140, -0.053}, 0.02};
    CHECK(reaches_clear(arm(), {up}, kDiameter, {0.45, 0.0}));
    CHECK(reaches_clear(arm(), {down}, kDiameter, {0.45, 0.0}));
    CHECK_FALSE(reaches_clear(arm(), {up, down}, kDiameter, {0.45, 0.0}));
}

TEST_CASE("a 3-joint arm's distal pair hinges at joint 2 behind a still link 1", "[output]") {
    modsynth::kinematics::Robot robot;
    robot.base = {0.1, 0.0};
    robot.link_lengths = {0.25, 0.22, 0.20};
    robot.link_diameter = kDiameter;
    const std::vector<double> q{modsynth::geometry::kPi / 2, 0.0, 0.0};
    const DistalPair pair = modsynth::kinematics::distal_pair(robot, q);
    CHECK(pair.origin.x() == Approx(0.1));
    CHECK(pair.origin.y() == Approx(0.25));
    CHECK(pair.r1 == 0.22);
    CHECK(pair.r2 == 0.20);
    REQUIRE(pair.fixed_links.size() == 1);
    CHECK(reaches_clear(pair, {}, kDiameter, {0.45, 0.25}));
    // The EE must keep clear of link 1, which lies along x = 0.1.
    CHECK_FALSE(reaches_clear(pair, {}, kDiameter, {0.11, 0.10}));
    // An obstacle on link 1 leaves nothing reachable.
    const std::vector<Obstacle> on_link{{{0.1, 0.12}, 0.01}};
    CHECK_FALSE(reaches_clear(pair, on_link, kDiameter, {0.45, 0.25}));
}

TEST_CASE("the reachable grid shades the annulus and leaves obstacles out", "[output]") {
    const std::vector<Obstacle> obstacles{{{0.35, 0.0}, 0.05}};
    const auto g = reachable_space(arm(), obstacles, kDiameter, {-0.6, -0.6}, {0.6, 0.6}, 0.01);
    CHECK(g.nx == 120);
    CHECK(g.ny == 120);
    // The annulus covers pi (0.5^2 - 0.1^2) of 1.44 m^2, less the obstacle's shadow.
    CHECK(g.fraction() > 0.3);
    CHECK(g.fraction() < 3.1416 * (0.25 - 0.01) / 1.44);
    for (int j = 0; j < g.ny; ++j) {
        for (int i = 0; i < g.nx; ++i) {
            const auto p = g.center(i, j);
            if ((p - obstacles[0].center).norm() < obstacles[0].radius) CHECK_FALSE(g.at(i, j));
            if (p.norm() > 0.5) CHECK_FALSE(g.at(i, j));
        }
    }
}
