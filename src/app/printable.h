#pragma once
// Request bytes echoed back in a reply (a path, a query value, a parse
// error quoting the body) may be anything: JSON can carry only valid UTF-8,
// and a message is read by people, so whatever is neither gets escaped.
#include <string>
#include <string_view>

namespace modsynth::app {

/// `text` with every byte that is not part of a valid UTF-8 sequence, and
/// every control character, written as \xHH; the rest unchanged.
std::string printable(std::string_view text);

}  // namespace modsynth::app
