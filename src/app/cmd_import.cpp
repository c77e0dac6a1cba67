// `modsynth import`: a drawing (SVG, DXF) to a task; `modsynth export-svg`:
// a task's primitives back to an SVG drawing.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <modsynth/drawing/import.h>
#include <modsynth/drawing/svg_writer.h>
#include <modsynth/io/atomic_file.h>
#include <modsynth/io/input.h>
#include <modsynth/io/task_document.h>
#include <modsynth/io/task_io.h>
#include <modsynth/task/input_error.h>

#include "command.h"
#include "imported_task.h"
#include "planar_task.h"

namespace modsynth::app {

namespace {

using geometry::Vec2;
using task::InputError;

struct ImportArgs {
    std::string input, output, name;
    double width = 0.0, scale = 0.0, rotate = 0.0, tolerance = 1e-4;
    std::vector<double> at;
    std::vector<std::vector<double>> bases;
    std::string obstacle_layer;
    std::vector<int> dof;
    double link_diameter = -1.0;
    bool keep_order = false;
};

/// What the task gets from the options: its name, base regions and robot.
task::Task base_task(const ImportArgs& a) {
    task::Task t;
    t.name = a.name;
    for (const auto& b : a.bases) t.base_regions.push_back({Vec2(b[0], b[1]), Vec2(b[2], b[3])});
    if (!a.dof.empty()) t.robot.dof = a.dof;
    if (a.link_diameter > 0.0) t.robot.link_diameter = a.link_diameter;
    return t;
}

std::string file_stem(const std::string& path) {
    return std::filesystem::path(path).stem().string();
}

int run_import(ImportArgs& a) {
    const drawing::DrawingFormat format = drawing::format_of(a.input);
    std::error_code ec;
    const auto size = std::filesystem::file_size(a.input, ec);
    if (!ec && size > drawing::kMaxDrawingBytes) {
        throw InputError(a.input, "larger than " + std::to_string(drawing::kMaxDrawingBytes >> 20) +
                                      " MB: too large for a drawing");
    }
    const std::string text = io::read_input_file(a.input, "drawing");
    drawing::ImportOptions options;
    options.read.obstacle_layer = a.obstacle_layer;
    if (a.width > 0.0) options.placement.width = a.width;
    if (a.scale > 0.0) options.placement.scale = a.scale;
    if (!a.at.empty()) options.placement.at = Vec2(a.at[0], a.at[1]);
    options.placement.rotate_degrees = a.rotate;
    options.tolerance = a.tolerance;
    options.keep_order = a.keep_order;
    drawing::ImportResult r;
    try {
        r = drawing::import_drawing(text, format, options);
    } catch (const InputError& e) {
        // Name the file too: "drawing.svg: path#p3 (line 12): ...".
        const std::string problem = e.part().empty() ? e.what() : e.what() + e.part().size() + 2;
        throw InputError(a.input + ": " + e.part(), problem);
    }
    if (a.name.empty()) a.name = file_stem(a.input);
    const nlohmann::json doc = imported_task_json(r, base_task(a));
    io::write_file_atomically(a.output, doc.dump(2) + "\n");

    std::size_t total = 0;
    std::string counts;
    for (const auto& s : r.strokes) {
        total += s.size();
        counts += (counts.empty() ? "" : " ") + std::to_string(s.size());
    }
    std::printf("%s -> %s: %zu stroke%s, %zu primitives, %zu obstacles\n", a.input.c_str(),
                a.output.c_str(), r.strokes.size(), r.strokes.size() == 1 ? "" : "s", total,
                r.obstacles.size());
    std::printf("deviation: %.3g m (tolerance %.3g m)\n", r.deviation, a.tolerance);
    std::printf("primitives per stroke: %s\n", counts.c_str());
    std::printf("travel: %.6g m\n", r.travel);
    return kOk;
}

/// The primitives of each stroke of a task file (one for a trajectory).
std::vector<drawing::Chain> task_strokes(const std::string& path) {
    const nlohmann::json doc = io::parse_json_text(io::read_input_file(path, "task"));
    if (io::is_spatial(doc)) throw spatial_not_supported("export-svg");
    std::vector<drawing::Chain> out;
    if (doc.is_object() && doc.contains("strokes") && doc["strokes"].is_array()) {
        // Each stroke is read as the trajectory of a task of its own.
        for (std::size_t s = 0; s < doc["strokes"].size(); ++s) {
            nlohmann::json one = doc;
            one.erase("strokes");
            one["trajectory"] = doc["strokes"][s];
            try {
                out.push_back(io::parse_task(one).trajectory);
            } catch (const InputError& e) {
                throw InputError(path, "strokes[" + std::to_string(s) + "]: " + e.what());
            }
        }
        if (out.empty()) throw InputError(path, "strokes: empty");
        return out;
    }
    out.push_back(io::parse_task(doc).trajectory);
    return out;
}

}  // namespace

Command add_import(CLI::App& parent) {
    auto a = std::make_shared<ImportArgs>();
    CLI::App* sub = parent.add_subcommand(
        "import", "Make a task from a drawing (SVG or DXF): its curves as lines and arcs");
    sub->add_option("DRAWING", a->input, "drawing.svg or drawing.dxf")->required();
    sub->add_option("-o,--output", a->output, "task file to write")->required();
    auto* width =
        sub->add_option("--width", a->width, "drawing width in metres")->check(CLI::PositiveNumber);
    sub->add_option("--scale", a->scale,
                    "metres per drawing unit (default: the file's units; SVG in mm)")
        ->check(CLI::PositiveNumber)
        ->excludes(width);
    sub->add_option("--at", a->at, "X,Y: where the drawing's centre goes (metres)")
        ->delimiter(',')
        ->expected(2);
    sub->add_option("--rotate", a->rotate, "degrees, counter-clockwise about --at")
        ->check(CLI::Range(-3600.0, 3600.0));
    sub->add_option("--tolerance", a->tolerance,
                    "largest deviation from the drawing, metres (default 1e-4)")
        ->check(CLI::Range(1e-9, 1.0));
    sub->add_option("--base", a->bases, "xmin,ymin,xmax,ymax: a base region (repeatable)")
        ->delimiter(',')
        ->expected(4)
        ->allow_extra_args(false);
    sub->add_option(
        "--obstacles-from", a->obstacle_layer,
        "layer (SVG group id or inkscape:label, DXF layer) whose circles are obstacles");
    sub->add_option("--name", a->name, "task name (default: the file name)");
    sub->add_option("--dof", a->dof, "allowed joint counts, e.g. 2,3")->delimiter(',');
    sub->add_option("--link-diameter", a->link_diameter, "tube diameter, metres")
        ->check(CLI::PositiveNumber);
    sub->add_flag("--keep-order", a->keep_order,
                  "draw the strokes in the file's order and direction");
    return {sub, [a] {
                if (!a->bases.empty() || true) {
                    for (const auto& b : a->bases) {
                        if (b.size() != 4 || !(b[0] <= b[2]) || !(b[1] <= b[3])) {
                            throw InputError("--base",
                                             "expected xmin,ymin,xmax,ymax with min <= max");
                        }
                    }
                }
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
                const auto strokes = task_strokes(*input);
                io::write_file_atomically(*output, drawing::write_svg(strokes));
                std::printf("%s -> %s: %zu stroke%s\n", input->c_str(), output->c_str(),
                            strokes.size(), strokes.size() == 1 ? "" : "s");
                return int{kOk};
            }};
}

}  // namespace modsynth::app
