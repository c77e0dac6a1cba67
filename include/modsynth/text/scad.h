#pragma once
// User text (a task's name, a catalog's module names) written into an
// OpenSCAD source, where a line break would end a comment and make the rest
// code that openscad runs (a cube, an include of any file).
#include <string>
#include <string_view>

namespace modsynth::text {

/// The text for an OpenSCAD line comment (after "//"): one line, its
/// control characters (line breaks first) and bytes that are not UTF-8
/// written as \xHH, nothing else changed.
std::string scad_comment(std::string_view text);

}  // namespace modsynth::text
