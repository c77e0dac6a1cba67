#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <modsynth/control/joint_limits.h>
#include <modsynth/control/retime.h>
#include <modsynth/hardware/select_dh_modules.h>
#include <modsynth/hardware/task_catalog.h>
#include <modsynth/io/solution_io.h>
#include <modsynth/io/task_document.h>
#include <modsynth/io/task_io.h>
#include <modsynth/output/exports.h>
#include <modsynth/output/parts_export.h>
#include <modsynth/output/recertify.h>
#include <modsynth/synth/module_choice.h>
#include <modsynth/synth/spatial_module_choice.h>
#include <modsynth/text/printable.h>

#include "command.h"
#include "task_file.h"

namespace modsynth::app {
namespace {

struct ExportArgs {
    std::string task, solution;
    output::ExportPaths exports;
    bool write_uncertified = false;
    bool strict = false;
};

/// Where the saved timing breaks the task's joint limits (when it has
/// them, formats.md "Timing a controller accepts"), or "".
std::string timing_fault(const task::Task& task, const synth::Solution& s) {
    const bool solved = s.status == synth::Status::Solved;
    if (!solved || !task.robot.joint_limits) return "";
    return control::timing_fault(s.samples, control::joint_limits_for(task, s.robot.dof()));
}
std::string timing_fault(const task::SpatialTask& task, const synth::Solution& s) {
    const bool solved = s.status == synth::Status::Solved;
    if (!solved || !task.robot.joint_limits || !s.dh_robot) return "";
    return control::timing_fault(s.samples, control::joint_limits_for(task, s.dh_robot->dof()));
}

/// Warns of a solved motion that is not certified, or whose timing breaks
/// the task's joint limits (a file solved before them, or edited), and,
/// unless the user asked for them, takes its controller files (CSV, joint
/// trajectory) out of `paths`: a controller commands what these files say,
/// so such a motion is not handed to one. Returns a line per file left out.
std::vector<std::string> refuse_uncertified(const ExportArgs& a, const synth::Solution& s,
                                            output::ExportPaths& paths,
                                            const std::string& timing = "") {
    std::vector<std::string> refused;
    if (s.status != synth::Status::Solved || (s.certificate.ok && timing.empty())) return refused;
    const std::string why =
        !s.certificate.ok ? "the motion is not certified" : "its timing breaks robot.joint_limits";
    if (!s.certificate.ok)
        std::fprintf(stderr, "warning: %s: not certified: %s\n",
                     text::printable(a.solution, 200).c_str(),
                     output::uncertified_reason(s.certificate).c_str());
    else
        std::fprintf(stderr, "warning: %s: the timing breaks robot.joint_limits: %s\n",
                     text::printable(a.solution, 200).c_str(), timing.c_str());
    if (a.write_uncertified) return refused;
    for (auto [path, option] : {std::pair{&paths.csv, "--csv"},
                                std::pair{&paths.joint_trajectory, "--joint-trajectory"}}) {
        if (path->empty()) continue;
        refused.push_back(std::string(option) + " " + *path + ": not written; " + why +
                          " (give --write-uncertified to write it anyway)");
        path->clear();
    }
    return refused;
}

/// Prints the files not written; exit 2 when there are any.
int report_skipped(std::vector<std::string> skipped, const std::vector<std::string>& refused) {
    skipped.insert(skipped.end(), refused.begin(), refused.end());
    for (const auto& line : skipped) std::fprintf(stderr, "error: %s\n", line.c_str());
    return skipped.empty() ? kOk : kInvalid;
}

/// --parts: the printed parts, written before the build sheet that lists
/// them. A solution without a robot or modules adds its line to `skipped`;
/// what the checks found is a warning.
template <class TaskT>
std::optional<parts::PrintedParts> print_parts(const ExportArgs& a, const TaskT& task,
                                               const std::optional<hardware::Catalog>& catalog,
                                               synth::Solution& solution,
                                               std::vector<std::string>& skipped) {
    if (a.exports.parts.empty()) return std::nullopt;
    std::vector<std::string> notes;
    std::optional<parts::PrintedParts> printed =
        output::export_parts(task, catalog, solution, a.exports.parts, notes);
    for (auto& n : notes) {
        if (printed)
            std::fprintf(stderr, "warning: %s\n", n.c_str());
        else
            skipped.push_back(std::move(n));
    }
    return printed;
}

/// A spatial task: re-verified as in the plane, modules chosen, and each
/// file written by the spatial writers.
int export_spatial(const ExportArgs& a, const task::SpatialTask& task) {
    std::string note;
    const std::optional<hardware::Catalog> catalog = hardware::spatial_catalog(task, &note);
    if (!note.empty()) std::fprintf(stderr, "note: %s\n", note.c_str());
    io::ParsedSolution parsed = io::load_solution(a.solution);
    output::ReportFigures figures;
    figures.certificate_note = output::recertify(task, parsed);
    synth::choose_modules(task, catalog, parsed.solution);
    std::vector<std::string> skipped;
    const std::optional<parts::PrintedParts> printed =
        print_parts(a, task, catalog, parsed.solution, skipped);
    const synth::Solution& s = parsed.solution;
    if (s.modules && s.modules->checked && !s.modules->carried())
        std::fprintf(stderr, "warning: the certified robot overloads its modules: %s\n",
                     text::printable(s.modules->message, 2000).c_str());
    output::ExportPaths paths = a.exports;
    const std::vector<std::string> refused = refuse_uncertified(a, s, paths, timing_fault(task, s));
    for (auto& line : output::write_exports(task, parsed.solution, paths, figures,
                                            printed ? &*printed : nullptr))
        skipped.push_back(std::move(line));
    return report_skipped(skipped, refused);
}

int run_export(const ExportArgs& a) {
    if (!a.exports.any()) {
        std::fprintf(stderr,
                     "error: nothing to export; give --report, --urdf, --csv, "
                     "--joint-trajectory, --build-sheet and/or --parts\n");
        return kInvalid;
    }
    io::check_outputs(export_outputs(a.exports), {a.task, a.solution});
    if (!a.exports.parts.empty()) parts::prepare_parts_folder(a.exports.parts);
    const io::TaskDocument doc = read_task_file(a.task, a.strict);
    if (const auto* spatial = std::get_if<task::SpatialTask>(&doc))
        return export_spatial(a, *spatial);
    const task::Task& task = std::get<task::Task>(doc);
    const hardware::TaskCatalog catalog = hardware::catalog_for(task);
    if (!catalog.note.empty()) std::fprintf(stderr, "note: %s\n", catalog.note.c_str());
    io::ParsedSolution parsed = io::load_solution(a.solution);
    output::ReportFigures figures;
    figures.certificate_note = output::recertify(task, parsed);
    synth::choose_modules(task, catalog.catalog, parsed.solution);
    std::vector<std::string> skipped;
    const std::optional<parts::PrintedParts> printed =
        print_parts(a, task, catalog.catalog, parsed.solution, skipped);
    const std::string overload = synth::overload_warning(parsed.solution);
    if (!overload.empty()) std::fprintf(stderr, "warning: %s\n", overload.c_str());
    const synth::Solution& s = parsed.solution;
    output::ExportPaths paths = a.exports;
    const std::vector<std::string> refused = refuse_uncertified(a, s, paths, timing_fault(task, s));
    for (auto& line : output::write_exports(task, parsed.solution, paths, figures,
                                            printed ? &*printed : nullptr))
        skipped.push_back(std::move(line));
    return report_skipped(skipped, refused);
}

}  // namespace

std::vector<io::OutputFile> export_outputs(const output::ExportPaths& paths) {
    std::vector<io::OutputFile> out = {{"--report", paths.report},
                                       {"--urdf", paths.urdf},
                                       {"--csv", paths.csv},
                                       {"--joint-trajectory", paths.joint_trajectory},
                                       {"--build-sheet", paths.build_sheet}};
    // A folder that is not there yet holds nothing to check.
    std::error_code ec;
    if (!paths.parts.empty() && std::filesystem::is_directory(paths.parts, ec))
        for (const std::string& p :
             parts::part_paths(paths.parts, std::max(task::kMaxDof, task::kMaxSpatialDof)))
            out.push_back({"--parts", p});
    return out;
}

void add_export_options(CLI::App& sub, output::ExportPaths& paths) {
    sub.add_option("--report", paths.report, "write a visual report (self-contained HTML)");
    sub.add_option("--urdf", paths.urdf, "write the robot as a URDF model");
    sub.add_option("--csv", paths.csv,
                   "write the joint trajectory as CSV "
                   "(t,q1..qn,phase,primitive,qd1..qdn,qdd1..qddn)");
    sub.add_option("--joint-trajectory", paths.joint_trajectory,
                   "write the joint trajectory as a ROS 2 trajectory_msgs/JointTrajectory (YAML)");
    sub.add_option("--build-sheet", paths.build_sheet,
                   "write a build sheet (Markdown): parts, tube cut lengths, base, start pose");
    sub.add_option("--parts", paths.parts,
                   "write printable links into this folder (created if need be): an OpenSCAD "
                   "source per link, base_plate.scad and tool_holder.scad, rendered to STL and "
                   "checked when openscad is installed; the links' printed masses then enter "
                   "the module choice");
}

Command add_export(CLI::App& parent) {
    auto a = std::make_shared<ExportArgs>();
    CLI::App* sub = parent.add_subcommand(
        "export",
        "Write the report, URDF, CSV, joint trajectory or build sheet of a saved solution");
    sub->add_option("TASK", a->task,
                    "modsynth-task/1 JSON file the solution is for (planar or spatial)")
        ->required();
    sub->add_option("SOLUTION", a->solution, "modsynth-solution/1 JSON file")->required();
    add_export_options(*sub, a->exports);
    add_strict_option(*sub, a->strict);
    sub->add_flag("--write-uncertified", a->write_uncertified,
                  "write --csv and --joint-trajectory even for a motion that fails "
                  "verification again (by default they are not written, and the exit code is 2)");
    return {sub, [a] { return run_export(*a); }};
}

}  // namespace modsynth::app
