#include <modsynth/output/dh_urdf.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include <modsynth/geometry/vec.h>
#include <modsynth/hardware/dh_arm_model.h>
#include <modsynth/hardware/dh_stack.h>
#include <modsynth/hardware/select_dh_modules.h>
#include <modsynth/kinematics/dh_chain.h>
#include <modsynth/output/urdf.h>
#include <modsynth/text/format.h>
#include <modsynth/text/printable.h>
#include <modsynth/text/xml.h>

namespace modsynth::output {
namespace {

using geometry::Vec3;

std::string num(double v) { return text::format("%.6f", v); }
std::string xyz(const Vec3& v) { return num(v.x()) + " " + num(v.y()) + " " + num(v.z()); }
std::string origin(const Vec3& at, const Vec3& rpy = Vec3::Zero()) {
    return "<origin xyz=\"" + xyz(at) + "\" rpy=\"" + xyz(rpy) + "\"/>";
}

/// A cylinder of `diameter` from a to b, both on the z or the x axis of the
/// link frame (the chain's segments are; URDF cylinders lie along z).
std::string cylinder(const char* element, const Vec3& a, const Vec3& b, double diameter,
                     const char* material) {
    const Vec3 d = b - a;
    const bool along_z = std::abs(d.z()) >= std::abs(d.x());
    std::string s =
        std::string("    <") + element + ">\n      " +
        origin((a + b) / 2.0, along_z ? Vec3::Zero() : Vec3(0.0, geometry::kPi / 2, 0.0)) +
        "\n      <geometry><cylinder radius=\"" + num(diameter / 2.0) + "\" length=\"" +
        num(d.norm()) + "\"/></geometry>\n";
    if (material) s += std::string("      <material name=\"") + material + "\"/>\n";
    return s + "    </" + element + ">\n";
}

std::string box(const task::SpatialRobotSpec& spec, const Vec3& at, double twist) {
    return "    <visual>\n      " + origin(at, Vec3(twist, 0.0, 0.0)) +
           "\n      <geometry><box size=\"" +
           xyz(Vec3(spec.module_length, spec.module_width, spec.module_height)) +
           "\"/></geometry>\n      <material name=\"module\"/>\n    </visual>\n";
}

/// Massless frames get a speck of mass: kdl_parser and simulators refuse
/// a link without it.
std::string inertial(const hardware::RigidBody& b) {
    const double mass = std::max(b.mass, 1e-6);
    const Eigen::Matrix3d I = b.inertia + 1e-9 * Eigen::Matrix3d::Identity();
    const auto g = [](double v) { return text::format("%.9g", v); };
    return "    <inertial>\n      " + origin(b.com) + "\n      <mass value=\"" + num(mass) +
           "\"/>\n      <inertia ixx=\"" + g(I(0, 0)) + "\" ixy=\"" + g(I(0, 1)) + "\" ixz=\"" +
           g(I(0, 2)) + "\" iyy=\"" + g(I(1, 1)) + "\" iyz=\"" + g(I(1, 2)) + "\" izz=\"" +
           g(I(2, 2)) + "\"/>\n    </inertial>\n";
}

struct Range {
    double lower = std::numeric_limits<double>::infinity();
    double upper = -std::numeric_limits<double>::infinity();
};

std::vector<Range> joint_ranges(const synth::Solution& solution, int n) {
    std::vector<Range> out(static_cast<std::size_t>(n));
    for (const auto& s : solution.samples)
        for (int k = 0; k < n; ++k) {
            out[k].lower = std::min(out[k].lower, s.q[k]);
            out[k].upper = std::max(out[k].upper, s.q[k]);
        }
    for (auto& r : out)
        if (!std::isfinite(r.lower)) r.lower = r.upper = 0.0;
    return out;
}

std::vector<const hardware::Actuator*> modules_of(const task::SpatialTask& task,
                                                  const synth::Solution& solution,
                                                  const hardware::Catalog& catalog, int n) {
    if (solution.modules && solution.modules->checked &&
        static_cast<int>(solution.modules->joints.size()) == n) {
        std::vector<const hardware::Actuator*> out;
        for (const auto& j : solution.modules->joints) {
            const hardware::Actuator* a = catalog.actuator(j.module);
            if (!a)
                throw std::runtime_error("the module catalog has no \"" +
                                         text::printable(j.module) + "\"");
            out.push_back(a);
        }
        return out;
    }
    return hardware::strongest_modules(task, n, catalog);
}

std::string joint(int k, const std::string& parent, const Vec3& at, double twist,
                  const Range& range, const hardware::Actuator& module) {
    return "  <joint name=\"" + urdf_joint_name(k) + "\" type=\"revolute\">\n    <parent link=\"" +
           parent + "\"/>\n    <child link=\"link_" + std::to_string(k + 1) + "\"/>\n    " +
           origin(at, Vec3(twist, 0.0, 0.0)) + "\n    <axis xyz=\"0 0 1\"/>\n    <limit lower=\"" +
           num(range.lower - kJointLimitMargin) + "\" upper=\"" +
           num(range.upper + kJointLimitMargin) + "\" effort=\"" + num(module.peak_torque) +
           "\" velocity=\"" + num(module.max_speed) + "\"/>\n  </joint>\n";
}

}  // namespace

std::string robot_urdf(const task::SpatialTask& task, const synth::Solution& solution) {
    return robot_urdf(task, solution, hardware::load_default_catalog());
}

std::string robot_urdf(const task::SpatialTask& task, const synth::Solution& solution,
                       const hardware::Catalog& catalog) {
    if (!solution.dh_robot) throw std::invalid_argument("robot_urdf: the solution has no DH robot");
    const kinematics::DhChain& chain = *solution.dh_robot;
    const task::SpatialRobotSpec& spec = task.robot;
    const int n = chain.dof();
    const double D = chain.link_diameter;
    const auto modules = modules_of(task, solution, catalog, n);
    const hardware::DhArmModel model = hardware::dh_arm_model(spec, chain, catalog, modules);
    const hardware::DhStack stack = hardware::dh_stack(spec, chain);
    const std::vector<Range> ranges = joint_ranges(solution, n);
    std::string names;
    for (const auto* m : modules) names += (names.empty() ? "" : ", ") + m->name;
    const bool chosen = solution.modules && solution.modules->checked;

    std::string s =
        "<?xml version=\"1.0\"?>\n<robot name=\"" + urdf_robot_name(task.name) + "\">\n";
    s += "  <!-- Spatial arm synthesised by modsynth: a Denavit-Hartenberg chain of " +
         std::to_string(n) +
         " joints. Frame \"world\" is the task frame (z up); link_k's frame is DH frame k-1 "
         "turned by joint k, and the origin of the tip link \"ee\" is the end-effector, and the z "
         "axis of link \"tool\" "
         "there is the tool's axis. Joint "
         "angles are those of the solution's samples. Modules (joint 1 first): " +
         text::xml_comment(names) +
         (chosen ? " (chosen to carry the motion)"
                 : " (not chosen for a load: the strongest allowed)") +
         ". Limits: the motion's range plus " + text::format("%.2f", kJointLimitMargin) +
         " rad; effort and velocity the module's peak torque and top speed. Inertials: the "
         "modules, tubes, adapters and brackets of the catalog, the tool and the payload. -->\n";
    s += "  <material name=\"module\"><color rgba=\"0.80 0.20 0.15 1\"/></material>\n";
    s += "  <material name=\"tube\"><color rgba=\"0.75 0.75 0.78 1\"/></material>\n";
    s += "  <material name=\"tool\"><color rgba=\"0.20 0.20 0.20 1\"/></material>\n";
    s += "  <link name=\"world\"/>\n";
    // Module 1's housing stands at the base, in frame 0 (the task's axes).
    hardware::RigidBody base;
    hardware::add_part(
        base, modules[0]->mass, Vec3::Zero(),
        hardware::box_inertia(modules[0]->mass,
                              Vec3(spec.module_length, spec.module_width, spec.module_height),
                              Eigen::Matrix3d::Identity()));
    s += "  <link name=\"base_module\">\n" + box(spec, Vec3::Zero(), 0.0) + inertial(base) +
         "  </link>\n";
    s += "  <joint name=\"base_mount\" type=\"fixed\">\n    <parent link=\"world\"/>\n"
         "    <child link=\"base_module\"/>\n    " +
         origin(chain.base) + "\n  </joint>\n";
    for (int k = 0; k < n; ++k) {
        const kinematics::DhRow& r = chain.rows[static_cast<std::size_t>(k)];
        const Vec3 end(r.a, 0.0, r.d);
        s += "  <link name=\"link_" + std::to_string(k + 1) + "\">\n";
        for (const hardware::DhTube& t : stack.tubes) {
            if (t.link != k) continue;
            const Vec3 u = (t.to - t.from).normalized();
            if (t.cut_length > 0.0)
                s += cylinder("visual", t.from + t.proximal_allowance * u,
                              t.to - t.distal_allowance * u, D, "tube");
            if (t.last && spec.tool_length > 0.0)
                s += cylinder("visual", t.to - spec.tool_length * u, t.to, spec.ee_rod_diameter,
                              "tool");
            // The chain's capsule, as the certificate checks it.
            s += cylinder("collision", t.from, t.to, D, nullptr);
        }
        if (k + 1 < n) s += box(spec, end, r.alpha);
        s += inertial(model.links[static_cast<std::size_t>(k)]);
        s += "  </link>\n";
        const std::string parent = k == 0 ? "base_module" : "link_" + std::to_string(k);
        const kinematics::DhRow* previous = k == 0 ? nullptr : &chain.rows[k - 1];
        s += joint(k, parent, previous ? Vec3(previous->a, 0.0, previous->d) : Vec3::Zero(),
                   previous ? previous->alpha : 0.0, ranges[k], *modules[k]);
    }
    const kinematics::DhRow& last = chain.rows.back();
    s += "  <link name=\"ee\"/>\n";
    s += "  <joint name=\"ee_tip\" type=\"fixed\">\n    <parent link=\"link_" + std::to_string(n) +
         "\"/>\n    <child link=\"ee\"/>\n    " +
         origin(Vec3(last.a, 0.0, last.d), Vec3(last.alpha, 0.0, 0.0)) + "\n  </joint>\n";
    // The tool's axis (formats.md: the chain's last segment, x_n when a_n > 0,
    // else sign(d_n) z_{n-1}, which frame n sees as (0, sin alpha, cos alpha))
    // as the z axis of a frame of its own, as tool frames are given to
    // planners that hold a direction.
    const Vec3 tool_rpy = last.a > kinematics::kZeroSegment ? Vec3(0.0, geometry::kPi / 2.0, 0.0)
                          : last.d >= 0.0                   ? Vec3(-last.alpha, 0.0, 0.0)
                                          : Vec3(geometry::kPi - last.alpha, 0.0, 0.0);
    s += "  <link name=\"tool\"/>\n";
    s += "  <joint name=\"tool_axis\" type=\"fixed\">\n    <parent link=\"ee\"/>\n"
         "    <child link=\"tool\"/>\n    " +
         origin(Vec3::Zero(), tool_rpy) + "\n  </joint>\n";
    s += ros2_control_block(task.name, solution, n);
    return s + "</robot>\n";
}

}  // namespace modsynth::output
