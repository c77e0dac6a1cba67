#include <modsynth/synth/initial_guess.h>

#include <chrono>

#include <catch2/catch.hpp>

#include <modsynth/kinematics/kinematics.h>

#include "../support/fixtures.h"

namespace {

using namespace modsynth;

smt::Skeleton two_joint_skeleton(int elbow) {
    smt::Skeleton s;
    s.dof = 2;
    s.elbow = elbow;
    s.base_region = 0;
    return s;
}

}  // namespace

TEST_CASE("initial guesses on an easy task are clear, distinct, in bounds and best first") {
    const task::Task t = testing::line_task();
    const auto guesses = synth::initial_guesses(t, two_joint_skeleton(1), 5, 1u);
    REQUIRE(!guesses.empty());
    REQUIRE(guesses.size() <= 5);
    CHECK(guesses.front().margin >= 0.0);
    for (std::size_t i = 0; i < guesses.size(); ++i) {
        const auto& r = guesses[i].robot;
        INFO("guess " << i);
        CHECK(r.elbow == 1);
        CHECK(r.base.x() >= t.base_regions[0].min.x());
        CHECK(r.base.x() <= t.base_regions[0].max.x());
        CHECK(r.base.y() >= t.base_regions[0].min.y());
        CHECK(r.base.y() <= t.base_regions[0].max.y());
        for (double l : r.link_lengths) {
            CHECK(l >= t.robot.min_link_length);
            CHECK(l <= t.robot.max_link_length);
        }
        // The stored margin is the one path_margin computes at that spacing.
        CHECK(guesses[i].margin == Approx(synth::path_margin(t, r, 0.02)).margin(1e-12));
        if (i > 0 && guesses[i - 1].margin >= 0.0 && guesses[i].margin >= 0.0)
            CHECK(guesses[i - 1].robot.total_length() <= guesses[i].robot.total_length());
        if (i > 0 && guesses[i - 1].margin < 0.0) CHECK(guesses[i - 1].margin >= guesses[i].margin);
    }
}

TEST_CASE("a clear initial guess reaches every point of the path with its elbow") {
    const task::Task t = testing::line_task();
    const auto guesses = synth::initial_guesses(t, two_joint_skeleton(-1), 3, 7u);
    REQUIRE(!guesses.empty());
    const auto& best = guesses.front();
    REQUIRE(best.margin >= 0.0);
    for (double s = 0.0; s <= 1.0; s += 0.05) {
        const geometry::Vec2 p =
            geometry::point_at(t.trajectory[0], s * geometry::length(t.trajectory[0]));
        CHECK(kinematics::inverse_two_link(best.robot.base, best.robot.link_lengths[0],
                                           best.robot.link_lengths[1], p, -1)
                  .has_value());
    }
}

TEST_CASE("initial guesses are deterministic in their seed") {
    const task::Task t = testing::line_task();
    const auto a = synth::initial_guesses(t, two_joint_skeleton(1), 4, 3u);
    const auto b = synth::initial_guesses(t, two_joint_skeleton(1), 4, 3u);
    REQUIRE(a.size() == b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        CHECK(a[i].robot.base == b[i].robot.base);
        CHECK(a[i].robot.link_lengths == b[i].robot.link_lengths);
        CHECK(a[i].margin == b[i].margin);
    }
}

TEST_CASE("an obstacle on the path makes every guess's margin negative") {
    task::Task t = testing::line_task();
    t.obstacles.push_back({{0.40, 0.18}, 0.03});
    const auto guesses = synth::initial_guesses(t, two_joint_skeleton(1), 5, 1u);
    REQUIRE(!guesses.empty());
    for (const auto& g : guesses) CHECK(g.margin < 0.0);
}

TEST_CASE("a path out of reach gives guesses whose margin says by how much") {
    task::Task t = testing::line_task();
    t.robot.max_link_length = 0.1;  // two links reach 0.2 m; the line is >= 0.4 m away
    t.robot.min_link_length = 0.05;
    const auto guesses = synth::initial_guesses(t, two_joint_skeleton(1), 5, 1u);
    for (const auto& g : guesses) CHECK(g.margin < -0.1);
}

TEST_CASE("a deadline in the past still returns only valid guesses") {
    const task::Task t = testing::line_task();
    const run::Deadline past = run::Deadline::in(-1.0);
    const auto guesses = synth::initial_guesses(t, two_joint_skeleton(1), 5, 1u, past);
    CHECK(guesses.size() <= 5);
    for (const auto& g : guesses) CHECK(g.robot.link_lengths.size() == 2);
}

TEST_CASE("three-joint guesses set a proximal angle per primitive") {
    task::Task t = testing::line_task();
    t.trajectory.push_back(geometry::make_line({0.40, 0.30}, {0.25, 0.30}));
    t.robot.dof = {3};
    smt::Skeleton s = two_joint_skeleton(1);
    s.dof = 3;
    const auto guesses = synth::initial_guesses(t, s, 3, 1u);
    REQUIRE(!guesses.empty());
    for (const auto& g : guesses) {
        CHECK(g.robot.link_lengths.size() == 3);
        CHECK(g.robot.proximal_angles.size() == t.trajectory.size());
    }
}
