#include <catch2/catch.hpp>

#include <cstdlib>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include <modsynth/output/exports.h>
#include <modsynth/output/urdf.h>

#include "output_fixtures.h"

namespace testing = modsynth::testing;
using modsynth::synth::Solution;

namespace {

// Just enough of URDF to walk the chain: the joints and their origins.
struct UrdfJoint {
    std::string name, type, parent, child;
    Eigen::Vector3d xyz = Eigen::Vector3d::Zero();
    Eigen::Vector3d rpy = Eigen::Vector3d::Zero();
    Eigen::Vector3d axis = Eigen::Vector3d::UnitX();
    double lower = 0.0, upper = 0.0;
};

std::string attribute(const std::string& element, const std::string& name) {
    const std::regex re(name + "=\"([^\"]*)\"");
    std::smatch m;
    return std::regex_search(element, m, re) ? m[1].str() : std::string();
}

/// The first <tag .../> or <tag ...> element in text, or "".
std::string element(const std::string& text, const std::string& tag) {
    const std::regex re("<" + tag + "\\b[^>]*>");
    std::smatch m;
    return std::regex_search(text, m, re) ? m[0].str() : std::string();
}

Eigen::Vector3d vector3(const std::string& text) {
    std::istringstream in(text);
    Eigen::Vector3d v;
    in >> v.x() >> v.y() >> v.z();
    return v;
}

std::vector<UrdfJoint> parse_joints(const std::string& full_urdf) {
    // The <ros2_control> block names the joints again in <joint> elements
    // of its own (interfaces, no kinematics): they are not the model's.
    const std::string urdf =
        std::regex_replace(full_urdf, std::regex("<ros2_control\\b[\\s\\S]*?</ros2_control>"), "");
    std::vector<UrdfJoint> out;
    const std::regex block("<joint\\b[^>]*>[\\s\\S]*?</joint>");
    for (auto it = std::sregex_iterator(urdf.begin(), urdf.end(), block);
         it != std::sregex_iterator(); ++it) {
        const std::string b = it->str();
        UrdfJoint j;
        const std::string head = element(b, "joint");
        j.name = attribute(head, "name");
        j.type = attribute(head, "type");
        j.parent = attribute(element(b, "parent"), "link");
        j.child = attribute(element(b, "child"), "link");
        const std::string origin = element(b, "origin");
        if (!origin.empty()) {
            j.xyz = vector3(attribute(origin, "xyz"));
            j.rpy = vector3(attribute(origin, "rpy"));
        }
        const std::string axis = element(b, "axis");
        if (!axis.empty()) j.axis = vector3(attribute(axis, "xyz"));
        const std::string limit = element(b, "limit");
        if (!limit.empty()) {
            j.lower = std::stod(attribute(limit, "lower"));
            j.upper = std::stod(attribute(limit, "upper"));
        }
        out.push_back(j);
    }
    return out;
}

/// Pose of `tip` in the root "world" frame, moving revolute joints in chain
/// order by the angles q.
Eigen::Isometry3d urdf_fk(const std::vector<UrdfJoint>& joints, const std::vector<double>& q,
                          const std::string& tip) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    std::string link = "world";
    std::size_t k = 0;
    while (link != tip) {
        const UrdfJoint* next = nullptr;
        for (const auto& j : joints) {
            if (j.parent == link) next = &j;
        }
        REQUIRE(next != nullptr);
        pose.translate(next->xyz);
        pose.rotate(Eigen::AngleAxisd(next->rpy.z(), Eigen::Vector3d::UnitZ()) *
                    Eigen::AngleAxisd(next->rpy.y(), Eigen::Vector3d::UnitY()) *
                    Eigen::AngleAxisd(next->rpy.x(), Eigen::Vector3d::UnitX()));
        if (next->type == "revolute") pose.rotate(Eigen::AngleAxisd(q.at(k++), next->axis));
        link = next->child;
    }
    CHECK(k == q.size());
    return pose;
}

void check_kinematics(const Solution& s, const std::string& urdf) {
    const auto joints = parse_joints(urdf);
    int revolute = 0;
    for (const auto& j : joints) {
        if (j.type != "revolute") continue;
        ++revolute;
        CHECK(j.axis == Eigen::Vector3d::UnitZ());
    }
    REQUIRE(revolute == s.robot.dof());
    // Several configurations of the motion, and a few arbitrary ones.
    std::vector<std::vector<double>> configurations;
    for (std::size_t i = 0; i < s.samples.size(); i += s.samples.size() / 7 + 1) {
        configurations.push_back(s.samples[i].q);
    }
    configurations.push_back(std::vector<double>(s.robot.dof(), 0.0));
    configurations.push_back(std::vector<double>(s.robot.dof(), 2.5));
    configurations.push_back(std::vector<double>(s.robot.dof(), -1.2));
    for (const auto& q : configurations) {
        const auto expected = modsynth::kinematics::forward(s.robot.base, s.robot.link_lengths, q);
        const Eigen::Vector3d ee = urdf_fk(joints, q, "ee").translation();
        CHECK(ee.x() == Approx(expected.back().x()).margin(2e-6));
        CHECK(ee.y() == Approx(expected.back().y()).margin(2e-6));
        CHECK(ee.z() == Approx(0.0).margin(2e-6));  // the tip touches the task plane
        // Each link's frame sits on its joint's axis, at s_k.
        for (int k = 0; k < s.robot.dof(); ++k) {
            const auto p = urdf_fk(joints, std::vector<double>(q.begin(), q.begin() + k + 1),
                                   "link_" + std::to_string(k + 1));
            CHECK(p.translation().x() == Approx(expected[k].x()).margin(2e-6));
            CHECK(p.translation().y() == Approx(expected[k].y()).margin(2e-6));
        }
    }
}

