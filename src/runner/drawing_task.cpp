#include "drawing_task.h"

#include <modsynth/geometry/vec.h>
#include <modsynth/task/input_error.h>
#include <modsynth/task/limits.h>
#include <modsynth/text/format.h>
#include <modsynth/text/printable.h>

namespace modsynth::app {

using geometry::Vec2;
using task::InputError;

void check_options(const DrawingTaskOptions& o) {
    for (const auto& b : o.bases) {
        if (o.spatial()) {
            if (b.size() != 6 || !(b[0] <= b[3]) || !(b[1] <= b[4]) || !(b[2] <= b[5]))
                throw InputError("--base",
                                 "expected a box xmin,ymin,zmin,xmax,ymax,zmax with min <= max "
                                 "(--plane, --cylinder)");
        } else if (b.size() != 4 || !(b[0] <= b[2]) || !(b[1] <= b[3])) {
            throw InputError("--base", "expected xmin,ymin,xmax,ymax with min <= max");
        }
    }
    // Bad surfaces are refused before the drawing is read.
    surface_of(o).check();
    for (int n : o.dof) {
        if (o.spatial() && !(n >= task::kMinSpatialDof && n <= task::kMaxSpatialDof))
            throw InputError("--dof", text::format("%d joints: a spatial chain "
                                                   "(--plane, --cylinder) has 3 to 6",
                                                   n));
    }
    if (o.tool_length >= 0.0 && !o.spatial())
        throw InputError("--tool-length", "only with --plane or --cylinder");
    if (!o.spatial() && !o.tool.empty())
        throw InputError("--tool", "only with --plane or --cylinder");
    if (!o.tool.empty() && o.tool != "square" && o.tool != "toward")
        throw InputError("--tool",
                         "'" + text::printable(o.tool, 40) + "': 'square' or 'toward' (or none)");
    if (o.tool == "toward" && o.cylinder.empty())
        throw InputError("--tool",
                         "'toward' points at a cylinder's axis: only with "
                         "--cylinder ('square' on a plane)");
    if (!(o.tool_tolerance_degrees >= 1e-3 && o.tool_tolerance_degrees <= 90.0))
        throw InputError("--tool-tolerance", "degrees from 0.001 to 90");
}

task::Task base_task(const DrawingTaskOptions& o) {
    task::Task t;
    t.name = o.name;
    for (const auto& b : o.bases) t.base_regions.push_back({Vec2(b[0], b[1]), Vec2(b[2], b[3])});
    if (!o.dof.empty()) t.robot.dof = o.dof;
    if (o.link_diameter > 0.0) t.robot.link_diameter = o.link_diameter;
    return t;
}

task::SpatialTask spatial_base_task(const DrawingTaskOptions& o) {
    task::SpatialTask t;
    t.name = o.name;
    for (const auto& b : o.bases)
        t.base_regions.push_back(
            {geometry::Vec3(b[0], b[1], b[2]), geometry::Vec3(b[3], b[4], b[5])});
    if (!o.dof.empty()) t.robot.dof = o.dof;
    if (o.link_diameter > 0.0) t.robot.link_diameter = o.link_diameter;
    if (o.tool_length >= 0.0) t.robot.tool_length = o.tool_length;
    // Holding a tool's direction takes a hand or a wrist (formats.md "Tool
    // orientation").
    if (!o.tool.empty() && o.dof.empty()) t.robot.dof = {4, 5};
    return t;
}

SurfaceImport surface_of(const DrawingTaskOptions& o) {
    SurfaceImport s;
    s.plane = o.plane;
    s.cylinder = o.cylinder;
    s.tool = o.tool;
    s.tool_tolerance = o.tool_tolerance_degrees * geometry::kPi / 180.0;
    return s;
}

drawing::ImportOptions import_options(const DrawingTaskOptions& o) {
    drawing::ImportOptions options;
    options.read.obstacle_layer = o.obstacle_layer;
    options.read.layers = o.layers;
    options.read.strict = o.strict;
    options.read.hatch_boundaries = o.hatch_boundaries;
    if (o.width > 0.0) options.placement.width = o.width;
    if (o.scale > 0.0) options.placement.scale = o.scale;
    if (!o.at.empty()) options.placement.at = Vec2(o.at[0], o.at[1]);
    options.placement.rotate_degrees = o.rotate;
    options.tolerance = o.tolerance;
    options.keep_order = o.keep_order;
    return options;
}

drawing::Drawing text_drawing(const DrawingTaskOptions& o) {
    drawing::TextLayout layout;
    layout.font = o.font;
    layout.height = o.height;
    drawing::TextCurves t = drawing::text_curves(o.text, Vec2::Zero(), layout, "--text", "--font");
    if (!t.missing.empty()) {
        throw InputError("--text", "the font '" + o.font + "' has no glyph for '" +
                                       text::printable(t.missing, 40) + "'");
    }
    if (t.curves.empty()) throw InputError("--text", "nothing to draw");
    drawing::Drawing d;
    d.curves = std::move(t.curves);
    d.metres_per_unit = 1.0;
    return d;
}

}  // namespace modsynth::app
