#include <modsynth/kinematics/dh_chain.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

#include <modsynth/geometry/vec.h>
#include <modsynth/kinematics/dh_motion_bound.h>

using namespace modsynth::kinematics;
using modsynth::geometry::kPi;
using modsynth::geometry::Vec3;

namespace {

/// frame k = frame k-1 * Rz(q) * Tz(d) * Tx(a) * Rx(alpha), one factor at a
/// time: an independent statement of formats.md's convention.
std::vector<Eigen::Isometry3d> reference_frames(const DhChain& c, const std::vector<double>& q) {
    std::vector<Eigen::Isometry3d> out;
    Eigen::Isometry3d f = Eigen::Isometry3d::Identity();
    f.translate(c.base);
    out.push_back(f);
    for (std::size_t k = 0; k < q.size(); ++k) {
        const DhRow& r = c.rows[k];
        f = f * Eigen::AngleAxisd(q[k], Vec3::UnitZ());
        f = f * Eigen::Translation3d(0, 0, r.d);
        f = f * Eigen::Translation3d(r.a, 0, 0);
        f = f * Eigen::AngleAxisd(r.alpha, Vec3::UnitX());
        out.push_back(f);
    }
    return out;
}

DhChain random_chain(std::mt19937& rng, int n) {
    std::uniform_real_distribution<double> len(0.05, 0.6);
    std::uniform_real_distribution<double> coord(-0.5, 0.5);
    std::uniform_int_distribution<int> twist(0, 2);
    const double twists[] = {0.0, kPi / 2, -kPi / 2};
    DhChain c;
    c.base = Vec3(coord(rng), coord(rng), coord(rng));
    c.link_diameter = 0.03;
    for (int k = 0; k < n; ++k) {
        DhRow r{len(rng), twists[twist(rng)], coord(rng)};
        if (rng() % 3 == 0) r.a = 0.0;
        if (rng() % 3 == 0) r.d = 0.0;
        c.rows.push_back(r);
    }
    return c;
}

std::vector<double> random_q(std::mt19937& rng, int n) {
    std::uniform_real_distribution<double> angle(-kPi, kPi);
    std::vector<double> q;
    for (int k = 0; k < n; ++k) q.push_back(angle(rng));
    return q;
}

}  // namespace

TEST_CASE("DH frames follow formats.md's convention", "[kinematics]") {
    std::mt19937 rng(71);
    for (int i = 0; i < 500; ++i) {
        const DhChain c = random_chain(rng, 1 + i % 6);
        const auto q = random_q(rng, c.dof());
        const auto got = frames(c, q);
        const auto want = reference_frames(c, q);
        for (std::size_t k = 0; k < got.size(); ++k)
            CHECK((got[k].matrix() - want[k].matrix()).cwiseAbs().maxCoeff() < 1e-12);
        CHECK((end_effector(c, q) - want.back().translation()).norm() < 1e-12);
    }
    // The column and pitch links of the planted arms (plant.py's Arm.points):
    // alpha = [pi/2, 0, 0], the pitch links in the vertical plane at yaw q1.
    DhChain arm;
    arm.base = Vec3(0.1, -0.2, 0.05);
    arm.rows = {{0.0, kPi / 2, 0.4}, {0.3, 0.0, 0.0}, {0.25, 0.0, 0.0}};
    const std::vector<double> q{0.7, 0.4, -1.1};
    const Vec3 shoulder = arm.base + Vec3(0, 0, 0.4);
    const double p2 = 0.4, p3 = 0.4 - 1.1;
    const Vec3 horizontal(std::cos(0.7), std::sin(0.7), 0.0);
    const Vec3 ee = shoulder + (0.3 * std::cos(p2) + 0.25 * std::cos(p3)) * horizontal +
                    Vec3(0, 0, 0.3 * std::sin(p2) + 0.25 * std::sin(p3));
    CHECK((end_effector(arm, q) - ee).norm() < 1e-12);
}

TEST_CASE("the chain's segments drop zero-length parts", "[kinematics]") {
    DhChain c;
    c.rows = {{0.0, kPi / 2, 0.4}, {0.3, 0.0, 0.0}, {0.2, kPi / 2, -0.1}};
    const auto layout = segment_layout(c);
    REQUIRE(layout.size() == 4);
    CHECK(layout[0].link == 0);
    CHECK(layout[0].along_axis);
    CHECK(layout[1].link == 1);
    CHECK_FALSE(layout[1].along_axis);
    CHECK(layout[2].along_axis);
    CHECK(layout[2].length == Approx(0.1));
    CHECK(layout[3].chain_start == Approx(0.8));
    CHECK(c.total_length() == Approx(1.0));
    const auto segs = chain_segments(c, std::vector<double>{0.3, -0.2, 0.5});
    REQUIRE(segs.size() == 4);
    CHECK((segs[0].end - segs[0].start).norm() == Approx(0.4));
    CHECK((segs[2].end - segs[2].start).norm() == Approx(0.1));
    for (std::size_t k = 0; k + 1 < segs.size(); ++k)
        CHECK((segs[k].end - segs[k + 1].start).norm() < 1e-12);
}

