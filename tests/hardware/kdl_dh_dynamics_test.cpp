// The spatial arm's inverse dynamics (KDL's recursive Newton-Euler behind
// hardware/dh_dynamics.h) against KDL's other formulation, the joint-space
// mass matrix, Coriolis and gravity terms of ChainDynParam, on a chain built
// here from the model with the bodies moved to KDL's tip frames by hand.
#include <catch2/catch.hpp>

#include <random>
#include <vector>

#include <Eigen/Geometry>
#include <kdl/chain.hpp>
#include <kdl/chaindynparam.hpp>

#include <modsynth/hardware/catalog.h>
#include <modsynth/hardware/dh_arm_model.h>
#include <modsynth/hardware/dh_dynamics.h>

using namespace modsynth::hardware;
using modsynth::geometry::kPi;
using modsynth::geometry::Vec3;

namespace {

KDL::Chain chain_of(const DhArmModel& m) {
    KDL::Chain chain;
    const Vec3& b = m.chain.base;
    chain.addSegment(
        KDL::Segment(KDL::Joint(KDL::Joint::None), KDL::Frame(KDL::Vector(b.x(), b.y(), b.z()))));
    for (std::size_t k = 0; k < m.chain.rows.size(); ++k) {
        const auto& r = m.chain.rows[k];
        // The tip frame is the joint frame moved by (a, 0, d) and turned by
        // Rx(alpha): a point p of the joint frame is R' (p - t) there.
        const Eigen::Matrix3d R =
            Eigen::AngleAxisd(r.alpha, Eigen::Vector3d::UnitX()).toRotationMatrix();
        const Vec3 t(r.a, 0.0, r.d);
        const RigidBody& body = m.links[k];
        const Vec3 com = R.transpose() * (body.com - t);
        const Eigen::Matrix3d I = R.transpose() * body.inertia * R;
        const KDL::RigidBodyInertia inertia(
            body.mass, KDL::Vector(com.x(), com.y(), com.z()),
            KDL::RotationalInertia(I(0, 0), I(1, 1), I(2, 2), I(0, 1), I(0, 2), I(1, 2)));
        chain.addSegment(KDL::Segment(KDL::Joint(KDL::Joint::RotZ),
                                      KDL::Frame::DH(r.a, r.alpha, r.d, 0.0), inertia));
    }
    return chain;
}

}  // namespace

TEST_CASE("spatial inverse dynamics equals KDL's M qdd + C + G", "[hardware]") {
    const Catalog catalog = load_default_catalog();
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> len(0.05, 0.6), coord(-0.5, 0.5), angle(-3.0, 3.0);
    const double twists[] = {0.0, kPi / 2, -kPi / 2, 0.7};
    for (int trial = 0; trial < 200; ++trial) {
        const int n = 3 + trial % 4;
        modsynth::kinematics::DhChain c;
        c.base = Vec3(coord(rng), coord(rng), coord(rng));
        c.link_diameter = 0.03175;
        std::vector<const Actuator*> modules;
        for (int k = 0; k < n; ++k) {
            modsynth::kinematics::DhRow r{len(rng), twists[rng() % 4], coord(rng)};
            if (rng() % 3 == 0) r.a = 0.0;
            if (rng() % 3 == 0) r.d = 0.0;
            c.rows.push_back(r);
            modules.push_back(&catalog.actuators[rng() % catalog.actuators.size()]);
        }
        modsynth::task::SpatialRobotSpec spec;
        spec.payload = 0.5;
        spec.tool_length = 0.01;
        spec.gravity = Vec3(coord(rng), coord(rng), -9.81);
        const DhArmModel m = dh_arm_model(spec, c, catalog, modules);
        const KDL::Chain chain = chain_of(m);
        KDL::ChainDynParam params(chain, KDL::Vector(m.gravity.x(), m.gravity.y(), m.gravity.z()));
        KDL::JntArray q(n), qd(n), gravity(n), coriolis(n);
        KDL::JntSpaceInertiaMatrix M(n);
        std::vector<double> vq, vqd, vqdd;
        for (int k = 0; k < n; ++k) {
            vq.push_back(q(k) = angle(rng));
            vqd.push_back(qd(k) = angle(rng));
            vqdd.push_back(angle(rng));
        }
        REQUIRE(params.JntToMass(q, M) >= 0);
        REQUIRE(params.JntToCoriolis(q, qd, coriolis) >= 0);
        REQUIRE(params.JntToGravity(q, gravity) >= 0);
        const auto tau = inverse_dynamics(m, vq, vqd, vqdd);
        for (int k = 0; k < n; ++k) {
            double expected = coriolis(k) + gravity(k);
            for (int j = 0; j < n; ++j) expected += M(k, j) * vqdd[j];
            CHECK(tau[k] == Approx(expected).margin(1e-9));
        }
    }
}
