#pragma once
// User text echoed in messages (names, keys, JSON strings, parser excerpts)
// may hold control characters, invalid UTF-8 or megabytes of anything: it is
// shown as printable UTF-8 with the rest escaped, and cut to a length.
#include <cstddef>
#include <string>
#include <string_view>

namespace modsynth::text {

/// `s` as printable UTF-8: valid multi-byte sequences kept, control bytes and
/// invalid bytes written as \xHH, at most `max_chars` characters (then "...").
std::string printable(std::string_view s, std::size_t max_chars = 40);

/// A number for a message: compact (at most 6 significant digits, exponent
/// form when large or tiny), never hundreds of digits.
std::string compact(double v);

}  // namespace modsynth::text
