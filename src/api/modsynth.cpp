#include <modsynth/modsynth.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <optional>
#include <utility>

#include <modsynth/drawing/import.h>
#include <modsynth/hardware/catalog.h>
#include <modsynth/hardware/select_dh_modules.h>
#include <modsynth/hardware/task_catalog.h>
#include <modsynth/io/input.h>
#include <modsynth/io/solution_io.h>
#include <modsynth/io/spatial_task_io.h>
#include <modsynth/io/task_document.h>
#include <modsynth/io/task_io.h>
#include <modsynth/output/exports.h>
#include <modsynth/output/recertify.h>
#include <modsynth/synth/module_choice.h>
#include <modsynth/synth/solve.h>
#include <modsynth/synth/spatial_module_choice.h>
#include <modsynth/text/format.h>

#include <nlohmann/json.hpp>

#include "drawing_task.h"
#include "imported_task.h"
#include "surface_import.h"

namespace modsynth {

Task read_task(std::string_view json_text) { return io::parse_task_text(json_text); }

Task load_task(const std::string& path) { return io::load_task(path); }

bool is_spatial_task(std::string_view json_text) {
    return io::is_spatial(io::parse_json_text(json_text));
}

SpatialTask read_spatial_task(std::string_view json_text) {
    return io::parse_spatial_task_text(json_text);
}

SpatialTask load_spatial_task(const std::string& path) { return io::load_spatial_task(path); }

Solution solve(const Task& task, const SolveOptions& options) {
    synth::SynthesisOptions o;
    o.time_limit = options.time_limit;
    o.seed = options.seed;
    o.progress = options.progress;
    o.cancel = options.cancel;
    return synth::solve(task, o);
}

Solution solve(const SpatialTask& task, const SolveOptions& options) {
    synth::SpatialSynthesisOptions o;
    o.time_limit = options.time_limit;
    o.seed = options.seed;
    o.progress = options.progress;
    o.cancel = options.cancel;
    return synth::solve(task, o);
}

Explanation explain(const Task& task, double time_limit, double solve_seconds) {
    explanation::ExplainOptions o;
    o.time_limit = time_limit;
    o.solve_seconds = solve_seconds;
    return explanation::explain(task, o);
}

Explanation explain(const SpatialTask& task, double time_limit, double solve_seconds) {
    explanation::ExplainOptions o;
    o.time_limit = time_limit;
    o.solve_seconds = solve_seconds;
    return explanation::explain(task, o);
}

Explanation explain(const Task& task, const ExplainOptions& options) {
    return explanation::explain(task, options);
}

Explanation explain(const SpatialTask& task, const ExplainOptions& options) {
    return explanation::explain(task, options);
}

std::string write_explanation_json(const std::string& task_name, const Explanation& e) {
    nlohmann::json out = {{"task", task_name},
                          {"status", synth::to_string(e.status)},
                          {"message", e.message},
                          {"core", task::to_strings(e.core)}};
    io::add_witnesses({e.message, e.core, e.separation, e.geodesic, e.enclosure}, out);
    if (e.proved) {
        out["suggestions"] = nlohmann::json::array();
        for (const auto& r : e.suggestions)
            out["suggestions"].push_back(
                {{"part", task::to_string(r.part)}, {"change", r.change}, {"outcome", r.outcome}});
    }
    return out.dump(1, ' ', false, nlohmann::json::error_handler_t::replace) + '\n';
}

Certificate certify(const Task& task, const Solution& solution) {
    if (solution.status != Status::Solved) return {};
    // The same re-verification export gives a solution read from a file.
    io::ParsedSolution parsed{solution, true};
    output::recertify(task, parsed);
    return std::move(parsed.solution.certificate);
}

Certificate certify(const SpatialTask& task, const Solution& solution) {
    if (solution.status != Status::Solved) return {};
    io::ParsedSolution parsed{solution, true};
    output::recertify(task, parsed);
    return std::move(parsed.solution.certificate);
}

std::string uncertified_reason(const Certificate& certificate) {
    // The certificate of a solution that is not solved checked nothing.
    if (!certificate.ok && certificate.violations.empty() && certificate.coarse_pairs.empty())
        return "no motion was checked";
    return output::uncertified_reason(certificate);
}

std::string write_solution_json(const Solution& solution) {
    return io::to_json(solution).dump(1) + '\n';
}

Solution read_solution(std::string_view json_text) {
    return io::parse_solution_text(json_text).solution;
}

std::string write_task_json(const Task& task) { return io::to_json(task).dump(2) + '\n'; }

std::string write_task_json(const SpatialTask& task) { return io::to_json(task).dump(2) + '\n'; }

namespace {

/// A controller commands what the CSV and the joint trajectory say, so a
/// motion that fails verification again is not written to them unless
/// asked for (as `modsynth export`).
std::vector<std::string> refuse_uncertified(const Solution& s, const ExportFiles& files,
                                            output::ExportPaths& paths) {
    std::vector<std::string> refused;
    if (s.status != Status::Solved || s.certificate.ok || files.write_uncertified) return refused;
    for (std::string* path : {&paths.csv, &paths.joint_trajectory}) {
        if (path->empty()) continue;
        refused.push_back(*path + ": not written; the motion is not certified (" +
                          output::uncertified_reason(s.certificate) + ")");
        path->clear();
    }
    return refused;
}

template <class TaskT>
std::vector<std::string> export_files(const TaskT& task,
                                      const std::optional<hardware::Catalog>& catalog,
                                      const Solution& solution, const ExportFiles& files) {
    io::ParsedSolution parsed{solution, files.had_certificate};
    output::ReportFigures figures;
    figures.certificate_note = output::recertify(task, parsed);
    synth::choose_modules(task, catalog, parsed.solution);
    output::ExportPaths paths{files.report, files.urdf, files.csv, files.build_sheet,
                              files.joint_trajectory};
    std::vector<std::string> skipped = refuse_uncertified(parsed.solution, files, paths);
    for (auto& line : output::write_exports(task, parsed.solution, paths, figures))
        skipped.push_back(std::move(line));
    return skipped;
}

}  // namespace

std::vector<std::string> write_exports(const Task& task, const Solution& solution,
                                       const ExportFiles& files) {
    return export_files(task, hardware::catalog_for(task).catalog, solution, files);
}

std::vector<std::string> write_exports(const SpatialTask& task, const Solution& solution,
                                       const ExportFiles& files) {
    std::string note;
    return export_files(task, hardware::spatial_catalog(task, &note), solution, files);
}

namespace {

app::DrawingTaskOptions task_options(const DrawingImport& r) {
    app::DrawingTaskOptions o;
    o.name = r.name;
    o.text = r.text;
    o.font = r.font;
    o.height = r.text_height;
    if (r.width) o.width = *r.width;
    if (r.scale) o.scale = *r.scale;
    o.rotate = r.rotate_degrees;
    o.tolerance = r.tolerance;
    o.time_limit = r.time_limit;
    if (r.at) o.at = {r.at->first, r.at->second};
    o.bases = r.base_regions;
    o.obstacle_layer = r.obstacle_layer;
    o.layers = r.layers;
    o.strict = r.strict;
    o.hatch_boundaries = r.hatch_boundaries;
    o.dof = r.dof;
    if (r.link_diameter) o.link_diameter = *r.link_diameter;
    o.keep_order = r.keep_order;
    o.plane = r.plane;
    o.cylinder = r.cylinder;
    if (r.tool_length) o.tool_length = *r.tool_length;
    o.tool = r.tool;
    o.tool_tolerance_degrees = r.tool_tolerance_degrees;
    return o;
}

/// The command line checks its numbers as it reads them (number_checks.h):
/// the same bounds, named as it names them.
void check_number(const char* option, double v, double lo, double hi, bool open_lo = false) {
    if (!std::isfinite(v)) throw InputError(option, "expected a finite number");
    if (open_lo ? v <= lo : v < lo)
        throw InputError(option, text::format("must be %s %g, got %g",
                                              open_lo ? "greater than" : "at least", lo, v));
    if (v > hi) throw InputError(option, text::format("must be at most %g, got %g", hi, v));
}

void check_numbers(const DrawingImport& r) {
    constexpr double kFar = 1e9;  // metres: any coordinate of a drawing's placement
    check_number("--height", r.text_height, 1e-6, 1e3);
    if (r.width) check_number("--width", *r.width, 0.0, kFar, true);
    if (r.scale) check_number("--scale", *r.scale, 0.0, kFar, true);
    if (r.at) {
        check_number("--at", r.at->first, -kFar, kFar);
        check_number("--at", r.at->second, -kFar, kFar);
    }
    check_number("--rotate", r.rotate_degrees, -3600.0, 3600.0);
    check_number("--tolerance", r.tolerance, 1e-9, 1.0);
    check_number("--time-limit", r.time_limit, 0.0, 7 * 24 * 3600.0, true);
    for (const auto& b : r.base_regions)
        for (double v : b) check_number("--base", v, -kFar, kFar);
    for (double v : r.plane) check_number("--plane", v, -kFar, kFar);
    for (double v : r.cylinder) check_number("--cylinder", v, -kFar, kFar);
    if (r.link_diameter) check_number("--link-diameter", *r.link_diameter, 0.0, kFar, true);
    if (r.tool_length) check_number("--tool-length", *r.tool_length, 0.0, 1e3);
}

/// The drawing's format: the file's extension, or the one given with its
/// contents.
drawing::DrawingFormat format_of(const DrawingImport& r) {
    if (r.format == "svg") return drawing::DrawingFormat::Svg;
    if (r.format == "dxf") return drawing::DrawingFormat::Dxf;
    if (!r.format.empty()) throw InputError("format", "expected \"svg\" or \"dxf\"");
    if (!r.path.empty()) return drawing::format_of(r.path);
    throw InputError("format", "give the format (\"svg\" or \"dxf\") of a drawing's contents");
}

}  // namespace

ImportedDrawing import_drawing(const DrawingImport& request) {
    const auto start = drawing::Clock::now();
    const int given = !request.path.empty() + !request.contents.empty() + !request.text.empty();
    if (given != 1)
        throw InputError("drawing", "give one of a drawing file, a drawing's contents or a text");
    check_numbers(request);
    app::DrawingTaskOptions o = task_options(request);
    app::check_options(o);
    if (o.name.empty())
        o.name = !request.text.empty()   ? "text"
                 : !request.path.empty() ? std::filesystem::path(request.path).stem().string()
                                         : "drawing";
    drawing::ImportOptions options = app::import_options(o);
    const app::SurfaceImport surface = app::surface_of(o);
    const double wrap_tolerance = app::prepare_surface_import(options, surface);
    options.deadline = start + std::chrono::duration_cast<drawing::Clock::duration>(
                                   std::chrono::duration<double>(request.time_limit));
    try {
        drawing::ImportResult r;
        if (!request.text.empty()) {
            // Its errors name the text's options already.
            r = drawing::import_drawing(app::text_drawing(o), options);
        } else {
            try {
                const drawing::DrawingFormat format = format_of(request);
                const std::string contents =
                    request.path.empty()
                        ? request.contents
                        : io::read_input_file(request.path, "drawing", drawing::kMaxDrawingBytes);
                r = drawing::import_drawing(contents, format, options);
            } catch (const InputError& e) {
                // Named as `modsynth import` names it, once: "drawing.svg:
                // path#p3 (line 12): ...".
                if (request.path.empty()) throw;
                throw e.in_file(request.path);
            }
        }
        const nlohmann::json doc =
            o.spatial() ? app::surface_task_json(r, surface, app::spatial_base_task(o),
                                                 wrap_tolerance, options.deadline)
                        : app::imported_task_json(r, app::base_task(o));
        ImportedDrawing out;
        out.task_json = doc.dump(2) + '\n';
        const nlohmann::json& strokes =
            doc.contains("strokes") ? doc["strokes"] : nlohmann::json::array({doc["trajectory"]});
        for (const auto& stroke : strokes) out.primitives_per_stroke.push_back(stroke.size());
        out.obstacles = r.obstacles.size();
        out.deviation = r.deviation;
        out.travel = r.travel;
        out.surface = o.spatial() ? surface.kind() : "";
        out.warnings = r.warnings;
        out.filled_outlines = r.filled_outlines;
        out.layers.assign(r.layers.begin(), r.layers.end());
        return out;
    } catch (const drawing::ImportTimeout& e) {
        throw ImportTimeout(
            text::format("not imported within the time limit (%g s): ", request.time_limit) +
            e.what());
    }
}

void set_catalog_folder(const std::string& folder) { hardware::set_default_catalog_folder(folder); }

std::string catalog_folder() { return hardware::default_catalog_folder(); }

}  // namespace modsynth
