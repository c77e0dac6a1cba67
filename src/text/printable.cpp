#include <modsynth/text/printable.h>

#include <cmath>

#include <modsynth/text/format.h>

#include "utf8.h"

namespace modsynth::text {

std::string printable(std::string_view s, std::size_t max_chars) {
    std::string out;
    std::size_t chars = 0;
    for (std::size_t i = 0; i < s.size(); ++chars) {
        if (chars == max_chars) return out + "...";
        const auto c = static_cast<unsigned char>(s[i]);
        if (c >= 0x20 && c < 0x7F) {
            out += static_cast<char>(c);
            ++i;
        } else if (const std::size_t n = c >= 0x80 ? utf8_length(s, i) : 0; n > 0) {
            out.append(s.substr(i, n));
            i += n;
        } else {
            out += format("\\x%02X", c);
            ++i;
        }
    }
    return out;
}

std::string compact(double v) {
    if (std::isnan(v)) return "NaN";
    if (std::isinf(v)) return v > 0 ? "infinity" : "-infinity";
    return format("%.6g", v);
}

}  // namespace modsynth::text
