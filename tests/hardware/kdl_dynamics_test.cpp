// The recursive Newton-Euler of hardware/dynamics.h against Orocos KDL's
// ChainIdSolver_RNE on random planar chains and states.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

#include <kdl/chain.hpp>
#include <kdl/chainidsolver_recursive_newton_euler.hpp>

#include <modsynth/hardware/arm_model.h>
#include <modsynth/hardware/catalog.h>
#include <modsynth/hardware/dynamics.h>

using namespace modsynth::hardware;

namespace {

/// The same arm as a KDL chain: a joint about z, then the link to the next
/// joint along x. KDL expresses a segment's inertia in its tip frame (at the
/// next joint), so the centre of mass lies at com - r along x. Each body's
/// moment about its centre is the model's about z (the others do not enter
/// a planar motion about z, so any value does).
KDL::Chain kdl_chain(const ArmModel& m) {
    KDL::Chain chain;
    for (std::size_t k = 0; k < m.link_lengths.size(); ++k) {
        const LinkBody& b = m.links[k];
        chain.addSegment(KDL::Segment(
            KDL::Joint(KDL::Joint::RotZ), KDL::Frame(KDL::Vector(m.link_lengths[k], 0.0, 0.0)),
            KDL::RigidBodyInertia(b.mass, KDL::Vector(b.com - m.link_lengths[k], 0.0, 0.0),
                                  KDL::RotationalInertia(b.inertia, b.inertia, b.inertia))));
    }
    return chain;
}

std::vector<double> kdl_torques(const ArmModel& m, const std::vector<double>& q,
                                const std::vector<double>& qd, const std::vector<double>& qdd) {
    const KDL::Chain chain = kdl_chain(m);
    KDL::ChainIdSolver_RNE solver(chain, KDL::Vector(m.gravity.x(), m.gravity.y(), 0.0));
    const unsigned n = chain.getNrOfJoints();
    KDL::JntArray jq(n), jqd(n), jqdd(n), tau(n);
    for (unsigned k = 0; k < n; ++k) {
        jq(k) = q[k];
        jqd(k) = qd[k];
        jqdd(k) = qdd[k];
    }
    KDL::Wrenches external(chain.getNrOfSegments(), KDL::Wrench::Zero());
    REQUIRE(solver.CartToJnt(jq, jqd, jqdd, external, tau) >= 0);
    std::vector<double> out(n);
    for (unsigned k = 0; k < n; ++k) out[k] = tau(k);
    return out;
}

}  // namespace

TEST_CASE("planar Newton-Euler agrees with KDL's ChainIdSolver_RNE", "[hardware]") {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int compared = 0;
    for (int trial = 0; trial < 200; ++trial) {
        const int n = 2 + trial % 2;
        ArmModel m;
        for (int k = 0; k < n; ++k) {
            const double r = 0.1 + 0.5 * std::fabs(u(rng));
            m.link_lengths.push_back(r);
            m.links.push_back({0.05 + 2.0 * std::fabs(u(rng)), r * (0.5 + 0.6 * u(rng)),
                               0.02 * std::fabs(u(rng))});
        }
        // Half the chains in an upright plane, half with gravity along the axes.
        if (trial % 4 < 2) m.gravity = {9.81 * u(rng), 9.81 * u(rng)};
        std::vector<double> q(n), qd(n), qdd(n);
        for (int k = 0; k < n; ++k) {
            q[k] = 3.0 * u(rng);
            qd[k] = 2.0 * u(rng);
            qdd[k] = 5.0 * u(rng);
        }
        const auto ours = inverse_dynamics(m, q, qd, qdd);
        const auto theirs = kdl_torques(m, q, qd, qdd);
        for (int k = 0; k < n; ++k) {
            CHECK(ours[k] == Approx(theirs[k]).margin(1e-9).epsilon(1e-9));
            ++compared;
        }
    }
    CHECK(compared == 500);
}

TEST_CASE("the catalog-built arm's torques agree with KDL too", "[hardware]") {
    const Catalog catalog = load_catalog(std::string(MODSYNTH_SOURCE_DIR) + "/catalog");
    modsynth::task::RobotSpec spec;
    spec.payload = 0.4;
    spec.gravity = modsynth::geometry::Vec2(0.0, -9.81);
    modsynth::kinematics::Robot robot;
    robot.link_lengths = {0.3, 0.25, 0.2};
    robot.link_diameter = spec.link_diameter;
    const std::vector<const Actuator*> modules = {
        catalog.actuator("X8-16"), catalog.actuator("X8-9"), catalog.actuator("X5-4")};
    const ArmModel m = arm_model(spec, robot, catalog, modules);
    const std::vector<double> q{0.3, -0.8, 1.1}, qd{0.5, -0.2, 0.9}, qdd{1.0, 2.0, -1.5};
    const auto ours = inverse_dynamics(m, q, qd, qdd);
    const auto theirs = kdl_torques(m, q, qd, qdd);
    for (int k = 0; k < 3; ++k) CHECK(ours[k] == Approx(theirs[k]).epsilon(1e-9));
}
