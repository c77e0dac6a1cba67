#include <modsynth/kinematics/yaw_pitch_ik.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include <modsynth/geometry/vec.h>

using namespace modsynth::kinematics;
using modsynth::geometry::kPi;
using modsynth::geometry::kTau;
using modsynth::geometry::Vec3;

namespace {

YawPitchArm random_arm(std::mt19937& rng, int dof) {
    std::uniform_real_distribution<double> len(0.1, 0.6);
    std::uniform_real_distribution<double> coord(-0.5, 0.5);
    YawPitchArm arm;
    arm.base = Vec3(coord(rng), coord(rng), coord(rng));
    arm.column = len(rng);
    arm.column_twist = rng() % 2 ? 1 : -1;
    for (int k = 1; k < dof; ++k) arm.links.push_back(len(rng));
    return arm;
}

double angle_gap(double a, double b) { return std::abs(std::remainder(a - b, kTau)); }

}  // namespace

TEST_CASE("a DH chain of the yaw-pitch pattern is recognised", "[kinematics]") {
    DhChain c;
    c.rows = {{0.0, kPi / 2, 0.4}, {0.3, 0.0, 0.0}, {0.25, 0.0, 0.0}};
    const auto arm = as_yaw_pitch(c);
    REQUIRE(arm);
    CHECK(arm->column == 0.4);
    CHECK(arm->column_twist == 1);
    CHECK(arm->links == std::vector<double>{0.3, 0.25});
    c.rows[0].alpha = -kPi / 2;
    CHECK(as_yaw_pitch(c)->column_twist == -1);
    c.rows[1].d = 0.1;  // not a pitch link
    CHECK_FALSE(as_yaw_pitch(c));
    c.rows[1].d = 0.0;
    c.rows[0].a = 0.1;  // the column is offset
    CHECK_FALSE(as_yaw_pitch(c));
    c.rows[0].a = 0.0;
    c.rows.pop_back();  // two joints
    CHECK_FALSE(as_yaw_pitch(c));
}

TEST_CASE("the yaw-pitch IK inverts forward kinematics on every branch", "[kinematics]") {
    std::mt19937 rng(81);
    std::uniform_real_distribution<double> angle(-kPi, kPi);
    int solved = 0;
    for (int i = 0; i < 4000; ++i) {
        const int dof = 3 + i % 4;
        const YawPitchArm arm = random_arm(rng, dof);
        const DhChain chain = to_chain(arm, 0.03);
        std::vector<double> q;
        for (int k = 0; k < dof; ++k) q.push_back(angle(rng));
        const Vec3 target = end_effector(chain, q);
        std::vector<double> pitches;
        double phi = q[1] + q[2];
        for (int k = 3; k < dof; ++k) pitches.push_back(phi += q[static_cast<std::size_t>(k)]);
        // The branch the pose is on: the EE in front of the column at yaw q1
        // (shoulder +1) or behind it; the elbow is q3's sign.
        const Vec3 v = target - arm.shoulder();
        const double x = v.x() * std::cos(q[0]) + v.y() * std::sin(q[0]);
        const IkBranch branch{x >= 0 ? 1 : -1, q[2] >= 0 ? 1 : -1};
        INFO("arm " << i << " dof " << dof);
        const auto got = yaw_pitch_ik(arm, target, branch, pitches);
        if (!got) {
            // Only near a singularity.
            const bool near_axis = std::hypot(v.x(), v.y()) < 1e-5;
            const bool near_fold = std::abs(std::sin(q[2])) < 1e-4;
            CHECK((near_axis || near_fold));
            continue;
        }
        ++solved;
        for (int k = 0; k < dof; ++k)
            CHECK(angle_gap((*got)[static_cast<std::size_t>(k)], q[static_cast<std::size_t>(k)]) <
                  1e-7);
        // Every other branch that exists reaches the same point.
        for (int shoulder : {1, -1})
            for (int elbow : {1, -1})
                if (const auto other = yaw_pitch_ik(arm, target, {shoulder, elbow}, pitches))
                    CHECK((end_effector(chain, *other) - target).norm() < 1e-9);
    }
    CHECK(solved > 3900);
}

TEST_CASE("the yaw-pitch IK gives up near singularities and out of reach", "[kinematics]") {
    YawPitchArm arm;
    arm.column = 0.4;
    arm.links = {0.3, 0.25};
    // On the column's axis: the yaw is undefined.
    CHECK_FALSE(yaw_pitch_ik(arm, arm.shoulder() + Vec3(0, 0, 0.3), {1, 1}));
    // Fully stretched and beyond.
    CHECK_FALSE(yaw_pitch_ik(arm, arm.shoulder() + Vec3(0.55, 0, 0), {1, 1}));
    CHECK_FALSE(yaw_pitch_ik(arm, arm.shoulder() + Vec3(0.7, 0, 0), {1, 1}));
    // Folded onto itself.
    CHECK_FALSE(yaw_pitch_ik(arm, arm.shoulder() + Vec3(0.05, 0, 0), {1, 1}));
    // The options widen the singular zones.
    IkOptions strict;
    strict.min_axis_distance = 0.08;
    strict.max_elbow_cos = 0.97;
    CHECK(yaw_pitch_ik(arm, arm.shoulder() + Vec3(0.05, 0.0, 0.3), {1, 1}));
    CHECK_FALSE(yaw_pitch_ik(arm, arm.shoulder() + Vec3(0.05, 0.0, 0.3), {1, 1}, {}, strict));
    // Hand pitches: one per hand link.
    CHECK_THROWS_AS(yaw_pitch_ik(arm, arm.shoulder() + Vec3(0.3, 0, 0), {1, 1}, {0.1}),
                    std::invalid_argument);
}