/// Every sampled angle lies within the URDF limits.
void check_limits(const Solution& s, const std::string& urdf) {
    std::vector<UrdfJoint> revolute;
    for (const auto& j : parse_joints(urdf)) {
        if (j.type == "revolute") revolute.push_back(j);
    }
    for (const auto& x : s.samples) {
        for (std::size_t k = 0; k < revolute.size(); ++k) {
            CHECK(x.q[k] >= revolute[k].lower);
            CHECK(x.q[k] <= revolute[k].upper);
        }
    }
}

/// check_urdf (Debian package liburdfdom-tools) accepts the file.
void check_with_urdfdom(const std::string& urdf, const std::string& name) {
    if (std::system("command -v check_urdf >/dev/null 2>&1") != 0) {
        WARN("check_urdf not installed (package liburdfdom-tools); skipping the parser check");
        return;
    }
    const auto path = testing::scratch_dir("urdf_" + name) / "robot.urdf";
    modsynth::output::write_text_file(path.string(), urdf);
    const std::string cmd = "check_urdf '" + path.string() + "' >/dev/null 2>&1";
    CHECK(std::system(cmd.c_str()) == 0);
}

}  // namespace

TEST_CASE("the URDF of a 2-joint arm matches modsynth's kinematics", "[output]") {
    const auto task = testing::two_joint_task();
    Solution s = testing::two_joint_solution(task);
    s.robot.base = {0.02, -0.03};  // FK must carry the base too
    const std::string urdf = modsynth::output::robot_urdf(task, s);
    CHECK(urdf.find("<robot name=\"line\">") != std::string::npos);
    check_kinematics(s, urdf);
    check_with_urdfdom(urdf, "two");
}

TEST_CASE("the URDF of a 3-joint arm matches modsynth's kinematics", "[output]") {
    const auto task = testing::three_joint_task();
    const Solution s = testing::three_joint_solution(task);
    const std::string urdf = modsynth::output::robot_urdf(task, s);
    check_kinematics(s, urdf);
    check_limits(s, urdf);
    check_with_urdfdom(urdf, "three");
}

TEST_CASE("URDF joint limits cover the motion with a margin", "[output]") {
    const auto task = testing::two_joint_task();
    const Solution s = testing::two_joint_solution(task);
    const std::string urdf = modsynth::output::robot_urdf(task, s);
    check_limits(s, urdf);
    double lo = 1e9;
    for (const auto& x : s.samples) lo = std::min(lo, x.q[0]);
    const auto joints = parse_joints(urdf);
    for (const auto& j : joints) {
        if (j.name == "joint_1")
            CHECK(j.lower == Approx(lo - modsynth::output::kJointLimitMargin).margin(1e-6));
    }
}

TEST_CASE("URDF links are stacked in z: each one module and one tube higher", "[output]") {
    const auto task = testing::three_joint_task();
    const Solution s = testing::three_joint_solution(task);
    const auto joints = parse_joints(modsynth::output::robot_urdf(task, s));
    const double h = task.robot.module_height, d = s.robot.link_diameter;
    const std::vector<double> q(3, 0.4);
    for (int k = 0; k < 3; ++k) {
        const auto p = urdf_fk(joints, std::vector<double>(q.begin(), q.begin() + k + 1),
                               "link_" + std::to_string(k + 1));
        CHECK(p.translation().z() == Approx((k + 1) * h + k * d));
    }
}

TEST_CASE("URDF names are sanitised", "[output]") {
    auto task = testing::two_joint_task();
    task.name = "my task <1>";
    const std::string urdf = modsynth::output::robot_urdf(task, testing::two_joint_solution(task));
    CHECK(urdf.find("<robot name=\"my_task__1_\">") != std::string::npos);
}

TEST_CASE("a hostile task name cannot break out of the URDF", "[output][escape]") {
    auto task = testing::two_joint_task();
    task.name = "x\"/><link name=\"evil\"/><!-- ]]> `|` \n'";
    const std::string urdf = modsynth::output::robot_urdf(task, testing::two_joint_solution(task));
    CHECK(urdf.find("<robot name=\"x____link_name__evil_____--___________\">") !=
          std::string::npos);
    CHECK(urdf.find("evil\"") == std::string::npos);
    CHECK(urdf.find("]]>") == std::string::npos);
}
