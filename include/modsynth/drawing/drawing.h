#pragma once
// What a drawing file holds once read: its curves and the circles of its
// obstacle layer, in the drawing's own units with y pointing up.
#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include <modsynth/drawing/curve.h>
#include <modsynth/drawing/deadline.h>
#include <modsynth/geometry/disc.h>

namespace modsynth::drawing {

struct Drawing {
    std::vector<Curve> curves;
    /// Circles found on the obstacle layer (`--obstacles-from`).
    std::vector<geometry::Disc> obstacles;
    /// Metres per drawing unit as the file states it (SVG: its units are
    /// read as millimetres; DXF: $INSUNITS), 0 when the file does not say.
    double metres_per_unit = 0.0;
    /// The file's own page as a viewer shows it (SVG: the outer viewport in
    /// pixels, y down) and the map from it to drawing units, so that the
    /// original can be drawn under what is fitted; a size of 0 when the
    /// format has no page (DXF).
    Vec2 page_size = Vec2::Zero();
    Affine page_to_units;
    /// What was read but not drawn, one line per reason: entities that
    /// cannot be traced, degenerate pieces (ReadOptions::strict refuses
    /// them instead).
    std::vector<std::string> warnings;
    /// Shapes only filled, not stroked (SVG), whose outlines were traced:
    /// a fill has no centreline, so an icon set drawn with fills takes
    /// several times the primitives of its stroked version.
    std::size_t filled_outlines = 0;
    /// The drawing's layers (DXF) and how many entities each holds.
    std::map<std::string, std::size_t> layers;
};

/// What a reader accepts: which layer's circles are obstacles ("" none).
struct ReadOptions {
    std::string obstacle_layer;
    /// The layers to read (DXF); empty: all of them.
    std::vector<std::string> layers;
    /// Refuse, rather than skip with a warning, what cannot be traced.
    bool strict = false;
    /// Trace the boundary paths of DXF HATCH entities as strokes (a fill
    /// has no centreline; its outline is what a pen can draw), rather than
    /// skip them with a warning.
    bool hatch_boundaries = false;
    /// Past it the reading stops with ImportTimeout (deadline.h): clip paths
    /// make work that grows with their size times the drawing's.
    Clock::time_point deadline = kNoDeadline;
};

/// The sizes a reader refuses beyond (a drawing for a robot arm has
/// hundreds of curves, not millions), so that no file makes it crash or
/// run for long.
constexpr std::size_t kMaxDrawingBytes = 16u << 20;
constexpr std::size_t kMaxCurves = 20000;
constexpr std::size_t kMaxSegments = 200000;
constexpr std::size_t kMaxSplineControlPoints = 10000;
constexpr int kMaxSplineDegree = 10;
/// Every coordinate of a drawing lies within this many drawing units of
/// its origin.
constexpr double kMaxDrawingCoordinate = 1e9;

}  // namespace modsynth::drawing
