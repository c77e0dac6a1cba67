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

std::string markdown_text(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    const auto word = [&](std::size_t k) {
        if (k >= text.size()) return false;
        const char c = text[k];
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
    };
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        const auto u = static_cast<unsigned char>(c);
        if (c == '<') {
            out += "&lt;";
        } else if (c == '>') {
            out += "&gt;";
        } else if (c == '&') {
            out += "&amp;";
        } else if (u < 0x20 || u == 0x7f) {
            out += "\xEF\xBF\xBD";
        } else if (c == '\\' || c == '`' || c == '*' || c == '|' || c == '~' ||
                   (c == '_' && !(word(i - 1) && word(i + 1))) ||
                   (c == ']' && i + 1 < text.size() &&
                    (text[i + 1] == '(' || text[i + 1] == '[')) ||
                   (i == 0 && (c == '#' || c == '+' || c == '-' || c == '=' || c == '['))) {
            // An underscore inside a word ("base_regions") and brackets not
            // followed by a link's target ("obstacles[3]") are no markup.
            out += '\\';
            out += c;
        } else {
            out += c;
        }
    }
    return out;
}

}  // namespace modsynth::text
