#pragma once
// SVG clip paths applied to the centrelines: a robot traces a stroke's
// centreline, so clipping it keeps the pieces of the line inside the clip
// region (and cuts those that cross its edge) rather than any outline.
#include <string>
#include <vector>

#include <modsynth/drawing/curve.h>
#include <modsynth/drawing/deadline.h>

namespace modsynth::drawing::svg_clip {

/// One filled shape of a clip path: the rings of its outline (flattened,
/// closed implicitly) and the rule that says what they enclose.
struct Shape {
    std::vector<std::vector<Vec2>> rings;
    bool even_odd = false;
};

/// The union of a clip path's shapes, in the outer viewport's pixels.
struct Region {
    std::vector<Shape> shapes;
    /// Points this close to an edge are inside: a stroke that runs along
    /// the clip's edge (a flag's border) is drawn.
    double margin = 0.0;
};

bool inside(const Region& region, const Vec2& p);

/// The pieces of `curve` inside `region`, each a curve of its own (same
/// source). Lines are cut exactly where they cross an edge; curves where
/// a fine polyline of them does, refined by bisection. The work grows with
/// the chords times the region's edges: past `deadline` it stops with
/// ImportTimeout.
std::vector<Curve> clipped(const Curve& curve, const Region& region,
                           Clock::time_point deadline = kNoDeadline);

/// Appends points along a segment to a ring, its start left out (the
/// ring's last point) and its end kept: a line as itself, a curve as 256
/// chords.
void flatten(const Segment& s, std::vector<Vec2>& ring);

}  // namespace modsynth::drawing::svg_clip
