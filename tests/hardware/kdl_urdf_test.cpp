// The exported URDF as a ROS stack loads it: kdl_parser builds the tree,
// the chain from "world" to "ee" reproduces modsynth's kinematics, and the
// masses are the catalog's.
#include <catch2/catch.hpp>

#include <kdl/chain.hpp>
#include <kdl/chainfksolverpos_recursive.hpp>
#include <kdl/tree.hpp>
#include <kdl_parser/kdl_parser.hpp>

#include <modsynth/hardware/catalog.h>
#include <modsynth/hardware/select_modules.h>
#include <modsynth/kinematics/kinematics.h>
#include <modsynth/output/exports.h>
#include <modsynth/output/urdf.h>

#include "../output/output_fixtures.h"

namespace testing = modsynth::testing;
using modsynth::synth::Solution;

namespace {

KDL::Chain chain_of(const std::string& urdf, const std::string& name) {
    const auto path = testing::scratch_dir("kdl_" + name) / "robot.urdf";
    modsynth::output::write_text_file(path.string(), urdf);
    KDL::Tree tree;
    REQUIRE(kdl_parser::treeFromFile(path.string(), tree));
    KDL::Chain chain;
    REQUIRE(tree.getChain("world", "ee", chain));
    return chain;
}

void check_forward_kinematics(const Solution& s, const KDL::Chain& chain) {
    REQUIRE(chain.getNrOfJoints() == static_cast<unsigned>(s.robot.dof()));
    KDL::ChainFkSolverPos_recursive fk(chain);
    int checked = 0;
    for (std::size_t i = 0; i < s.samples.size(); i += s.samples.size() / 9 + 1) {
        const auto& q = s.samples[i].q;
        KDL::JntArray jq(q.size());
        for (std::size_t k = 0; k < q.size(); ++k) jq(k) = q[k];
        KDL::Frame ee;
        REQUIRE(fk.JntToCart(jq, ee) >= 0);
        const auto expected = modsynth::kinematics::forward(s.robot.base, s.robot.link_lengths, q);
        CHECK(ee.p.x() == Approx(expected.back().x()).margin(2e-6));
        CHECK(ee.p.y() == Approx(expected.back().y()).margin(2e-6));
        CHECK(ee.p.z() == Approx(0.0).margin(2e-6));
        ++checked;
    }
    CHECK(checked >= 5);
}

double chain_mass(const KDL::Chain& chain) {
    double m = 0.0;
    for (unsigned i = 0; i < chain.getNrOfSegments(); ++i)
        m += chain.getSegment(i).getInertia().getMass();
    return m;
}

}  // namespace

TEST_CASE("kdl_parser loads the 2-joint URDF and its FK is the solution's", "[hardware]") {
    const auto task = testing::two_joint_task();
    Solution s = testing::two_joint_solution(task);
    s.robot.base = {0.02, -0.03};
    const std::string urdf = modsynth::output::robot_urdf(task, s);
    check_forward_kinematics(s, chain_of(urdf, "two"));
}

TEST_CASE("kdl_parser loads the 3-joint URDF and its FK is the solution's", "[hardware]") {
    const auto task = testing::three_joint_task();
    const Solution s = testing::three_joint_solution(task);
    const std::string urdf = modsynth::output::robot_urdf(task, s);
    check_forward_kinematics(s, chain_of(urdf, "three"));
}

TEST_CASE("the URDF carries the chosen modules' masses, limits and a ros2_control block",
          "[hardware]") {
    auto task = testing::two_joint_task();
    task.robot.payload = 0.3;
    Solution s = testing::two_joint_solution(task);
    const auto catalog = modsynth::hardware::load_default_catalog();
    // Joint 1 X8-9, joint 2 X5-4, as a selection would have it.
    modsynth::hardware::ModuleSelection sel;
    sel.checked = true;
    sel.joints.resize(2);
    sel.joints[0].module = "X8-9";
    sel.joints[1].module = "X5-4";
    s.modules = sel;
    const std::string urdf = modsynth::output::robot_urdf(task, s, catalog);
    const KDL::Chain chain = chain_of(urdf, "masses");
    // The chain from world holds module 1's housing (base link), both links
    // with module 2, the tubes, adapters, rod and payload.
    const double expected = catalog.actuator("X8-9")->mass + catalog.actuator("X5-4")->mass + 0.3;
    CHECK(chain_mass(chain) > expected);
    CHECK(chain_mass(chain) < expected + 1.0);
    CHECK(urdf.find("effort=\"20.000000\" velocity=\"3.142000\"") != std::string::npos);  // X8-9
    CHECK(urdf.find("effort=\"7.000000\" velocity=\"3.351000\"") != std::string::npos);   // X5-4
    CHECK(urdf.find("<ros2_control name=\"line\" type=\"system\">") != std::string::npos);
    for (const char* joint : {"joint_1", "joint_2"}) {
        const auto at = urdf.find(std::string("<joint name=\"") + joint +
                                  "\">\n      <command_interface name=\"position\"/>");
        CHECK(at != std::string::npos);
    }
    CHECK(urdf.find("<state_interface name=\"velocity\"/>") != std::string::npos);
    // Every link but the massless frames has an inertial.
    for (const char* link : {"base_module", "link_1", "link_2"}) {
        const auto at = urdf.find(std::string("<link name=\"") + link + "\">");
        REQUIRE(at != std::string::npos);
        CHECK(urdf.find("<inertial>", at) < urdf.find("</link>", at));
    }
}
