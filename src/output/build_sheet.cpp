#include <modsynth/output/build_sheet.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include <modsynth/geometry/vec.h>
#include <modsynth/kinematics/kinematics.h>
#include <modsynth/output/hardware.h>
#include <modsynth/output/parts_export.h>
#include <modsynth/output/recertify.h>
#include <modsynth/text/format.h>
#include <modsynth/text/markdown.h>

namespace modsynth::output {
namespace {

std::string mm(double metres) { return text::format("%.1f", 1000.0 * metres); }

std::string parts(const task::Task& task, const kinematics::Robot& robot) {
    const auto& spec = task.robot;
    const int n = robot.dof();
    std::string s = "## Parts\n\n| part | count | size |\n|---|---|---|\n";
    s += "| actuator module (default: HEBI X8) | " + std::to_string(n) + " | " +
         mm(spec.module_length) + " x " + mm(spec.module_width) + " x " + mm(spec.module_height) +
         " mm |\n";
    s += "| tube | " + std::to_string(n) + " | " + mm(robot.link_diameter) +
         " mm diameter, cut lengths below |\n";
    s += "| tube adapter | " + std::to_string(2 * n - 1) +
         " | one at each module output, one at each module body carried by a tube |\n";
    s += "| end-effector rod | 1 | " + mm(spec.ee_rod_diameter) + " mm diameter, " +
         mm(ee_rod_length(spec, robot.link_diameter, n)) + " mm long |\n\n";
    return s;
}

std::string cut_row(int k, const TubeCut& c) {
    return "| " + std::to_string(k + 1) + " | " + mm(c.link_length) + " | " +
           mm(c.proximal_allowance) + " | " + mm(c.distal_allowance) + " | **" + mm(c.cut_length) +
           "** |\n";
}

std::string cut_warnings(const std::vector<TubeCut>& cuts) {
    std::string s;
    for (std::size_t k = 0; k < cuts.size(); ++k) {
        if (cuts[k].cut_length > 0.0) continue;
        s += "\n**Warning:** link " + std::to_string(k + 1) + " (" + mm(cuts[k].link_length) +
             " mm) is too short to build with these modules and adapters: it needs at least " +
             mm(cuts[k].proximal_allowance + cuts[k].distal_allowance) + " mm.\n";
    }
    return s;
}

std::string rod_warning(const task::RobotSpec& spec, double link_diameter) {
    if (spec.ee_rod_diameter < link_diameter) return "";
    return "\n**Warning:** the " + mm(spec.ee_rod_diameter) + " mm rod does not fit through the " +
           mm(link_diameter) + " mm tube; mount it beside the tube's end instead.\n";
}

std::string cuts_section(const task::Task& task, const kinematics::Robot& robot) {
    const auto& spec = task.robot;
    const std::vector<TubeCut> cuts = tube_cuts(spec, robot);
    std::string s = "## Tube cut lengths\n\n";
    s += "Link lengths are axis to axis (the last one: axis to the end-effector rod). Each tube is "
         "shorter by what the hardware takes at its ends:\n\n";
    s += "- at the output of the module that drives it: half the module width plus an adapter, " +
         mm(spec.module_width / 2.0) + " + " + mm(spec.adapter_length) + " = " +
         mm(proximal_allowance(spec)) + " mm;\n";
    s += "- at the body of the next module: the body behind its axis plus an adapter, " +
         mm(spec.module_length - spec.module_width / 2.0) + " + " + mm(spec.adapter_length) +
         " = " + mm(distal_allowance(spec)) + " mm;\n";
    s += "- at the end-effector: the tube runs half its diameter past the rod's axis, " +
         mm(ee_allowance(robot.link_diameter)) + " mm; drill the " + mm(spec.ee_rod_diameter) +
         " mm rod hole " + mm(robot.link_diameter / 2.0) + " mm from that end.\n\n";
    s += "| link | link length (mm) | - output end (mm) | - far end (mm) | = cut length (mm) "
         "|\n|---|---|---|---|---|\n";
    for (std::size_t k = 0; k < cuts.size(); ++k) s += cut_row(static_cast<int>(k), cuts[k]);
    return s + cut_warnings(cuts) + rod_warning(spec, robot.link_diameter) + "\n";
}

std::string stack_section(const task::Task& task, const kinematics::Robot& robot) {
    const auto& spec = task.robot;
    std::string s =
        "## Stack\n\nModule 1 stands on the table, output up; every further module "
        "stands on the previous tube, so each link lies one level higher and only "
        "the end-effector rod reaches down to the task plane.\n\n"
        "| joint | output face above the table (mm) | tube axis above the table (mm) "
        "|\n|---|---|---|\n";
    for (int k = 0; k < robot.dof(); ++k) {
        s += "| " + std::to_string(k + 1) + " | " +
             mm(output_face_height(spec, robot.link_diameter, k)) + " | " +
             mm(tube_axis_height(spec, robot.link_diameter, k)) + " |\n";
    }
    return s + "\n";
}

std::string base_section(const kinematics::Robot& robot) {
    return "## Base\n\nJoint 1's axis at x = " + text::format("%.4f", robot.base.x()) +
           " m, y = " + text::format("%.4f", robot.base.y()) +
           " m in the task frame (the frame of the task file).\n\n";
}

std::string start_pose_section(const synth::Solution& solution) {
    const auto& robot = solution.robot;
    const auto& q = solution.samples.front().q;
    const auto s_joint = kinematics::forward(robot.base, robot.link_lengths, q);
    std::string s =
        "## Start pose\n\nBefore starting, command these joint angles (q1 from the "
        "task's x-axis, counter-clockwise; each further joint relative to the "
        "previous link):\n\n| joint | angle (rad) | angle (deg) |\n|---|---|---|\n";
    for (std::size_t k = 0; k < q.size(); ++k) {
        s += "| " + std::to_string(k + 1) + " | " + text::format("%.4f", q[k]) + " | " +
             text::format("%.2f", q[k] * 180.0 / geometry::kPi) + " |\n";
    }
    const geometry::Vec2 ee = s_joint.back();
    return s + "\nThe end-effector then stands at (" + text::format("%.4f", ee.x()) + ", " +
           text::format("%.4f", ee.y()) + ") m, the start of the path. Joint " +
           std::to_string(robot.dof()) + " stays bent " +
           (robot.elbow > 0 ? "counter-clockwise (positive)" : "clockwise (negative)") +
           " for the whole motion.\n";
}

}  // namespace

std::string modules_section(const synth::Solution& solution) {
    if (!solution.modules) return "";
    const hardware::ModuleSelection& m = *solution.modules;
    std::string s = "## Modules\n\n";
    if (!m.checked) return s + text::markdown_literal(m.message) + ".\n\n";
    if (m.overloaded_joint > 0) s += "**Warning:** " + text::markdown_literal(m.message) + ".\n\n";
    s += "Lightest allowed module per joint that carries the motion: peak |torque| within its "
         "peak torque, RMS torque within its continuous torque, |speed| within its top speed. "
         "Margin: rating minus load.\n\n"
         "| joint | module | family | cost (USD) | mass (kg) | peak torque (N m) | at t (s) | "
         "peak margin (N m) | RMS torque (N m) | continuous margin (N m) | top speed (rad/s) | "
         "speed margin (rad/s) |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (std::size_t k = 0; k < m.joints.size(); ++k) {
        const auto& j = m.joints[k];
        s += "| " + std::to_string(k + 1) + " | " + text::markdown_literal(j.module) +
             (j.carries ? "" : " **(overloaded)**") + " | " + text::markdown_literal(j.family) +
             " | " + (j.cost ? text::format("%.2f", *j.cost) : std::string("unknown")) + " | " +
             text::format("%.3f", j.mass) + " | " + text::format("%.3f", j.load.peak_torque) +
             " | " + text::format("%.3f", j.load.peak_time) + " | " +
             text::format("%.3f", j.peak_margin) + " | " + text::format("%.3f", j.load.rms_torque) +
             " | " + text::format("%.3f", j.continuous_margin) + " | " +
             text::format("%.3f", j.load.max_speed) + " | " + text::format("%.3f", j.speed_margin) +
             " |\n";
    }
    // The parts bill: one row per model, in joint order.
    struct Row {
        const hardware::JointChoice* choice;
        int count;
    };
    std::vector<Row> rows;
    for (const auto& j : m.joints) {
        const auto r = std::find_if(rows.begin(), rows.end(),
                                    [&](const Row& x) { return x.choice->module == j.module; });
        if (r == rows.end()) {
            rows.push_back({&j, 1});
        } else {
            ++r->count;
        }
    }
    s += "\nModules to order:\n\n| module | family | count | unit cost (USD) | cost (USD) |\n"
         "|---|---|---|---|---|\n";
    double known = 0.0;
    bool unknown = false;
    for (const Row& r : rows) {
        const auto& c = r.choice->cost;
        s += "| " + text::markdown_literal(r.choice->module) + " | " +
             text::markdown_literal(r.choice->family) + " | " + std::to_string(r.count) + " | " +
             (c ? text::format("%.2f", *c) : std::string("unknown")) + " | " +
             (c ? text::format("%.2f", r.count * *c) : std::string("unknown")) + " |\n";
        if (c) {
            known += r.count * *c;
        } else {
            unknown = true;
        }
    }
    std::string total;
    if (!unknown) {
        total = text::format("total cost $%.2f", known);
    } else if (known > 0.0) {
        total = text::format("total cost $%.2f plus the modules of unknown cost", known);
    } else {
        total = "total cost unknown";
    }
    return s + "\nModules: " + text::format("%.3f", m.total_mass) + " kg in all; " + total +
           ".\n\n";
}

std::string build_sheet(const task::Task& task, const synth::Solution& solution,
                        const parts::PrintedParts* printed) {
    const auto& robot = solution.robot;
    std::string s = "# Build sheet: " +
                    (task.name.empty() ? std::string("task") : text::markdown_literal(task.name)) +
                    "\n\nA planar arm with " + std::to_string(robot.dof()) + " joints, links";
    for (double r : robot.link_lengths) s += " " + mm(r);
    s += " mm (axis to axis). Lengths in mm unless marked.\n\n";
    // Hardware is built from this sheet: a motion that failed verification
    // must say so before anything is cut.
    if (!solution.certificate.ok)
        s += "**Warning:** not certified: " +
             text::markdown_literal(uncertified_reason(solution.certificate)) +
             ". The motion may leave the path or collide.\n\n";
    return s + parts(task, robot) + modules_section(solution) + cuts_section(task, robot) +
           stack_section(task, robot) + base_section(robot) + start_pose_section(solution) +
           (printed ? "\n" + printed_parts_section(*printed) : std::string());
}

}  // namespace modsynth::output
