#include <modsynth/text/scad.h>

#include <modsynth/text/printable.h>

namespace modsynth::text {

// A comment ends at a line break only: printable text of any length (its
// control bytes and bytes that are not UTF-8 as \xHH) is one line.
std::string scad_comment(std::string_view text) { return printable(text, text.size() + 1); }

}  // namespace modsynth::text
