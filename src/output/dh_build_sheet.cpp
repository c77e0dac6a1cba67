#include <modsynth/output/dh_build_sheet.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <modsynth/hardware/dh_stack.h>
#include <modsynth/kinematics/dh_chain.h>
#include <modsynth/output/build_sheet.h>
#include <modsynth/output/parts_export.h>
#include <modsynth/output/recertify.h>
#include <modsynth/task/part.h>
#include <modsynth/task/part_list.h>
#include <modsynth/task/spatial_strokes.h>
#include <modsynth/text/format.h>
#include <modsynth/text/markdown.h>

namespace modsynth::output {
namespace {

using hardware::DhMountKind;

std::string mm(double metres) { return text::format("%.1f", 1000.0 * metres); }
std::string deg(double radians) { return text::format("%.1f", radians * 180.0 / geometry::kPi); }

std::string mount_text(const hardware::DhMount& m) {
    switch (m.kind) {
        case DhMountKind::TubeAdapter:
            return std::abs(std::remainder(m.twist, 2.0 * geometry::kPi)) < 1.0
                       ? std::string("tube adapter (axis parallel to the previous one)")
                       : std::string("tube adapter, module turned over (axis reversed)");
        case DhMountKind::RightAngleBracket:
            return "right-angle bracket (axis a quarter turn from the previous one)";
        case DhMountKind::OtherBracket:
            return "a bracket made for " + deg(std::abs(m.twist)) + " degrees (not in the catalog)";
    }
    return "";
}

std::string chain_section(const kinematics::DhChain& chain) {
    std::string s =
        "## Chain\n\nDenavit-Hartenberg rows (classic: frame k = frame k-1 Rz(q_k) Tz(d_k) "
        "Tx(a_k) Rx(alpha_k)); link k runs along joint k's axis by d_k, then along the common "
        "normal by a_k.\n\n| joint | a (mm) | alpha (deg) | d (mm) |\n|---|---|---|---|\n";
    for (int k = 0; k < chain.dof(); ++k) {
        const auto& r = chain.rows[static_cast<std::size_t>(k)];
        s += "| " + std::to_string(k + 1) + " | " + mm(r.a) + " | " + deg(r.alpha) + " | " +
             mm(r.d) + " |\n";
    }
    return s + "\nChain length (sum of a and |d|): " + mm(chain.total_length()) + " mm.\n\n";
}

std::string parts_section(const task::SpatialTask& task, const kinematics::DhChain& chain,
                          const hardware::DhStack& stack) {
    const auto& spec = task.robot;
    int adapters = 0, right_angle = 0, other = 0;
    for (const auto& t : stack.tubes) {
        const bool corner_start =
            !t.along_axis &&
            std::find(stack.corners.begin(), stack.corners.end(), t.link) != stack.corners.end();
        if (!corner_start) ++adapters;  // at the module output it leaves
    }
    for (const auto& m : stack.mounts) {
        if (m.kind == DhMountKind::TubeAdapter && m.on_tube) ++adapters;
        if (m.kind == DhMountKind::RightAngleBracket) ++right_angle;
        if (m.kind == DhMountKind::OtherBracket) ++other;
    }
    right_angle += static_cast<int>(stack.corners.size());
    std::string s = "## Parts\n\n| part | count | size |\n|---|---|---|\n";
    s += "| actuator module (default: HEBI X8) | " + std::to_string(chain.dof()) + " | " +
         mm(spec.module_length) + " x " + mm(spec.module_width) + " x " + mm(spec.module_height) +
         " mm |\n";
    s += "| tube | " + std::to_string(stack.tubes.size()) + " | " + mm(chain.link_diameter) +
         " mm diameter, cut lengths below |\n";
    s += "| tube adapter | " + std::to_string(adapters) +
         " | at each module output a tube leaves, at each module a tube carries in line |\n";
    if (right_angle > 0)
        s += "| right-angle bracket | " + std::to_string(right_angle) +
             " | for each quarter-turn twist, and where a link's two tubes meet |\n";
    if (other > 0)
        s += "| bracket for another angle (not in the catalog) | " + std::to_string(other) +
             " | see \"Joints and brackets\" |\n";
    if (spec.tool_length > 0.0)
        s += "| tool | 1 | " + mm(spec.tool_length) + " mm long at the end of the chain |\n";
    return s + "\n";
}

std::string cuts_section(const task::SpatialTask& task, const hardware::DhStack& stack) {
    const auto& spec = task.robot;
    std::string s = "## Tube cut lengths\n\n";
    s +=
        "Each tube is one segment of the chain (axis to axis) less what the hardware takes at "
        "its ends: at a module's output, half the module's height (leaving along its axis) or "
        "half its width (leaving across it); at the next module, as far as the tube's line runs "
        "inside its housing; at a link's corner bracket, half the tube's diameter; an adapter of " +
        mm(spec.adapter_length) + " mm at each of these; at the end of the chain, the tool (" +
        mm(spec.tool_length) + " mm).\n\n";
    s += "| tube | link | along | segment (mm) | - start (mm) | - end (mm) | = cut length (mm) "
         "|\n|---|---|---|---|---|---|---|\n";
    std::string warnings;
    for (std::size_t i = 0; i < stack.tubes.size(); ++i) {
        const auto& t = stack.tubes[i];
        s += "| " + std::to_string(i + 1) + " | " + std::to_string(t.link + 1) + " | " +
             (t.along_axis ? "joint axis (d)" : "common normal (a)") + " | " +
             mm(t.segment_length) + " | " + mm(t.proximal_allowance) + " | " +
             mm(t.distal_allowance) + " | **" + mm(t.cut_length) + "** |\n";
        if (t.cut_length <= 0.0)
            warnings += "\n**Warning:** tube " + std::to_string(i + 1) + " (link " +
                        std::to_string(t.link + 1) + ", " + mm(t.segment_length) +
                        " mm) is too short to build with these modules and adapters: it needs at "
                        "least " +
                        mm(t.proximal_allowance + t.distal_allowance) + " mm.\n";
    }
    return s + warnings + "\n";
}

std::string joints_section(const kinematics::DhChain& chain, const hardware::DhStack& stack) {
    std::string s =
        "## Joints and brackets\n\nModule 1 stands on the base, its axis vertical (the task's "
        "z). Each further module is mounted at the end of the link before it, turned about the "
        "common normal by that link's twist:\n\n| joint | on | twist (deg) | mount |\n"
        "|---|---|---|---|\n";
    for (const auto& m : stack.mounts) {
        s += "| " + std::to_string(m.joint) + " | " +
             (m.on_tube ? "link " + std::to_string(m.joint - 1) + "'s tube"
                        : "module " + std::to_string(m.joint - 1) + "'s output") +
             " | " + deg(m.twist) + " | " + mount_text(m) + " |\n";
    }
    for (int k : stack.corners)
        s += "\nLink " + std::to_string(k + 1) + " has both d (" +
             mm(chain.rows[static_cast<std::size_t>(k)].d) + " mm) and a (" +
             mm(chain.rows[static_cast<std::size_t>(k)].a) +
             " mm): its two tubes meet at a right-angle bracket.\n";
    return s + "\n";
}

std::string base_section(const kinematics::DhChain& chain) {
    return "## Base\n\nJoint 1's axis through (" + text::format("%.4f", chain.base.x()) + ", " +
           text::format("%.4f", chain.base.y()) + ", " + text::format("%.4f", chain.base.z()) +
           ") m in the task frame (the frame of the task file), pointing up (+z); module 1's "
           "output (the base point of the chain) at that height.\n\n";
}

std::string start_pose_section(const synth::Solution& solution) {
    const auto& chain = *solution.dh_robot;
    const auto& q = solution.samples.front().q;
    std::string s =
        "## Start pose\n\nBefore starting, command these joint angles (DH angles: q_k about "
        "joint k's axis, from the common normal of the link before):\n\n"
        "| joint | angle (rad) | angle (deg) |\n|---|---|---|\n";
    for (std::size_t k = 0; k < q.size(); ++k)
        s += "| " + std::to_string(k + 1) + " | " + text::format("%.4f", q[k]) + " | " +
             text::format("%.2f", q[k] * 180.0 / geometry::kPi) + " |\n";
    const geometry::Vec3 ee = kinematics::end_effector(chain, q);
    return s + "\nThe end-effector then stands at (" + text::format("%.4f", ee.x()) + ", " +
           text::format("%.4f", ee.y()) + ", " + text::format("%.4f", ee.z()) +
           ") m, the start of the path.\n";
}

/// "0-5", "0-2, 5-8": runs of three or more by their ends.
std::string index_list(const std::vector<int>& ids) {
    std::string s;
    for (std::size_t i = 0; i < ids.size();) {
        std::size_t end = i + 1;
        while (end < ids.size() && ids[end] == ids[end - 1] + 1) ++end;
        s += (s.empty() ? "" : ", ") + std::to_string(ids[i]);
        if (end - i >= 3) {
            s += "-" + std::to_string(ids[end - 1]);
        } else {
            for (std::size_t k = i + 1; k < end; ++k) s += ", " + std::to_string(ids[k]);
        }
        i = end;
    }
    return s;
}

// Nothing is built, so the sheet says why: a person holding it wants the
// reason and what to change, not an empty file.
std::string no_arm_sheet(const task::SpatialTask& task, const synth::Solution& solution) {
    const synth::Explanation& e = solution.explanation;
    const std::string status = synth::to_string(solution.status);
    std::string s = "# Build sheet: " +
                    (task.name.empty() ? std::string("task") : text::markdown_literal(task.name)) +
                    "\n\nNo arm to build: the task is " + status +
                    (solution.status == synth::Status::Infeasible
                         ? " (no arm of the allowed kind can do it, proved below)."
                         : " (no arm was found, and none was proved impossible).") +
                    "\n\n## Why\n\n" +
                    (e.message.empty() ? std::string("No explanation was given.")
                                       : text::markdown_text(e.message)) +
                    "\n";
    if (!e.core.empty()) {
        s += "\n## The parts that conflict\n\nChanging any one of them can remove the "
             "conflict (`modsynth explain` says by how much):\n\n";
        // A run (a shell of 80 spheres) is one line, by its ends.
        for (const task::PartRun& run : task::part_runs(e.core)) {
            if (run.size() >= 3) {
                s += "- `" + task::to_string(e.core[run.first]) + "` to `" +
                     task::to_string(e.core[run.last]) + "` (" + std::to_string(run.size()) + ")\n";
                continue;
            }
            for (std::size_t k = run.first; k <= run.last; ++k)
                s += "- `" + task::to_string(e.core[k]) + "`\n";
        }
    }
    if (e.enclosure) {
        s += "\n## The wall\n\n";
        for (const prove::Enclosure& w : e.enclosure->walls) {
            const std::string region = "base_regions[" + std::to_string(w.base_region) + "]";
            const std::string point =
                task::part_name(task, w.primitive) + " at (" +
                text::format("%.3f, %.3f, %.3f", w.point.x(), w.point.y(), w.point.z()) + ") m";
            s += "- Obstacles " + index_list(w.obstacles) +
                 (w.base_inside
                      ? " close in " + region + "; the path, " + point + ", is outside them.\n"
                      : " close in the path, " + point + "; " + region + " is outside them.\n");
        }
    }
    return s;
}

}  // namespace

std::string build_sheet(const task::SpatialTask& task, const synth::Solution& solution,
                        const parts::PrintedParts* printed) {
    if (solution.status != synth::Status::Solved) return no_arm_sheet(task, solution);
    if (!solution.dh_robot || solution.samples.empty())
        throw std::invalid_argument("build_sheet: the solution has no DH robot or no motion");
    const kinematics::DhChain& chain = *solution.dh_robot;
    const hardware::DhStack stack = hardware::dh_stack(task.robot, chain);
    std::string s = "# Build sheet: " +
                    (task.name.empty() ? std::string("task") : text::markdown_literal(task.name)) +
                    "\n\nA spatial arm with " + std::to_string(chain.dof()) +
                    " joints. Lengths in mm unless marked.\n\n";
    // Hardware is built from this sheet: a motion that failed verification
    // must say so before anything is cut.
    if (!solution.certificate.ok)
        s += "**Warning:** not certified: " +
             text::markdown_literal(uncertified_reason(solution.certificate)) +
             ". The motion may leave the path or collide.\n\n";
    return s + chain_section(chain) + parts_section(task, chain, stack) +
           modules_section(solution) + cuts_section(task, stack) + joints_section(chain, stack) +
           base_section(chain) + start_pose_section(solution) +
           (printed ? "\n" + printed_parts_section(*printed) : std::string());
}

}  // namespace modsynth::output
