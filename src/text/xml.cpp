#include <modsynth/text/xml.h>

#include "utf8.h"

namespace modsynth::text {
namespace {

constexpr const char* kReplacement = "\xEF\xBF\xBD";

/// Appends the characters XML allows as they are, and U+FFFD for the rest.
void append_allowed(std::string& out, std::string_view text, bool references) {
    for (std::size_t i = 0; i < text.size();) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c >= 0x80) {
            const std::size_t n = utf8_length(text, i);
            if (n == 0) {
                out += kReplacement;
                ++i;
            } else {
                out.append(text.substr(i, n));
                i += n;
            }
            continue;
        }
        ++i;
        if ((c < 0x20 && c != '\t' && c != '\n' && c != '\r') || c == 0x7f) {
            out += kReplacement;
            continue;
        }
        if (const char* ref = references ? markup_reference(static_cast<char>(c)) : nullptr) {
            out += ref;
            continue;
        }
        out += static_cast<char>(c);
    }
}

}  // namespace

std::string xml_text(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    append_allowed(out, text, true);
    return out;
}

std::string xml_comment(std::string_view text) {
    std::string allowed;
    append_allowed(allowed, text, false);
    std::string out;
    out.reserve(allowed.size());
    for (const char c : allowed) {
        if (c == '-' && !out.empty() && out.back() == '-') out += ' ';
        out += c;
    }
    if (!out.empty() && out.back() == '-') out += ' ';
    return out;
}

}  // namespace modsynth::text
