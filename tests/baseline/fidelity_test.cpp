#include <catch2/catch.hpp>

#include <cmath>

#include <modsynth/baseline/fidelity.h>
#include <modsynth/kinematics/kinematics.h>

#include "../support/fixtures.h"

using namespace modsynth;
using geometry::Vec2;

namespace {

struct Reach {
    task::Task task;
    kinematics::Robot robot;
    Reach(double r1, double r2) {
        task.name = "reach";
        task.trajectory.push_back(geometry::make_line({0.30, 0.0}, {0.50, 0.0}));
        robot.base = {0.0, 0.0};
        robot.link_lengths = {r1, r2};
        robot.link_diameter = 0.02;
        robot.elbow = 1;
    }
    // The configuration that puts the EE at x on the line.
    std::vector<double> at(double x) const {
        const auto ik = kinematics::inverse_two_link(
            robot.base, robot.link_lengths[0], robot.link_lengths[1], Vec2(x, 0.0), robot.elbow);
        REQUIRE(ik);
        return {ik->phi1, ik->q2};
    }
};

}  // namespace

TEST_CASE("a motion that follows the path deviates by its chord error only", "[baseline]") {
    const Reach r(0.3, 0.3);
    std::vector<std::vector<double>> waypoints;
    for (int k = 0; k <= 200; ++k) waypoints.push_back(r.at(0.30 + 0.20 * k / 200));
    const baseline::Fidelity f = baseline::measure_fidelity(r.task, r.robot, waypoints);
    CHECK(f.max_deviation < 1e-5);
    CHECK(f.coverage_gap < 1e-5);
    CHECK(f.whole_path_reachable());
    CHECK(f.path_length == Approx(0.2));
}

TEST_CASE("joint-linear motion between two far points bows off the path", "[baseline]") {
    // Unequal links: with equal ones the EE would stay on the line by symmetry.
    const Reach r(0.35, 0.25);
    const std::vector<std::vector<double>> waypoints{r.at(0.30), r.at(0.50)};
    const baseline::Fidelity f = baseline::measure_fidelity(r.task, r.robot, waypoints);
    // The EE's distance to the line is |y|; its largest value along the
    // joint-linear motion, found by brute force here.
    double worst = 0.0;
    for (int k = 0; k <= 100000; ++k) {
        const double t = k / 100000.0;
        const std::vector<double> q{waypoints[0][0] + t * (waypoints[1][0] - waypoints[0][0]),
                                    waypoints[0][1] + t * (waypoints[1][1] - waypoints[0][1])};
        worst = std::max(
            worst, std::abs(kinematics::forward(r.robot.base, r.robot.link_lengths, q).back().y()));
    }
    CHECK(worst > 0.005);
    CHECK(f.max_deviation == Approx(worst).margin(1e-5));
    CHECK(f.coverage_gap > 0.0);
}

TEST_CASE("the part of the path beyond the arm's reach is measured", "[baseline]") {
    // Reach 0.45 m: the last 5 cm of the line are out of reach.
    const Reach r(0.25, 0.20);
    const baseline::Fidelity f =
        baseline::measure_fidelity(r.task, r.robot, {r.at(0.30), r.at(0.44)});
    CHECK_FALSE(f.whole_path_reachable());
    CHECK(f.outside_length == Approx(0.05).margin(0.0025));
    for (const Vec2& p : f.outside_points) CHECK(p.x() > 0.45 - 1e-9);
}
