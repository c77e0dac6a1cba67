#include <modsynth/text/markdown.h>

#include "utf8.h"

namespace modsynth::text {

std::string markdown_literal(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (const char c : text) {
        const auto u = static_cast<unsigned char>(c);
        if (const char* ref = markup_reference(c)) {
            out += ref;
            continue;
        }
        if (u < 0x20 || u == 0x7f) {
            out += "\xEF\xBF\xBD";
        } else if ((u >= 0x21 && u <= 0x2f) || (u >= 0x3a && u <= 0x40) ||
                   (u >= 0x5b && u <= 0x60) || (u >= 0x7b && u <= 0x7e)) {
            // CommonMark lets a backslash escape any ASCII punctuation.
            out += '\\';
            out += c;
        } else {
            out += c;
        }
    }
    return out;
}

}  // namespace modsynth::text
