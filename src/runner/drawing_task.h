#pragma once
// What a task made from a drawing is given besides the drawing, as
// `modsynth import` takes it on its command line and the library's
// import_drawing takes it from a program: the placement, the fitting, the
// surface in space, and the task's name, base regions and robot. Errors
// name the options as the command line spells them ("--base").
#include <string>
#include <vector>

#include <modsynth/drawing/drawing.h>
#include <modsynth/drawing/hershey_text.h>
#include <modsynth/drawing/import.h>
#include <modsynth/task/spatial_task.h>
#include <modsynth/task/task.h>

#include "surface_import.h"

namespace modsynth::app {

struct DrawingTaskOptions {
    std::string name;
    /// Text written in a Hershey font instead of a drawing; `height` is
    /// its capitals' height in metres.
    std::string text, font = drawing::kDefaultFont;
    double height = 0.03;
    /// 0: not given (the file's units, no rotation).
    double width = 0.0, scale = 0.0, rotate = 0.0;
    double tolerance = 1e-4;
    double time_limit = 60.0;
    std::vector<double> at;                  ///< x, y, or none
    std::vector<std::vector<double>> bases;  ///< rectangles (4 numbers) or boxes (6)
    std::string obstacle_layer;
    std::vector<std::string> layers;
    bool strict = false;
    bool hatch_boundaries = false;
    std::vector<int> dof;
    double link_diameter = -1.0;  ///< <= 0: not given
    bool keep_order = false;
    std::vector<double> plane, cylinder;
    double tool_length = -1.0;  ///< < 0: not given
    /// "square" or "toward" (formats.md "Tool orientation"), empty: free.
    std::string tool;
    double tool_tolerance_degrees = 5.0;

    bool spatial() const { return !plane.empty() || !cylinder.empty(); }
};

/// Throws task::InputError naming the option when the options cannot make
/// a task (bad base regions, surfaces, joint counts for a chain in space,
/// a tool without a surface), before any drawing is read.
void check_options(const DrawingTaskOptions& o);

/// What the task gets from the options: its name, base regions and robot,
/// in the plane and, for a drawing placed in space, with the spatial
/// robot's defaults (formats.md) unless given.
task::Task base_task(const DrawingTaskOptions& o);
task::SpatialTask spatial_base_task(const DrawingTaskOptions& o);

SurfaceImport surface_of(const DrawingTaskOptions& o);

/// The import's options: reading, placement, tolerance and order (the
/// deadline is the caller's to set).
drawing::ImportOptions import_options(const DrawingTaskOptions& o);

/// The text in its Hershey font, its capitals `height` metres tall, the
/// first line's baseline starting at the origin. Throws task::InputError
/// naming --text for a glyph the font lacks or nothing to draw.
drawing::Drawing text_drawing(const DrawingTaskOptions& o);

}  // namespace modsynth::app
