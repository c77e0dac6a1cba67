#include <modsynth/output/exports.h>

#include <functional>
#include <initializer_list>
#include <stdexcept>

#include <modsynth/io/atomic_file.h>
#include <modsynth/output/build_sheet.h>
#include <modsynth/output/csv.h>
#include <modsynth/output/dh_build_sheet.h>
#include <modsynth/output/dh_urdf.h>
#include <modsynth/output/joint_trajectory.h>
#include <modsynth/output/report3d.h>
#include <modsynth/output/urdf.h>

namespace modsynth::output {

void write_text_file(const std::string& path, const std::string& text) {
    io::write_file_atomically(path, text);
}

namespace {

const std::string kNone;  ///< no path: the output is not asked for

struct RobotOutput {
    const std::string& path;
    const char* option;
    std::function<std::string()> make;
};

/// Writes the outputs that need a robot when the solution is solved; the
/// lines of those not written otherwise.
std::vector<std::string> write_robot_outputs(const synth::Solution& solution,
                                             std::initializer_list<RobotOutput> outputs) {
    const bool solved = solution.status == synth::Status::Solved;
    std::vector<std::string> skipped;
    for (const auto& o : outputs) {
        if (o.path.empty()) continue;
        if (solved) {
            write_text_file(o.path, o.make());
        } else {
            skipped.push_back(std::string(o.option) + " " + o.path +
                              ": not written; the solution is " +
                              synth::to_string(solution.status) + ", so there is no robot");
        }
    }
    return skipped;
}

}  // namespace

std::vector<std::string> write_exports(const task::Task& task, const synth::Solution& solution,
                                       const ExportPaths& paths, const ReportFigures& figures,
                                       const parts::PrintedParts* printed) {
    if (!paths.report.empty()) write_text_file(paths.report, html_report(task, solution, figures));
    return write_robot_outputs(
        solution,
        {{paths.urdf, "--urdf", [&] { return robot_urdf(task, solution); }},
         {paths.csv, "--csv", [&] { return trajectory_csv(solution); }},
         {paths.build_sheet, "--build-sheet", [&] { return build_sheet(task, solution, printed); }},
         {paths.joint_trajectory, "--joint-trajectory",
          [&] { return joint_trajectory_yaml(solution); }}});
}

std::vector<std::string> write_exports(const task::SpatialTask& task,
                                       const synth::Solution& solution, const ExportPaths& paths,
                                       const ReportFigures& figures,
                                       const parts::PrintedParts* printed) {
    if (!paths.report.empty()) write_text_file(paths.report, html_report(task, solution, figures));
    // A spatial sheet without an arm says why there is none.
    if (!paths.build_sheet.empty() && solution.status != synth::Status::Solved)
        write_text_file(paths.build_sheet, build_sheet(task, solution));
    return write_robot_outputs(
        solution, {{paths.urdf, "--urdf", [&] { return robot_urdf(task, solution); }},
                   {paths.csv, "--csv", [&] { return trajectory_csv(solution); }},
                   {solution.status == synth::Status::Solved ? paths.build_sheet : kNone,
                    "--build-sheet", [&] { return build_sheet(task, solution, printed); }},
                   {paths.joint_trajectory, "--joint-trajectory",
                    [&] { return joint_trajectory_yaml(solution); }}});
}

}  // namespace modsynth::output
