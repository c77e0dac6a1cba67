#pragma once
// printf-style formatting into a std::string, for messages, reports and
// files (GCC 12's libstdc++ has no std::format). The format attribute lets
// the compiler check every call's arguments against its pattern.
#include <string>

namespace modsynth::text {

std::string format(const char* pattern, ...) __attribute__((format(printf, 1, 2)));

/// `v` with `digits` decimals appended to `out`, the text of
/// format("%.*f", digits, v) without printf's cost: reports write one
/// number per sample and joint.
void append_fixed(std::string& out, double v, int digits);

/// A certified clearance as a person reads it: "clearance margin 0.0023 m",
/// or "no obstacles" when there was nothing to keep clear of (an infinite
/// margin).
std::string clearance_text(double margin);

/// The text of format("%.9g", v), appended to `out`.
void append_general(std::string& out, double v, int digits);

}  // namespace modsynth::text
