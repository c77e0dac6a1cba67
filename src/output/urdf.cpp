#include <modsynth/output/urdf.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include <modsynth/geometry/vec.h>
#include <modsynth/hardware/arm_model.h>
#include <modsynth/hardware/select_modules.h>
#include <modsynth/output/hardware.h>
#include <modsynth/text/format.h>
#include <modsynth/text/printable.h>
#include <modsynth/text/xml.h>

namespace modsynth::output {
namespace {

std::string num(double v) { return text::format("%.6f", v); }

std::string xyz(double x, double y, double z) { return num(x) + " " + num(y) + " " + num(z); }

std::string origin(double x, double y, double z, double pitch = 0.0) {
    return "<origin xyz=\"" + xyz(x, y, z) + "\" rpy=\"" + xyz(0.0, pitch, 0.0) + "\"/>";
}

std::string box(const task::RobotSpec& spec, double x, double z) {
    return "    <visual>\n      " + origin(x, 0.0, z) + "\n      <geometry><box size=\"" +
           xyz(spec.module_length, spec.module_width, spec.module_height) +
           "\"/></geometry>\n      <material name=\"module\"/>\n    </visual>\n";
}

/// The body's planar moment (about z) is the model's own (arm_model.h);
/// about the link's axis a tube of the link's diameter, and across it the
/// same as about z, since every part lies along the link.
std::string inertial(const hardware::LinkBody& b, double z, double diameter) {
    const double mass = std::max(b.mass, 1e-6);
    const double izz = std::max(b.inertia, 1e-9);
    const double ixx = std::max(mass * diameter * diameter / 8.0, 1e-9);
    return "    <inertial>\n      " + origin(b.com, 0.0, z) + "\n      <mass value=\"" + num(mass) +
           "\"/>\n      <inertia ixx=\"" + text::format("%.9g", ixx) +
           "\" ixy=\"0\" ixz=\"0\" iyy=\"" + text::format("%.9g", izz) + "\" iyz=\"0\" izz=\"" +
           text::format("%.9g", izz) + "\"/>\n    </inertial>\n";
}

/// A cylinder along x from x0 to x1 at height z (URDF cylinders lie along z).
std::string x_cylinder(const char* element, double x0, double x1, double z, double diameter,
                       const char* material) {
    std::string s = std::string("    <") + element + ">\n      " +
                    origin((x0 + x1) / 2.0, 0.0, z, geometry::kPi / 2.0) +
                    "\n      <geometry><cylinder radius=\"" + num(diameter / 2.0) + "\" length=\"" +
                    num(x1 - x0) + "\"/></geometry>\n";
    if (material) s += std::string("      <material name=\"") + material + "\"/>\n";
    return s + "    </" + element + ">\n";
}

std::string rod(double x, double z_top, double length, double diameter) {
    return "    <visual>\n      " + origin(x, 0.0, z_top - length / 2.0) +
           "\n      <geometry><cylinder radius=\"" + num(diameter / 2.0) + "\" length=\"" +
           num(length) + "\"/></geometry>\n      <material name=\"rod\"/>\n    </visual>\n";
}

/// The body of a module whose axis is at x_axis, extending back along -x.
double body_center(const task::RobotSpec& spec, double x_axis) {
    return x_axis - (spec.module_length / 2.0 - spec.module_width / 2.0);
}

/// Module 1 stands on the table: its housing is the base link.
std::string base_link(const task::RobotSpec& spec, const hardware::Actuator& module) {
    hardware::LinkBody b;
    const double L = spec.module_length, W = spec.module_width;
    hardware::add_part(b, module.mass, body_center(spec, 0.0),
                       module.mass * (L * L + W * W) / 12.0);
    return "  <link name=\"base_module\">\n" +
           box(spec, body_center(spec, 0.0), spec.module_height / 2.0) +
           inertial(b, spec.module_height / 2.0, spec.module_width) + "  </link>\n";
}

/// Link k (0-based) in its joint's frame: the output face at z = 0, the
/// tube on it, and the next module standing on the tube (or the EE rod).
std::string arm_link(const task::RobotSpec& spec, const kinematics::Robot& robot,
                     const TubeCut& cut, const hardware::LinkBody& body, int k) {
    const double d = robot.link_diameter;
    const double r = cut.link_length;
    std::string s = "  <link name=\"link_" + std::to_string(k + 1) + "\">\n";
    if (cut.cut_length > 0.0) {
        s += x_cylinder("visual", cut.proximal_allowance, r - cut.distal_allowance, d / 2.0, d,
                        "tube");
    }
    s += x_cylinder("collision", 0.0, r, d / 2.0, d, nullptr);
    if (cut.last) {
        s += rod(r, d, ee_rod_length(spec, d, robot.dof()), spec.ee_rod_diameter);
    } else {
        s += box(spec, body_center(spec, r), d + spec.module_height / 2.0);
    }
    s += inertial(body, d / 2.0, d);
    return s + "  </link>\n";
}

struct Range {
    double lower = std::numeric_limits<double>::infinity();
    double upper = -std::numeric_limits<double>::infinity();
    double speed = 0.0;
};

/// Each joint's range and fastest speed over the motion.
std::vector<Range> joint_ranges(const synth::Solution& solution) {
    std::vector<Range> out(solution.robot.link_lengths.size());
    const auto& samples = solution.samples;
    for (std::size_t i = 0; i < samples.size(); ++i) {
        for (std::size_t k = 0; k < out.size(); ++k) {
            out[k].lower = std::min(out[k].lower, samples[i].q[k]);
            out[k].upper = std::max(out[k].upper, samples[i].q[k]);
            const double dt = i > 0 ? samples[i].t - samples[i - 1].t : 0.0;
            if (dt > 0.0) {
                out[k].speed =
                    std::max(out[k].speed, std::abs(samples[i].q[k] - samples[i - 1].q[k]) / dt);
            }
        }
    }
    for (auto& r : out) {
        if (!std::isfinite(r.lower)) r.lower = r.upper = 0.0;
    }
    return out;
}

std::string revolute(int k, const std::string& parent, double x, double z, const Range& range,
                     const hardware::Actuator& module) {
    return "  <joint name=\"" + urdf_joint_name(k) + "\" type=\"revolute\">\n    <parent link=\"" +
           parent + "\"/>\n    <child link=\"link_" + std::to_string(k + 1) + "\"/>\n    " +
           origin(x, 0.0, z) + "\n    <axis xyz=\"0 0 1\"/>\n    <limit lower=\"" +
           num(range.lower - kJointLimitMargin) + "\" upper=\"" +
           num(range.upper + kJointLimitMargin) + "\" effort=\"" + num(module.peak_torque) +
           "\" velocity=\"" + num(module.max_speed) + "\"/>\n  </joint>\n";
}

std::string fixed_joint(const char* name, const std::string& parent, const std::string& child,
                        double x, double y, double z) {
    return std::string("  <joint name=\"") + name + "\" type=\"fixed\">\n    <parent link=\"" +
           parent + "\"/>\n    <child link=\"" + child + "\"/>\n    " + origin(x, y, z) +
           "\n  </joint>\n";
}

std::string preamble(const task::Task& task, const std::string& modules, bool chosen) {
    std::string s =
        "<?xml version=\"1.0\"?>\n<robot name=\"" + urdf_robot_name(task.name) + "\">\n";
    s += "  <!-- Planar arm synthesised by modsynth. Frame \"world\" is the task plane (z up); "
         "the tip link \"ee\" touches it. Joint angles are those of the solution's samples. "
         "Modules (joint 1 first): " +
         text::xml_comment(modules) +
         (chosen ? " (chosen to carry the motion)"
                 : " (not chosen for a load: the strongest allowed)") +
         ". Limits: the motion's range plus " + std::to_string(kJointLimitMargin).substr(0, 4) +
         " rad; effort and velocity the module's peak torque and top speed. Inertials: the "
         "modules, tubes and adapters of the catalog, with the payload at the tool. -->\n";
    s += "  <material name=\"module\"><color rgba=\"0.80 0.20 0.15 1\"/></material>\n";
    s += "  <material name=\"tube\"><color rgba=\"0.75 0.75 0.78 1\"/></material>\n";
    s += "  <material name=\"rod\"><color rgba=\"0.20 0.20 0.20 1\"/></material>\n";
    return s + "  <link name=\"world\"/>\n";
}

/// The chosen modules when the solution has them, else the strongest
/// allowed module at every joint.
std::vector<const hardware::Actuator*> urdf_modules(const task::Task& task,
                                                    const synth::Solution& solution,
                                                    const hardware::Catalog& catalog) {
    const int n = solution.robot.dof();
    std::vector<const hardware::Actuator*> out;
    if (solution.modules && solution.modules->checked &&
        static_cast<int>(solution.modules->joints.size()) == n) {
        for (const auto& j : solution.modules->joints) {
            const hardware::Actuator* a = catalog.actuator(j.module);
            if (!a)
                throw std::runtime_error("the module catalog has no \"" +
                                         text::printable(j.module) + "\"");
            out.push_back(a);
        }
        return out;
    }
    const auto allowed = hardware::allowed_actuators(task.robot, catalog);
    const auto strongest = std::max_element(
        allowed.begin(), allowed.end(),
        [](const auto* a, const auto* b) { return a->peak_torque < b->peak_torque; });
    return std::vector<const hardware::Actuator*>(n, *strongest);
}

}  // namespace

std::string urdf_joint_name(int k) { return "joint_" + std::to_string(k + 1); }

std::string urdf_robot_name(const std::string& task_name) {
    std::string out;
    for (char c : task_name)
        out += std::isalnum(static_cast<unsigned char>(c)) || c == '-' ? c : '_';
    return out.empty() ? "modsynth_arm" : out;
}

/// A ros2_control system for the arm: each joint commanded by position,
/// reporting position and velocity, starting at the motion's first pose. The
/// plugin is ros2_control's mock system, which runs the arm without hardware;
/// a real arm names its modules' driver there instead.
std::string ros2_control_block(const std::string& task_name, const synth::Solution& solution,
                               int dof) {
    std::string s = "  <ros2_control name=\"" + urdf_robot_name(task_name) +
                    "\" type=\"system\">\n    <hardware>\n      "
                    "<plugin>mock_components/GenericSystem</plugin>\n    </hardware>\n";
    for (int k = 0; k < dof; ++k) {
        const double q0 = solution.samples.empty() ? 0.0 : solution.samples.front().q[k];
        s += "    <joint name=\"" + urdf_joint_name(k) +
             "\">\n      <command_interface name=\"position\"/>\n"
             "      <state_interface name=\"position\">\n        <param "
             "name=\"initial_value\">" +
             num(q0) +
             "</param>\n      </state_interface>\n"
             "      <state_interface name=\"velocity\"/>\n    </joint>\n";
    }
    return s + "  </ros2_control>\n";
}

std::string robot_urdf(const task::Task& task, const synth::Solution& solution) {
    return robot_urdf(task, solution, hardware::load_default_catalog());
}

std::string robot_urdf(const task::Task& task, const synth::Solution& solution,
                       const hardware::Catalog& catalog) {
    const kinematics::Robot& robot = solution.robot;
    const task::RobotSpec& spec = task.robot;
    const double d = robot.link_diameter;
    const std::vector<TubeCut> cuts = tube_cuts(spec, robot);
    const std::vector<Range> ranges = joint_ranges(solution);
    const int n = robot.dof();
    const auto modules = urdf_modules(task, solution, catalog);
    const hardware::ArmModel model = hardware::arm_model(spec, robot, catalog, modules);
    std::string names;
    for (const auto* m : modules) names += (names.empty() ? "" : ", ") + m->name;
    std::string s = preamble(task, names, solution.modules && solution.modules->checked);
    s += base_link(spec, *modules[0]);
    s += fixed_joint("base_mount", "world", "base_module", robot.base.x(), robot.base.y(), 0.0);
    for (int k = 0; k < n; ++k) {
        s += arm_link(spec, robot, cuts[k], model.links[k], k);
        const std::string parent = k == 0 ? "base_module" : "link_" + std::to_string(k);
        const double x = k == 0 ? 0.0 : robot.link_lengths[k - 1];
        const double z = k == 0 ? spec.module_height : d + spec.module_height;
        s += revolute(k, parent, x, z, ranges[k], *modules[k]);
    }
    s += "  <link name=\"ee\"/>\n";
    s += fixed_joint("ee_tip", "link_" + std::to_string(n), "ee", robot.link_lengths[n - 1], 0.0,
                     -output_face_height(spec, d, n - 1));
    s += ros2_control_block(task.name, solution, n);
    return s + "</robot>\n";
}

}  // namespace modsynth::output
