#pragma once
// Reading a DXF drawing (dxflib) into curves: LINE, ARC, CIRCLE, ELLIPSE,
// LWPOLYLINE and POLYLINE (with bulges) and SPLINE, in the file's units
// ($INSUNITS when it states them), y up.
#include <string_view>

#include <modsynth/drawing/drawing.h>

namespace modsynth::drawing {

/// Throws task::InputError naming the entity ("SPLINE #4 (layer 0)") for
/// malformed entities, entities that cannot be drawn (TEXT, INSERT, HATCH,
/// ...: all listed), zero-length curves, sizes beyond the caps of drawing.h
/// and text that is not DXF.
Drawing read_dxf(std::string_view text, const ReadOptions& options = {});

}  // namespace modsynth::drawing
