#pragma once
// The report's inline style sheet and script.

namespace modsynth::output::assets {

extern const char* const kStyle;
/// Plays the motion stored in the element #motion-data (see report.cpp)
/// on the SVG #plot, with the controls #play, #scrub, #speed.
extern const char* const kScript;

}  // namespace modsynth::output::assets
