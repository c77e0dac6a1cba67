#pragma once
// SVG `use` elements resolved in the document itself, before it is walked:
// each becomes a `g` that holds a copy of what it references, moved by its
// transform and its x and y, so that the walk sees what a browser renders.
#include <string>

#include <tinyxml2.h>

namespace modsynth::drawing::svg_use {

/// Replaces every `use` of the document (nested ones too) by the group it
/// draws. Throws task::InputError naming the `use` for a reference to an
/// id the file does not hold, to another file, or to itself (directly or
/// through others: the chain is named), and naming the document when the
/// copies would exceed the reader's caps.
void expand(tinyxml2::XMLDocument& doc);

/// A copy of `e` and all it holds in `doc`, which keeps the lines of the
/// originals for line_of.
tinyxml2::XMLElement* copy_of(const tinyxml2::XMLElement* e, tinyxml2::XMLDocument& doc);

/// The line an element was written on: the referenced element's for a
/// copy, with the line of the `use` that drew it ("12, drawn by use at line
/// 30"), so that messages point into the file.
std::string line_of(const tinyxml2::XMLElement* e);

}  // namespace modsynth::drawing::svg_use
