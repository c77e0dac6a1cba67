// `modsynth import`: a drawing (SVG, DXF) to a task; `modsynth export-svg`:
// a task's primitives back to an SVG drawing.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <modsynth/drawing/hershey_text.h>
#include <modsynth/drawing/import.h>
#include <modsynth/drawing/svg_writer.h>
#include <modsynth/io/atomic_file.h>
#include <modsynth/io/input.h>
#include <modsynth/io/task_checks.h>
#include <modsynth/io/task_document.h>
#include <modsynth/io/task_io.h>
#include <modsynth/task/input_error.h>
#include <modsynth/task/limits.h>
#include <modsynth/task/spatial_task.h>
#include <modsynth/task/strokes.h>
#include <modsynth/text/format.h>
#include <modsynth/text/printable.h>

#include "command.h"
#include "drawing_task.h"
#include "imported_task.h"
#include "number_checks.h"
#include "planar_task.h"
#include "surface_import.h"
#include "watchdog.h"

namespace modsynth::app {

namespace {

using task::InputError;

struct ImportArgs : DrawingTaskOptions {
    std::string input, output, reply;
};

std::string file_stem(const std::string& path) {
    return std::filesystem::path(path).stem().string();
}

/// --reply: why the drawing was not imported, as the server answers it.
void write_error_reply(const ImportArgs& a, const std::string& message, const std::string& part) {
    if (a.reply.empty()) return;
    nlohmann::json body = {{"error", message}};
    if (!part.empty()) body["part"] = part;
    io::write_file_atomically(a.reply, body.dump() + "\n");
}

// Past the time limit by this much, the watchdog answers for the import.
constexpr double kWatchdogMargin = 0.6;

int run_import(ImportArgs& a) {
    io::check_outputs({{"-o", a.output}, {"--reply", a.reply}}, {a.input});
    const auto start = drawing::Clock::now();
    const auto limit = std::chrono::duration_cast<drawing::Clock::duration>(
        std::chrono::duration<double>(a.time_limit));
    const auto timed_out = [&](const std::string& why) {
        const std::string message =
            text::format("not imported within the time limit (%g s): ", a.time_limit) + why;
        write_error_reply(a, message, {});
        std::fprintf(stderr, "error: %s: %s\n", a.input.c_str(), message.c_str());
        return int{kUnknown};
    };
    // The importer checks its deadline as it goes; this ends the command
    // even inside a library call that does not return.
    Watchdog watchdog(a.time_limit + kWatchdogMargin,
                      [&] { return timed_out("the import did not stop at its deadline"); });
    const bool from_text = !a.text.empty();
    if (from_text) a.input = "--text";
    if (a.name.empty()) a.name = from_text ? "text" : file_stem(a.input);
    drawing::ImportOptions options = import_options(a);
    const SurfaceImport surface = surface_of(a);
    const double wrap_tolerance = prepare_surface_import(options, surface);
    options.deadline = start + limit;
    drawing::ImportResult r;
    nlohmann::json doc, reply;
    try {
        try {
            if (from_text) {
                r = drawing::import_drawing(text_drawing(a), options);
            } else {
                const drawing::DrawingFormat format = drawing::format_of(a.input);
                const std::string text =
                    io::read_input_file(a.input, "drawing", drawing::kMaxDrawingBytes);
                r = drawing::import_drawing(text, format, options);
            }
        } catch (const InputError& e) {
            // Name the file too, once: "drawing.svg: path#p3 (line 12): ...".
            write_error_reply(a, e.what(), e.part());
            throw e.in_file(a.input);
        }
        if (a.spatial()) {
            doc = surface_task_json(r, surface, spatial_base_task(a), wrap_tolerance,
                                    options.deadline);
            reply = surface_import_reply_json(r, options, doc, surface.kind(), a.tolerance);
        } else if (a.reply.empty()) {
            doc = imported_task_json(r, base_task(a));
        } else {
            reply = import_reply_json(r, options, base_task(a));
            doc = reply["task"];
        }
    } catch (const drawing::ImportTimeout& e) {
        watchdog.claim();
        return timed_out(e.what());
    } catch (const InputError& e) {
        watchdog.claim();
        if (!a.reply.empty() && !std::filesystem::exists(a.reply))
            write_error_reply(a, e.what(), e.part());
        throw;
    }
    watchdog.claim();
    io::write_file_atomically(a.output, doc.dump(2) + "\n");
    if (!a.reply.empty()) io::write_file_atomically(a.reply, reply.dump() + "\n");

    std::size_t total = 0;
    std::string counts;
    for (const auto& s : r.strokes) {
        total += s.size();
        counts += (counts.empty() ? "" : " ") + std::to_string(s.size());
    }
    if (a.spatial()) {
        total = 0;
        counts.clear();
        const nlohmann::json& doc_strokes =
            doc.contains("strokes") ? doc["strokes"] : nlohmann::json::array({doc["trajectory"]});
        for (const auto& s : doc_strokes) {
            total += s.size();
            counts += (counts.empty() ? "" : " ") + std::to_string(s.size());
        }
    }
    std::printf("%s -> %s: %s%zu stroke%s, %zu primitives, %zu obstacles\n", a.input.c_str(),
                a.output.c_str(),
                a.plane.empty() ? (a.cylinder.empty() ? "" : "round a cylinder, ") : "on a plane, ",
                r.strokes.size(), r.strokes.size() == 1 ? "" : "s", total, r.obstacles.size());
    std::printf("deviation: %.3g m (tolerance %.3g m)\n", r.deviation, a.tolerance);
    std::printf("primitives per stroke: %s\n", counts.c_str());
    std::printf("travel: %.6g m\n", r.travel);
    if (r.filled_outlines > 0) {
        std::printf("traced the outlines of %zu filled shape%s (a fill has no centreline)\n",
                    r.filled_outlines, r.filled_outlines == 1 ? "" : "s");
    }
    if (!r.layers.empty()) {
        std::string layers;
        for (const auto& [name, count] : r.layers)
            layers += (layers.empty() ? "" : ", ") + text::printable(name) + " (" +
                      std::to_string(count) + ")";
        std::printf("layers (entities): %s\n", layers.c_str());
    }
    // The warnings after the summary, as a terminal shows them.
    std::fflush(stdout);
    for (const std::string& w : r.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    // A drawing in millimetres read as metres makes a task a hundred metres
    // across: say so, with the options that place it.
    for (const InputError& w : io::unit_warnings(doc))
        std::fprintf(stderr,
                     "warning: %s: %s; give --scale (metres per drawing unit: 0.001 for a "
                     "drawing in millimetres) or --width (its width in metres)\n",
                     a.output.c_str(), w.what());
    return kOk;
}

/// The primitives of each stroke of a task file (one for a trajectory),
/// read and checked as every command reads a task.
std::vector<drawing::Chain> task_strokes(const std::string& path) {
    const task::Task t = load_planar_task(path, "export-svg");
    std::vector<drawing::Chain> out;
    for (int s = 0; s < task::stroke_count(t); ++s) {
        out.emplace_back(t.trajectory.begin() + task::stroke_first(t, s),
                         t.trajectory.begin() + task::stroke_last(t, s) + 1);
    }
    return out;
}

}  // namespace

Command add_import(CLI::App& parent) {
    auto a = std::make_shared<ImportArgs>();
    CLI::App* sub = parent.add_subcommand(
        "import", "Make a task from a drawing (SVG or DXF): its curves as lines and arcs");
    auto* input = sub->add_option("DRAWING", a->input, "drawing.svg or drawing.dxf");
    auto* text = sub->add_option("--text", a->text,
                                 "write this text (instead of a drawing) in a single-stroke font")
                     ->excludes(input);
    input->excludes(text);
    sub->add_option("--font", a->font,
                    std::string("Hershey font of --text (default ") + drawing::kDefaultFont +
                        "; any of /usr/share/hershey-fonts)")
        ->needs(text);
    sub->add_option("--height", a->height, "capital height of --text, metres (default 0.03)")
        ->check(within(1e-6, 1e3))
        ->needs(text);
    sub->add_option("-o,--output", a->output, "task file to write")->required();
    auto* width =
        sub->add_option("--width", a->width, "drawing width in metres")->check(positive());
    sub->add_option("--scale", a->scale,
                    "metres per drawing unit (default: the file's units; SVG in mm)")
        ->check(positive())
        ->excludes(width);
    auto* at = sub->add_option("--at", a->at, "X,Y: where the drawing's centre goes (metres)")
                   ->delimiter(',')
                   ->expected(2)
                   ->check(within(-1e9, 1e9));
    auto* plane =
        sub->add_option("--plane", a->plane,
                        "OX,OY,OZ,UX,UY,UZ,VX,VY,VZ: place the drawing in space on a plane, its "
                        "centre at O, its x along U and its y along V (unit and perpendicular "
                        "within 1e-3); writes a spatial task")
            ->delimiter(',')
            ->allow_extra_args(false)
            ->check(within(-1e9, 1e9))
            ->excludes(at);
    sub->add_option("--cylinder", a->cylinder,
                    "CX,CY,CZ,AX,AY,AZ,R: wrap the drawing round a cylinder of radius R whose "
                    "axis runs along A through C, the point level with the drawing's centre; "
                    "its x runs round the axis, its y along it, facing the first --base box "
                    "(else the origin); writes a spatial task")
        ->delimiter(',')
        ->allow_extra_args(false)
        ->check(within(-1e9, 1e9))
        ->excludes(at)
        ->excludes(plane);
    sub->add_option("--rotate", a->rotate,
                    "degrees, counter-clockwise about --at (with --plane or --cylinder, "
                    "about the drawing's centre in its own plane)")
        ->check(within(-3600.0, 3600.0));
    sub->add_option("--tolerance", a->tolerance,
                    "largest deviation from the drawing, metres (default 1e-4)")
        ->check(within(1e-9, 1.0));
    sub->add_option("--time-limit", a->time_limit,
                    "seconds for the whole import (default 60); past it, exit 4")
        ->check(seconds());
    sub->add_option("--base", a->bases,
                    "xmin,ymin,xmax,ymax: a base region (repeatable); with --plane or "
                    "--cylinder a box xmin,ymin,zmin,xmax,ymax,zmax")
        ->delimiter(',')
        ->expected(4, 6)
        ->allow_extra_args(false)
        ->check(within(-1e9, 1e9));
    sub->add_option(
        "--obstacles-from", a->obstacle_layer,
        "layer (SVG group id or inkscape:label, DXF layer) whose circles are obstacles");
    sub->add_option("--layers", a->layers, "A,B: import only these DXF layers")->delimiter(',');
    sub->add_flag("--strict", a->strict,
                  "refuse what cannot be traced (text without a font, hatches, dimensions, "
                  "points, images, 3D solids, degenerate pieces) instead of skipping it");
    sub->add_flag("--hatch-boundaries", a->hatch_boundaries,
                  "trace the boundary paths of DXF hatches (their outlines) instead of "
                  "skipping them");
    sub->add_option("--name", a->name, "task name (default: the file name)");
    sub->add_option("--dof", a->dof,
                    "allowed joint counts, e.g. 2,3 (default 2,3; with --plane or --cylinder "
                    "3,4, each 3 to 6)")
        ->delimiter(',');
    sub->add_option("--link-diameter", a->link_diameter, "tube diameter, metres (default 0.03175)")
        ->check(positive());
    sub->add_option("--tool-length", a->tool_length,
                    "with --plane or --cylinder: the tool at the chain's end, metres (default 0; "
                    "links 0.05 to 1 m, twists 0 and +-90 degrees)")
        ->check(within(0.0, 1e3));
    sub->add_option("--tool", a->tool,
                    "with --plane or --cylinder: 'square' holds the tool square into the "
                    "surface while it traces (a pen on an easel, a brush on a pipe); "
                    "'toward', round a cylinder, the same: at its axis")
        ->check(CLI::IsMember({"square", "toward"}));
    sub->add_option("--tool-tolerance", a->tool_tolerance_degrees,
                    "with --tool: how far the tool may tilt from square, degrees (default 5)")
        ->check(within(1e-3, 90.0));
    sub->add_flag("--keep-order", a->keep_order,
                  "draw the strokes in the file's order and direction");
    // What `serve` runs an import with: the reply of POST /api/import (or
    // its error) as JSON. Not for users: no help line.
    sub->add_option("--reply", a->reply)->group("");
    return {sub, [a] {
                if (a->input.empty() && a->text.empty())
                    throw InputError("DRAWING", "give a drawing file or --text");
                check_options(*a);
                return run_import(*a);
            }};
}

Command add_export_svg(CLI::App& parent) {
    auto input = std::make_shared<std::string>();
    auto output = std::make_shared<std::string>();
    CLI::App* sub = parent.add_subcommand(
        "export-svg", "Write a task's primitives as an SVG drawing (lines and arcs, in mm)");
    sub->add_option("TASK", *input, "task file (trajectory or strokes)")->required();
    sub->add_option("-o,--output", *output, "SVG file to write")->required();
    return {sub, [input, output] {
                io::check_outputs({{"-o", *output}}, {*input});
                const auto strokes = task_strokes(*input);
                io::write_file_atomically(*output, drawing::write_svg(strokes));
                std::printf("%s -> %s: %zu stroke%s\n", input->c_str(), output->c_str(),
                            strokes.size(), strokes.size() == 1 ? "" : "s");
                return int{kOk};
            }};
}

}  // namespace modsynth::app
