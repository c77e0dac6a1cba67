// Forward kinematics and the position Jacobian of kinematics/dh_chain.h
// against Orocos KDL on random DH chains (Frame::DH is the classic
// convention formats.md uses).
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

#include <kdl/chain.hpp>
#include <kdl/chainfksolverpos_recursive.hpp>
#include <kdl/chainjnttojacsolver.hpp>

#include <modsynth/geometry/vec.h>
#include <modsynth/kinematics/dh_chain.h>

using namespace modsynth::kinematics;
using modsynth::geometry::Vec3;

namespace {

KDL::Chain kdl_chain(const DhChain& c) {
    KDL::Chain chain;
    for (const DhRow& r : c.rows)
        chain.addSegment(
            KDL::Segment(KDL::Joint(KDL::Joint::RotZ), KDL::Frame::DH(r.a, r.alpha, r.d, 0.0)));
    return chain;
}

DhChain random_chain(std::mt19937& rng, int n) {
    std::uniform_real_distribution<double> len(0.0, 0.8);
    std::uniform_real_distribution<double> coord(-1.0, 1.0);
    std::uniform_int_distribution<int> twist(0, 3);
    const double twists[] = {0.0, modsynth::geometry::kPi / 2, -modsynth::geometry::kPi / 2, 0.7};
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

}  // namespace

TEST_CASE("DH forward kinematics agrees with KDL", "[kinematics]") {
    std::mt19937 rng(51);
    std::uniform_real_distribution<double> angle(-4.0, 4.0);
    for (int i = 0; i < 1000; ++i) {
        const DhChain c = random_chain(rng, 1 + i % 6);
        std::vector<double> q;
        KDL::JntArray jq(static_cast<unsigned>(c.dof()));
        for (int k = 0; k < c.dof(); ++k) {
            q.push_back(angle(rng));
            jq(static_cast<unsigned>(k)) = q.back();
        }
        const KDL::Chain chain = kdl_chain(c);
        KDL::ChainFkSolverPos_recursive fk(chain);
        const auto fr = frames(c, q);
        INFO("chain " << i);
        for (int k = 0; k <= c.dof(); ++k) {
            KDL::Frame f;
            REQUIRE(fk.JntToCart(jq, f, k) >= 0);
            const Vec3 o = c.base + Vec3(f.p.x(), f.p.y(), f.p.z());
            CHECK((fr[static_cast<std::size_t>(k)].translation() - o).norm() < 1e-12);
            for (int r = 0; r < 3; ++r)
                for (int col = 0; col < 3; ++col)
                    CHECK(std::abs(fr[static_cast<std::size_t>(k)].linear()(r, col) -
                                   f.M(static_cast<unsigned>(r), static_cast<unsigned>(col))) <
                          1e-12);
        }
        KDL::ChainJntToJacSolver jac_solver(chain);
        KDL::Jacobian jac(static_cast<unsigned>(c.dof()));
        REQUIRE(jac_solver.JntToJac(jq, jac) >= 0);
        const auto j = position_jacobian(c, q);
        for (int r = 0; r < 3; ++r)
            for (int k = 0; k < c.dof(); ++k)
                CHECK(std::abs(j(r, k) - jac(static_cast<unsigned>(r), static_cast<unsigned>(k))) <
                      1e-12);
    }
}
