#include <catch2/catch.hpp>

#include <cmath>

#include <modsynth/baseline/discretized_design.h>
#include <modsynth/geometry/primitive.h>
#include <modsynth/io/task_io.h>
#include <modsynth/kinematics/kinematics.h>
#include <modsynth/kinematics/pose_clearance.h>

#include "../support/derivative_check.h"
#include "../support/fixtures.h"

using namespace modsynth;
using geometry::Vec2;

namespace {

// Arc length from the start of the whole path to a sample.
double path_position(const task::Task& t, const baseline::PathSample& p) {
    double before = 0.0;
    for (int j = 0; j < p.primitive; ++j) before += geometry::length(t.trajectory[j]);
    return before + p.s;
}

void require_poses_reach_points(const task::Task& t, const baseline::PointDesign& d,
                                const std::vector<baseline::PathSample>& points) {
    REQUIRE(d.poses.size() == points.size());
    for (std::size_t k = 0; k < points.size(); ++k) {
        const auto joints = kinematics::forward(d.robot.base, d.robot.link_lengths, d.poses[k]);
        CHECK((joints.back() - points[k].point).norm() < 1e-6);
        // The design keeps a 3 mm clearance margin at its points.
        CHECK(kinematics::pose_clearance(t.obstacles, d.robot, d.poses[k]).worst() > 0.003 - 1e-6);
        // Elbow consistency: every pair bends to its design side or is straight.
        for (int i = 1; i < d.robot.dof(); ++i)
            CHECK(d.elbows[i - 1] * std::sin(d.poses[k][i]) > -1e-6);
    }
}

}  // namespace

TEST_CASE("equidistant points span the whole path at equal arc-length steps", "[baseline]") {
    const task::Task rose = io::load_task(testing::source_path("tasks/rose.json"));
    const auto points = baseline::equidistant_points(rose, 25);
    REQUIRE(points.size() == 25);
    CHECK((points.front().point - rose.trajectory.front().start).norm() < 1e-12);
    CHECK((points.back().point - rose.trajectory.back().end).norm() < 1e-9);
    double total = 0.0;
    for (const auto& p : rose.trajectory) total += geometry::length(p);
    for (std::size_t k = 0; k < points.size(); ++k) {
        CHECK(path_position(rose, points[k]) == Approx(total * k / 24.0).margin(1e-9));
        CHECK((geometry::point_at(rose.trajectory[points[k].primitive], points[k].s) -
               points[k].point)
                  .norm() < 1e-12);
    }
    CHECK_THROWS_AS(baseline::equidistant_points(rose, 1), std::invalid_argument);
}

TEST_CASE("the discretized design is the shortest robot that reaches the points", "[baseline]") {
    // No obstacles: the shortest 2-link arm reaches the farthest point,
    // (0.40, 0.30), straight from the nearest corner of the base region,
    // (0.05, 0.05).
    const task::Task t = testing::line_task();
    const auto points = baseline::equidistant_points(t, 10);
    const baseline::PointDesign d = baseline::design_for_points(t, points, {});
    REQUIRE(d.found);
    CHECK(d.robot.dof() == 2);
    CHECK(t.base_regions[0].contains(d.robot.base, 1e-9));
    CHECK(d.robot.total_length() == Approx(std::hypot(0.35, 0.25)).margin(1e-3));
    require_poses_reach_points(t, d, points);
}

TEST_CASE("the discretized design keeps every link clear of obstacles at its points",
          "[baseline]") {
    task::Task t = testing::line_task();
    t.obstacles.push_back({{0.22, 0.10}, 0.04});
    t.robot.dof = {3};
    const auto points = baseline::equidistant_points(t, 12);
    const baseline::PointDesign d = baseline::design_for_points(t, points, {});
    REQUIRE(d.found);
    CHECK(d.robot.dof() == 3);
    CHECK(d.elbows.size() == 2);
    require_poses_reach_points(t, d, points);
}

TEST_CASE("no discretized design when the points are out of reach", "[baseline]") {
    task::Task t = testing::line_task();
    t.robot.max_link_length = 0.1;
    const auto points = baseline::equidistant_points(t, 5);
    const baseline::PointDesign d = baseline::design_for_points(t, points, {});
    CHECK_FALSE(d.found);
    CHECK(d.message.find("5 points") != std::string::npos);
    CHECK(d.nlp_solves > 0);
}

TEST_CASE("discretized design derivatives agree with finite differences", "[baseline][nlp]") {
    // Every constraint kind of the design (links, elbow sides, clearance,
    // EE to lower links) and the smoothness term, for each joint count,
    // with and without a base region, on both elbow sides.
    const task::Task rose = io::load_task(testing::source_path("tasks/rose.json"));
    REQUIRE_FALSE(rose.obstacles.empty());
    const auto points = baseline::equidistant_points(rose, 8);
    const baseline::DesignOptions options;
    for (const auto& [dof, elbows] : std::vector<std::pair<int, std::vector<int>>>{
             {2, {1}}, {2, {-1}}, {3, {1, -1}}, {3, {-1, -1}}}) {
        for (int region : {-1, 0}) {
            const nlp::QuadraticProgram qp =
                baseline::design_program(rose, points, dof, region, elbows, options);
            INFO(dof << " joints, region " << region << ", last elbow " << elbows.back());
            REQUIRE(qp.num_constraints() > static_cast<int>(points.size() * rose.obstacles.size()));
            testing::check_derivatives(qp, 3);
            testing::check_derivatives(qp, 17);
        }
    }
}

TEST_CASE("a design program needs one elbow sign per link pair", "[baseline]") {
    const task::Task t = testing::line_task();
    const auto points = baseline::equidistant_points(t, 3);
    CHECK_THROWS_AS(baseline::design_program(t, points, 3, -1, {1}, {}), std::invalid_argument);
}
