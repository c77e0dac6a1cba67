#include <catch2/catch.hpp>

#include <cmath>

#include <modsynth/prove/loop_proof.h>
#include <modsynth/prove/provers.h>
#include <modsynth/task/part.h>

using namespace modsynth;
using geometry::Vec2;
using task::TaskPart;

namespace {

/// A base region at the origin, a post of radius `post` at (0.6, 0), links
/// of at most 1 m.
task::Task post_task(std::vector<geometry::Primitive> path, double post = 0.05,
                     std::vector<int> dof = {2}) {
    task::Task t;
    t.name = "loop";
    t.trajectory = std::move(path);
    t.obstacles.push_back({{0.6, 0.0}, post});
    t.base_regions.push_back({{-0.01, -0.01}, {0.01, 0.01}});
    t.robot.dof = std::move(dof);
    t.robot.max_link_length = 1.0;
    return t;
}

/// A regular polygon of n sides round `centre`, counter-clockwise unless cw.
std::vector<geometry::Primitive> polygon(int n, Vec2 centre, double radius, bool cw = false) {
    std::vector<geometry::Primitive> path;
    auto corner = [&](int k) {
        const double a = (cw ? -1.0 : 1.0) * geometry::kTau * k / n;
        return Vec2(centre + radius * Vec2(std::cos(a), std::sin(a)));
    };
    for (int k = 0; k < n; ++k) path.push_back(geometry::make_line(corner(k), corner(k + 1)));
    path.back().end = path.front().start;  // closed exactly, as a document writes it
    return path;
}

}  // namespace

TEST_CASE("a circle round a post is no path for two joints, whatever the base and links",
          "[prove][loop_proof]") {
    const task::Task t = post_task({geometry::make_circle({0.9, 0.0}, {0.6, 0.0}, true)});
    const auto loop = prove::loop_around_obstacle(t);
    REQUIRE(loop);
    CHECK(loop->turns == 1);
    const auto proof = prove::prove_two_joint_loop(t);
    REQUIRE(proof);
    CHECK(proof->core == std::vector<TaskPart>{TaskPart::trajectory(0), TaskPart::obstacle(0),
                                               TaskPart::robot(task::RobotKey::Dof)});
    CHECK_THAT(proof->message, Catch::Contains("trajectory[0] is a closed loop that winds once "
                                               "counter-clockwise round the centre of "
                                               "obstacles[0]"));
    // The provers try it for tasks of two joints only: a third joint can
    // turn the first link aside.
    bool proved = false;
    for (const auto& p : prove::provers({})) proved = proved || p.prove(t, run::Deadline::never());
    CHECK(proved);
    const task::Task three = post_task(t.trajectory, 0.05, {2, 3});
    for (const auto& p : prove::provers({})) CHECK_FALSE(p.prove(three, run::Deadline::never()));
}

TEST_CASE("each condition of the loop proof is needed", "[prove][loop_proof]") {
    // A loop that does not wind round the post.
    CHECK_FALSE(prove::prove_two_joint_loop(
        post_task({geometry::make_circle({0.3, 0.3}, {0.3, 0.2}, true)})));
    // Nearly round it, but open: 359 degrees.
    const double a = geometry::kTau * 359.0 / 360.0;
    CHECK_FALSE(prove::prove_two_joint_loop(post_task({geometry::make_arc(
        {0.9, 0.0}, {0.6 + 0.3 * std::cos(a), 0.3 * std::sin(a)}, {0.6, 0.0}, true)})));
    // A post of radius 0 and links of no width: a link may pass over it.
    task::Task thin = post_task({geometry::make_circle({0.9, 0.0}, {0.6, 0.0}, true)}, 0.0);
    thin.robot.link_diameter = 0.0;
    CHECK_FALSE(prove::prove_two_joint_loop(thin));
    // With width, the links' own diameter is part of the proof.
    thin.robot.link_diameter = 0.03;
    const auto proof = prove::prove_two_joint_loop(thin);
    REQUIRE(proof);
    CHECK(proof->core.back() == TaskPart::robot(task::RobotKey::LinkDiameter));
}

TEST_CASE("a polygon round a post, and a loop inside a longer stroke, name only the loop",
          "[prove][loop_proof]") {
    const task::Task t = post_task(polygon(32, {0.6, 0.0}, 0.3, true));
    const auto proof = prove::prove_two_joint_loop(t);
    REQUIRE(proof);
    CHECK(proof->core.size() == 34u);
    CHECK_THAT(proof->message, Catch::Contains("trajectory[0] to trajectory[31]") &&
                                   Catch::Contains("once clockwise"));
    // In from the left, round the post twice clockwise, out upwards: the
    // first time round is the shortest closed run.
    std::vector<geometry::Primitive> path = {geometry::make_line({0.1, 0.0}, {0.3, 0.0})};
    for (int lap = 0; lap < 2; ++lap)
        path.push_back(geometry::make_circle({0.3, 0.0}, {0.6, 0.0}, false));
    path.push_back(geometry::make_line({0.3, 0.0}, {0.3, 0.2}));
    const auto loop = prove::loop_around_obstacle(post_task(path));
    REQUIRE(loop);
    CHECK(loop->first == 1);
    CHECK(loop->last == 1);
    CHECK(loop->turns == -1);
    // Only runs of at most `longest` primitives, when asked.
    CHECK_FALSE(prove::loop_around_obstacle(t, 31));
    CHECK(prove::loop_around_obstacle(t, 32));
}
