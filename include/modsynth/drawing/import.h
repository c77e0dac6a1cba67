#pragma once
// A drawing file to the strokes of a task: read it, place it in the task
// plane (scale, rotation, position), fit every curve with primitives within
// the tolerance, and order the strokes.
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <modsynth/drawing/deadline.h>
#include <modsynth/drawing/drawing.h>
#include <modsynth/drawing/stroke_order.h>
#include <modsynth/geometry/disc.h>

namespace modsynth::drawing {

enum class DrawingFormat { Svg, Dxf };

/// By the file name's extension (.svg, .dxf, any case); throws
/// task::InputError for any other.
DrawingFormat format_of(const std::string& path);

struct Placement {
    std::optional<double> width;  ///< the drawing's bounding box width, metres
    std::optional<double> scale;  ///< metres per drawing unit
    /// Where the bounding box's centre lands; absent: the drawing's own
    /// origin stays at the task's origin.
    std::optional<Vec2> at;
    double rotate_degrees = 0.0;  ///< counter-clockwise, about that point
};

struct ImportOptions {
    ReadOptions read;
    Placement placement;
    double tolerance = 1e-4;  ///< largest deviation from the drawing, metres
    bool keep_order = false;  ///< strokes in file order and direction
    /// Past it the import stops with ImportTimeout (deadline.h).
    Clock::time_point deadline = kNoDeadline;
};

struct ImportResult {
    std::vector<Chain> strokes;
    std::vector<geometry::Disc> obstacles;
    double deviation = 0.0;  ///< the worst found, metres
    double travel = 0.0;     ///< pen-up distance between strokes, metres
    double metres_per_unit = 0.0;
    /// Drawing units to task metres, as the placement gave it.
    Affine placement;
    /// The file's page (Drawing::page_size; 0 without one) and the map from
    /// it to task metres: placement after Drawing::page_to_units.
    Vec2 page_size = Vec2::Zero();
    Affine page_to_task;
    /// What the reader skipped (Drawing::warnings), one line each.
    std::vector<std::string> warnings;
    /// Filled shapes whose outlines were traced (Drawing::filled_outlines).
    std::size_t filled_outlines = 0;
    /// The drawing's layers and their entity counts (DXF).
    std::map<std::string, std::size_t> layers;
};

/// Throws task::InputError naming the offending element or option, and
/// ImportTimeout once options.deadline has passed.
ImportResult import_drawing(std::string_view text, DrawingFormat format,
                            const ImportOptions& options);

/// The same for a drawing already read (or made, as text is).
ImportResult import_drawing(const Drawing& drawing, const ImportOptions& options);

/// The affine map from drawing units to task metres that the placement
/// gives for this drawing.
Affine placement_map(const Drawing& drawing, const Placement& placement);

}  // namespace modsynth::drawing
