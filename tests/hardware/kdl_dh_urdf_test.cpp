// The URDF of a spatial arm as a ROS stack loads it: kdl_parser builds the
// tree, the chain from "world" to "ee" reproduces the DH chain's forward
// kinematics at every sample, and its inertials give the arm model's
// inverse dynamics.
#include <catch2/catch.hpp>

#include <random>
#include <string>

#include <kdl/chain.hpp>
#include <kdl/chainfksolverpos_recursive.hpp>
#include <kdl/chainidsolver_recursive_newton_euler.hpp>
#include <kdl/tree.hpp>
#include <kdl_parser/kdl_parser.hpp>

#include <modsynth/hardware/catalog.h>
#include <modsynth/hardware/dh_arm_model.h>
#include <modsynth/hardware/dh_dynamics.h>
#include <modsynth/hardware/select_dh_modules.h>
#include <modsynth/io/solution_io.h>
#include <modsynth/io/spatial_task_io.h>
#include <modsynth/kinematics/dh_chain.h>
#include <modsynth/output/dh_urdf.h>
#include <modsynth/output/exports.h>

#include "../output/output_fixtures.h"

using namespace modsynth;

namespace {

const std::string kFixtures = std::string(MODSYNTH_SOURCE_DIR) + "/tests/fixtures/spatial/";

KDL::Chain chain_of(const std::string& urdf, const std::string& name) {
    const auto path = testing::scratch_dir("kdl_dh_" + name) / "robot.urdf";
    output::write_text_file(path.string(), urdf);
    KDL::Tree tree;
    REQUIRE(kdl_parser::treeFromFile(path.string(), tree));
    KDL::Chain chain;
    REQUIRE(tree.getChain("world", "ee", chain));
    return chain;
}

}  // namespace

TEST_CASE("kdl_parser loads a spatial arm's URDF; its FK is the DH chain's at every sample",
          "[hardware]") {
    for (const char* name : {"s3-0001", "s3-0017", "s4-0010", "s4-0030"}) {
        const task::SpatialTask task = io::load_spatial_task(kFixtures + name + ".task.json");
        const synth::Solution s = io::load_solution(kFixtures + name + ".planted.json").solution;
        const kinematics::DhChain& dh = *s.dh_robot;
        const KDL::Chain chain = chain_of(output::robot_urdf(task, s), name);
        REQUIRE(chain.getNrOfJoints() == static_cast<unsigned>(dh.dof()));
        KDL::ChainFkSolverPos_recursive fk(chain);
        for (const auto& sample : s.samples) {
            KDL::JntArray q(static_cast<unsigned>(dh.dof()));
            for (int k = 0; k < dh.dof(); ++k) q(k) = sample.q[k];
            KDL::Frame ee;
            REQUIRE(fk.JntToCart(q, ee) >= 0);
            const Eigen::Isometry3d expected = kinematics::frames(dh, sample.q).back();
            for (int i = 0; i < 3; ++i) {
                CHECK(ee.p(i) == Approx(expected.translation()(i)).margin(1e-6));
                for (int j = 0; j < 3; ++j)
                    CHECK(ee.M(i, j) == Approx(expected.linear()(i, j)).margin(1e-6));
            }
        }
    }
}

TEST_CASE("a spatial URDF's inertials give the arm model's torques", "[hardware]") {
    const std::string name = "s4-0010";
    task::SpatialTask task = io::load_spatial_task(kFixtures + name + ".task.json");
    task.robot.payload = 0.4;
    task.robot.tool_length = 0.03;
    const synth::Solution s = io::load_solution(kFixtures + name + ".planted.json").solution;
    const auto catalog = hardware::load_default_catalog();
    const KDL::Chain chain = chain_of(output::robot_urdf(task, s, catalog), "dynamics");
    const auto modules = hardware::strongest_modules(task, s.dh_robot->dof(), catalog);
    const hardware::DhArmModel model =
        hardware::dh_arm_model(task.robot, *s.dh_robot, catalog, modules);
    const hardware::DhInverseDynamics dynamics(model);
    KDL::ChainIdSolver_RNE rne(chain, KDL::Vector(0.0, 0.0, -9.81));
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-2.0, 2.0);
    const unsigned n = chain.getNrOfJoints();
    for (int trial = 0; trial < 50; ++trial) {
        KDL::JntArray q(n), qd(n), qdd(n), tau(n);
        std::vector<double> vq, vqd, vqdd;
        for (unsigned k = 0; k < n; ++k) {
            vq.push_back(q(k) = u(rng));
            vqd.push_back(qd(k) = u(rng));
            vqdd.push_back(qdd(k) = u(rng));
        }
        const KDL::Wrenches none(chain.getNrOfSegments(), KDL::Wrench::Zero());
        REQUIRE(rne.CartToJnt(q, qd, qdd, none, tau) >= 0);
        const auto expected = dynamics.torques(vq, vqd, vqdd);
        for (unsigned k = 0; k < n; ++k) CHECK(tau(k) == Approx(expected[k]).margin(1e-4));
    }
}
