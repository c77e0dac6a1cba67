#pragma once
// printf-style formatting into a std::string, for messages, reports and
// files (GCC 12's libstdc++ has no std::format). The format attribute lets
// the compiler check every call's arguments against its pattern.
#include <string>

namespace modsynth::text {

std::string format(const char* pattern, ...) __attribute__((format(printf, 1, 2)));

}  // namespace modsynth::text