TEST_CASE("clearance parts leave out the mount and the tool", "[kinematics]") {
    // Segments of 0.4, 0.3 and 0.25 m.
    const std::vector<SegmentLayout> layout{
        {0, true, 0.4, 0.0}, {1, false, 0.3, 0.4}, {2, false, 0.25, 0.7}};
    auto parts = clearance_parts(layout, 0.1, 0.015);
    REQUIRE(parts.size() == 3);
    CHECK(parts[0].from == Approx(0.015 / 0.4));
    CHECK(parts[2].to == Approx(0.15 / 0.25));
    // A tool as long as the last segment removes it.
    parts = clearance_parts(layout, 0.25, 0.0);
    REQUIRE(parts.size() == 2);
    CHECK(parts[1].segment == 1);
    CHECK(parts[1].to == 1.0);
    // A mount longer than the first segment reaches into the second.
    parts = clearance_parts(layout, 0.0, 0.5);
    REQUIRE(parts.size() == 2);
    CHECK(parts[0].segment == 1);
    CHECK(parts[0].from == Approx(0.1 / 0.3));
}

TEST_CASE("the position Jacobian agrees with finite differences", "[kinematics]") {
    std::mt19937 rng(72);
    for (int i = 0; i < 300; ++i) {
        const DhChain c = random_chain(rng, 1 + i % 6);
        const auto q = random_q(rng, c.dof());
        const auto j = position_jacobian(c, q);
        for (int k = 0; k < c.dof(); ++k) {
            auto plus = q, minus = q;
            plus[static_cast<std::size_t>(k)] += 1e-6;
            minus[static_cast<std::size_t>(k)] -= 1e-6;
            const Vec3 d = (end_effector(c, plus) - end_effector(c, minus)) / 2e-6;
            CHECK((d - j.col(k)).norm() < 1e-8);
        }
    }
}

TEST_CASE("points stay within the chord bound along joint-linear steps", "[kinematics]") {
    std::mt19937 rng(73);
    std::uniform_real_distribution<double> step(-0.05, 0.05);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    double tightest = 1e9;
    for (int i = 0; i < 300; ++i) {
        const DhChain c = random_chain(rng, 1 + i % 6);
        const int n = c.dof();
        const auto qa = random_q(rng, n);
        std::vector<double> dq;
        for (int k = 0; k < n; ++k) dq.push_back(step(rng));
        const auto layout = segment_layout(c);
        auto at = [&](double tau) {
            std::vector<double> q = qa;
            for (int k = 0; k < n; ++k)
                q[static_cast<std::size_t>(k)] += tau * dq[static_cast<std::size_t>(k)];
            return frames(c, q);
        };
        const auto fa = at(0.0), fb = at(1.0);
        // A point of each segment, seen from the world and from every frame
        // before its link.
        for (std::size_t s = 0; s < layout.size(); ++s) {
            const double lambda = unit(rng);
            const int link = layout[s].link + 1;
            const int last = layout[s].along_axis ? link - 1 : link;
            const double reach = layout[s].chain_start + layout[s].length;
            auto point = [&](const std::vector<Eigen::Isometry3d>& f) {
                const auto segs = chain_segments(c, f);
                return Vec3(segs[s].start + lambda * (segs[s].end - segs[s].start));
            };
            for (int frame = 0; frame < link; ++frame) {
                auto seen = [&](const std::vector<Eigen::Isometry3d>& f) {
                    return Vec3(f[static_cast<std::size_t>(frame)].inverse() * point(f));
                };
                const Vec3 pa = seen(fa), pb = seen(fb);
                double worst = 0.0;
                for (int m = 1; m < 64; ++m) {
                    const double tau = m / 64.0;
                    worst = std::max(worst, (seen(at(tau)) - ((1 - tau) * pa + tau * pb)).norm());
                }
                const double bound = chord_gap(c, dq, frame, last, reach);
                INFO("chain " << i << " segment " << s << " frame " << frame);
                CHECK(worst <= bound + 1e-12);
                if (worst > 1e-6) tightest = std::min(tightest, bound / worst);
            }
        }
    }
    // Not absurdly loose either.
    CHECK(tightest < 20.0);
}
