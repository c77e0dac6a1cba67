#pragma once
// modsynth as a library: the calls a program that embeds it makes, and the
// value types they take and give. This header and the ones it includes are
// the public API (what `cmake --install` installs, and all that
// tests/embed/example.cpp may use); the other headers under
// include/modsynth/ are the stages' interfaces to each other and may change
// without notice.
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <modsynth/explanation/explain.h>
#include <modsynth/run/cancel.h>
#include <modsynth/run/progress.h>
#include <modsynth/synth/solution.h>
#include <modsynth/task/input_error.h>
#include <modsynth/task/part.h>
#include <modsynth/task/spatial_task.h>
#include <modsynth/task/task.h>

namespace modsynth {

using explanation::ExplainOptions;
using explanation::Explanation;
using run::CancelToken;
using run::ProgressEvent;
using run::ProgressSink;
using synth::Solution;
using synth::Status;
using task::InputError;
using task::SpatialTask;
using task::Task;
using task::TaskPart;
using verify::Certificate;

/// A modsynth-task/1 document (docs/formats.md), validated. Throws
/// InputError naming the offending part (`part()`) on anything invalid.
Task read_task(std::string_view json_text);
/// The same from a file; an unreadable file is an InputError too.
Task load_task(const std::string& path);

/// Whether a task document (JSON text) is a spatial task, `"space": "3d"`
/// (docs/formats.md "Spatial tasks"), which read_task refuses by name.
/// Throws InputError when the text is not JSON.
bool is_spatial_task(std::string_view json_text);
/// A spatial task document, validated; InputError naming the offending part.
SpatialTask read_spatial_task(std::string_view json_text);
SpatialTask load_spatial_task(const std::string& path);

struct SolveOptions {
    double time_limit = 60.0;  ///< seconds for the whole synthesis; > 0
    unsigned seed = 0;         ///< varies initial guesses; same seed, same answer
    /// Told of every step (stage, sentence, seconds since the start;
    /// run::console_line prints it as `modsynth solve` does); leave empty
    /// for silence.
    ProgressSink progress;
    /// Keep a copy and call cancel() on it (from any thread) to end the
    /// solve early; it then answers as at its time limit, "unknown" unless
    /// a robot is already certified.
    run::CancelToken cancel;
};

/// A certified robot and its timed motion (with the actuator modules that
/// carry it), a proof that none exists, or "unknown" with the stage reached
/// and why: the same answer as `modsynth solve`. Throws InputError when the
/// task names a module the catalog lacks, and std::invalid_argument naming
/// the field when the options are not valid.
Solution solve(const Task& task, const SolveOptions& options = {});
/// The same for a spatial task: a certified DH chain (Solution::dh_robot)
/// and its timed motion with its modules, a proof that none exists, or
/// "unknown"; the same answer as `modsynth solve` on that task.
Solution solve(const SpatialTask& task, const SolveOptions& options = {});

/// Why a task cannot be done, within `time_limit` seconds in all;
/// `solve_seconds` of synthesis go to each suggested change. The same flow
/// as `modsynth explain`.
Explanation explain(const Task& task, double time_limit = 60.0, double solve_seconds = 10.0);
/// The same for a spatial task: the spatial reach proof or the front
/// stage's core as task parts, else the spatial synthesis, else the
/// changes (links, joints, twists, base regions) that remove the conflict.
Explanation explain(const SpatialTask& task, double time_limit = 60.0, double solve_seconds = 10.0);

/// The same flow with every option: the proof's share of the time, and
/// progress events (the flow's steps, "proving infeasibility", "solving
/// the task", "looking for the smallest changes"). Throws
/// std::invalid_argument naming the field when the options are not valid.
Explanation explain(const Task& task, const ExplainOptions& options);
Explanation explain(const SpatialTask& task, const ExplainOptions& options);
/// An explanation as `modsynth explain --json` prints it: task, status,
/// message, core, the proof's witnesses and the suggestions (part, change,
/// outcome), "suggestions" only when proved.
std::string write_explanation_json(const std::string& task_name, const Explanation& explanation);

/// Checks a solution's motion against the task over the whole continuum,
/// independently of how it was made (docs/verification.md). A solution
/// that is not "solved" gets a certificate that is not ok.
Certificate certify(const Task& task, const Solution& solution);
/// The same for a spatial task, whose solution carries a DH robot
/// (Solution::dh_robot; an InputError when it does not).
Certificate certify(const SpatialTask& task, const Solution& solution);
/// Why a certificate is not ok, in one line naming the first offending
/// sample ("samples[3]: EE is 0.052000 m off the path (and 4 more)"), as
/// `modsynth certify` says it; "" when it is ok.
std::string uncertified_reason(const Certificate& certificate);

/// A solution as a modsynth-solution/1 document, and back (the reader
/// throws InputError naming the part).
std::string write_solution_json(const Solution& solution);
Solution read_solution(std::string_view json_text);

/// A task as a modsynth-task/1 document (JSON text), which the readers
/// above read back to the same task: for the tasks a program builds, and
/// the changed tasks an explanation suggests (explanation::Relaxation).
std::string write_task_json(const Task& task);
std::string write_task_json(const SpatialTask& task);

/// The files `modsynth export TASK SOLUTION` writes; an empty path is not
/// written.
struct ExportFiles {
    std::string report;            ///< HTML, self-contained
    std::string urdf;              ///< the arm as a URDF model
    std::string csv;               ///< t, q, phase, primitive, qd, qdd per sample
    std::string joint_trajectory;  ///< ROS 2 trajectory_msgs/JointTrajectory (YAML)
    std::string build_sheet;       ///< Markdown: parts, cut lengths, base, start pose
    /// Write the CSV and the joint trajectory of a motion that fails
    /// verification again too (a controller commands what they say).
    bool write_uncertified = false;
    /// Whether the solution came with a certificate (a document without
    /// "certificate" has none to compare the new one with; the report
    /// says so).
    bool had_certificate = true;
};

/// Writes the files as `modsynth export` does: the solution is verified
/// again (its certificate replaced by the verifier's), its modules chosen
/// from the task's catalog, and each file written. Returns one line per
/// file not written and why (no robot in an unsolved solution; a motion
/// that is not certified, for the CSV and the joint trajectory); empty when
/// all were. Throws InputError when the solution does not fit the task,
/// std::runtime_error naming a path that cannot be written.
std::vector<std::string> write_exports(const Task& task, const Solution& solution,
                                       const ExportFiles& files);
std::vector<std::string> write_exports(const SpatialTask& task, const Solution& solution,
                                       const ExportFiles& files);

/// A drawing (SVG, DXF) or a text to make a task of, and how: the options
/// of `modsynth import`, named as there.
struct DrawingImport {
    /// One of the three: a drawing file (.svg, .dxf), a drawing's contents
    /// with its `format` ("svg" or "dxf"), or text written in a Hershey
    /// single-stroke font.
    std::string path;
    std::string contents, format;
    std::string text;
    std::string font = "futural";  ///< any of /usr/share/hershey-fonts
    double text_height = 0.03;     ///< m, of a capital letter
    std::string name;              ///< default: the file's stem, "text" or "drawing"
    std::optional<double> width;   ///< m, the drawing's width
    std::optional<double> scale;   ///< m per drawing unit (default: the file's units)
    /// Where the drawing's centre goes in the plane (x, y).
    std::optional<std::pair<double, double>> at;
    double rotate_degrees = 0.0;  ///< counter-clockwise
    double tolerance = 1e-4;      ///< m: the largest deviation from the drawing
    double time_limit = 60.0;     ///< s for the whole import
    /// Base regions: xmin, ymin, xmax, ymax in the plane; boxes xmin, ymin,
    /// zmin, xmax, ymax, zmax on a plane or cylinder in space.
    std::vector<std::vector<double>> base_regions;
    std::string obstacle_layer;       ///< layer whose circles are obstacles
    std::vector<std::string> layers;  ///< DXF layers to import (all when empty)
    bool strict = false;              ///< refuse what cannot be traced instead of skipping it
    bool hatch_boundaries = false;    ///< trace DXF hatches' boundaries
    bool keep_order = false;          ///< the file's stroke order and direction
    std::vector<int> dof;             ///< allowed joint counts (default: the format's)
    std::optional<double> link_diameter;
    /// In space: on a plane (origin, u, v: nine numbers) or round a
    /// cylinder (centre, axis, radius: seven); neither for the plane.
    std::vector<double> plane, cylinder;
    std::optional<double> tool_length;  ///< in space only
    /// In space: "square" holds the tool square into the surface while it
    /// traces, "toward" (round a cylinder) at its axis, within
    /// `tool_tolerance_degrees`; empty: the tool is free.
    std::string tool;
    double tool_tolerance_degrees = 5.0;
};

struct ImportedDrawing {
    /// The task as `modsynth import` writes it (modsynth-task/1 JSON, the
    /// same bytes).
    std::string task_json;
    std::vector<std::size_t> primitives_per_stroke;
    std::size_t obstacles = 0;
    double deviation = 0.0;  ///< m, the worst found
    double travel = 0.0;     ///< m of pen-up moves between strokes
    /// Empty for a task in the plane; "plane" or "cylinder" for one placed
    /// in space.
    std::string surface;
    std::vector<std::string> warnings;  ///< what the reader skipped
    std::size_t filled_outlines = 0;    ///< filled shapes whose outlines were traced
    std::vector<std::pair<std::string, std::size_t>> layers;  ///< DXF layers, entities
};

/// The import did not finish within its time limit.
class ImportTimeout : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// A task from a drawing, as `modsynth import` makes it. Throws InputError
/// naming the option (as the command line spells it: "--base") or the
/// drawing's part ("drawing.svg: path#p3 (line 12)"), ImportTimeout past the
/// time limit.
ImportedDrawing import_drawing(const DrawingImport& request);

/// Where the module catalog is read from (docs/formats.md "Module
/// catalog"): by default the one installed beside the program. A library
/// whose data lies elsewhere (the Python module's, beside it) says where,
/// once for the whole process; an empty string goes back to the default.
void set_catalog_folder(const std::string& folder);
std::string catalog_folder();

}  // namespace modsynth
