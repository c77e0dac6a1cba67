#include <modsynth/text/format.h>

#include <cmath>

#include <array>
#include <charconv>
#include <cstdarg>
#include <cstdio>

namespace modsynth::text {

std::string format(const char* pattern, ...) {
    std::va_list args;
    va_start(args, pattern);
    std::va_list again;
    va_copy(again, args);
    const int n = std::vsnprintf(nullptr, 0, pattern, args);
    va_end(args);
    std::string out(n > 0 ? static_cast<std::size_t>(n) : 0, '\0');
    if (n > 0) std::vsnprintf(out.data(), out.size() + 1, pattern, again);
    va_end(again);
    return out;
}

void append_fixed(std::string& out, double v, int digits) {
    std::array<char, 512> buf{};
    const auto r =
        std::to_chars(buf.data(), buf.data() + buf.size(), v, std::chars_format::fixed, digits);
    if (r.ec == std::errc{})
        out.append(buf.data(), r.ptr);
    else
        out += format("%.*f", digits, v);
}

void append_general(std::string& out, double v, int digits) {
    std::array<char, 64> buf{};
    const auto r =
        std::to_chars(buf.data(), buf.data() + buf.size(), v, std::chars_format::general, digits);
    if (r.ec == std::errc{})
        out.append(buf.data(), r.ptr);
    else
        out += format("%.*g", digits, v);
}

std::string clearance_text(double margin) {
    return std::isfinite(margin) ? format("clearance margin %.4f m", margin) : "no obstacles";
}

}  // namespace modsynth::text
