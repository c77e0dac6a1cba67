#pragma once
// The outputs people use besides the solution file, written together by
// `solve` and by `export`: report (HTML), URDF, trajectory CSV, ROS 2 joint
// trajectory (YAML), build sheet.
#include <string>
#include <vector>

#include <modsynth/output/report.h>
#include <modsynth/parts/printed_parts.h>
#include <modsynth/synth/solution.h>
#include <modsynth/task/spatial_task.h>
#include <modsynth/task/task.h>

namespace modsynth::output {

/// Where to write each output; an empty path means "not wanted".
struct ExportPaths {
    std::string report;
    std::string urdf;
    std::string csv;
    std::string build_sheet;
    std::string joint_trajectory{};
    /// A folder for the printed parts (output/parts_export.h), which the
    /// command writes before the others, so that the build sheet lists them.
    std::string parts{};

    bool any() const {
        return !report.empty() || !urdf.empty() || !csv.empty() || !build_sheet.empty() ||
               !joint_trajectory.empty() || !parts.empty();
    }
};

/// Writes every wanted output. The report is always possible; the URDF, CSV,
/// joint trajectory and build sheet need a robot, so for an unsolved solution they are not
/// written and the returned list says so, one line each (empty: all written).
/// Throws std::runtime_error naming the path when a file cannot be written.
/// `printed`: the parts written for paths.parts, which the build sheet lists.
std::vector<std::string> write_exports(const task::Task& task, const synth::Solution& solution,
                                       const ExportPaths& paths, const ReportFigures& figures,
                                       const parts::PrintedParts* printed = nullptr);
/// The same for a spatial task: the 3-D report (report3d.h), the DH arm's
/// URDF (dh_urdf.h) and build sheet (dh_build_sheet.h), and the CSV and
/// joint trajectory, which are the plane's. The build sheet of an unsolved
/// spatial solution is written too: it says why there is no arm.
std::vector<std::string> write_exports(const task::SpatialTask& task,
                                       const synth::Solution& solution, const ExportPaths& paths,
                                       const ReportFigures& figures,
                                       const parts::PrintedParts* printed = nullptr);

/// Writes text to a file atomically (atomic_file.h); throws std::runtime_error
/// naming the path on failure.
void write_text_file(const std::string& path, const std::string& text);

}  // namespace modsynth::output
