#pragma once
// Reading an SVG drawing (SVG++ on a tinyxml2 document) into curves: paths
// with every command, absolute and relative, the basic shapes, nested
// transforms and viewBoxes. Units: millimetres, y up, origin at the page's
// bottom-left corner.
#include <string_view>

#include <modsynth/drawing/drawing.h>

namespace modsynth::drawing {

/// Throws task::InputError naming the element, e.g. "path#p3 (line 12):
/// malformed path data ...", for malformed input, elements that cannot be
/// drawn (text not converted to a path, images, ...: all of them listed),
/// zero-length curves and sizes beyond the caps of drawing.h.
Drawing read_svg(std::string_view text, const ReadOptions& options = {});

}  // namespace modsynth::drawing
