#pragma once
// Strokes as an SVG drawing, one path per stroke of lines (L) and arcs (A),
// in millimetres on a page whose bottom-left corner is the task's origin:
// what read_svg reads back to the same primitives.
#include <string>
#include <vector>

#include <modsynth/drawing/stroke_order.h>

namespace modsynth::drawing {

std::string write_svg(const std::vector<Chain>& strokes);

}  // namespace modsynth::drawing
