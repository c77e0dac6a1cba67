#include "imported_task.h"

#include <modsynth/io/spatial_task_io.h>
#include <modsynth/io/task_io.h>
#include <modsynth/text/printable.h>

namespace modsynth::app {
namespace {

using nlohmann::json;

/// The SVG matrix(a, b, c, d, e, f) of a map: x' = a x + c y + e,
/// y' = b x + d y + f.
json svg_matrix(const drawing::Affine& m) {
    return {m.m(0, 0), m.m(1, 0), m.m(0, 1), m.m(1, 1), m.offset.x(), m.offset.y()};
}

/// True when the map turns the plane over (an SVG page, y down, to the
/// task's y up).
bool is_mirror(const drawing::Affine& a) {
    return a.m(0, 0) * a.m(1, 1) - a.m(0, 1) * a.m(1, 0) < 0.0;
}

}  // namespace

json imported_task_json(const drawing::ImportResult& r, const task::Task& base) {
    task::Task t = base;
    t.obstacles = r.obstacles;
    t.trajectory.clear();
    t.stroke_starts.clear();
    for (const auto& stroke : r.strokes) {
        if (r.strokes.size() > 1) t.stroke_starts.push_back(static_cast<int>(t.trajectory.size()));
        t.trajectory.insert(t.trajectory.end(), stroke.begin(), stroke.end());
    }
    const json doc = io::to_json(t);
    // Checked as any task is, once: every stroke against every obstacle.
    io::parse_task(doc);
    return doc;
}

json imported_spatial_task_json(const drawing::PlacedStrokes& placed,
                                const std::vector<geometry::Obstacle3>& obstacles,
                                const task::SpatialTask& base,
                                const std::function<void(task::SpatialTask&)>& finish) {
    task::SpatialTask t = base;
    t.obstacles = obstacles;
    t.trajectory.clear();
    t.stroke_starts.clear();
    for (const auto& stroke : placed.strokes) {
        if (placed.strokes.size() > 1)
            t.stroke_starts.push_back(static_cast<int>(t.trajectory.size()));
        t.trajectory.insert(t.trajectory.end(), stroke.begin(), stroke.end());
    }
    if (finish) finish(t);
    const json doc = io::to_json(t);
    io::parse_spatial_task(doc);
    return doc;
}

namespace {

/// The reply's keys but the task's: counts of what `task` holds, the
/// figures of the import.
json reply_json(const drawing::ImportResult& r, const drawing::ImportOptions& options,
                const json& task) {
    // A task in space may hold more primitives than the drawing had: the
    // wrapping round a cylinder fits curves anew.
    const json strokes =
        task.contains("strokes") ? task["strokes"] : json::array({task["trajectory"]});
    std::size_t primitives = 0;
    for (const auto& s : strokes) primitives += s.size();
    // What the CLI prints beside the task: the layers found with their
    // entity counts (DXF), and one line for each kind of thing skipped.
    json layers = json::object();
    for (const auto& [name, count] : r.layers) layers[text::printable(name, 200)] = count;
    json underlay = nullptr;
    if (r.page_size.x() > 0.0 && r.page_size.y() > 0.0) {
        underlay = {{"width", r.page_size.x()},
                    {"height", r.page_size.y()},
                    {"transform", svg_matrix(r.page_to_task)},
                    {"y_flip", is_mirror(r.page_to_task)}};
    }
    return {{"task", task},
            {"strokes", strokes.size()},
            {"primitives", primitives},
            {"obstacles", r.obstacles.size()},
            {"deviation", r.deviation},
            {"tolerance", options.tolerance},
            {"travel", r.travel},
            {"placement",
             {{"metres_per_unit", r.metres_per_unit},
              {"rotate_degrees", options.placement.rotate_degrees},
              {"transform", svg_matrix(r.placement)}}},
            {"underlay", underlay},
            {"warnings", r.warnings},
            {"filled_outlines", r.filled_outlines},
            {"layers", layers}};
}

}  // namespace

json import_reply_json(const drawing::ImportResult& r, const drawing::ImportOptions& options,
                       const task::Task& base) {
    return reply_json(r, options, imported_task_json(r, base));
}

json surface_import_reply_json(const drawing::ImportResult& r,
                               const drawing::ImportOptions& options, const json& task,
                               const char* surface, double tolerance) {
    json reply = reply_json(r, options, task);
    reply["tolerance"] = tolerance;
    reply["underlay"] = nullptr;
    reply["surface"] = surface;
    return reply;
}

}  // namespace modsynth::app
