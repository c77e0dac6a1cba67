#pragma once
// The discretized baseline in the report, beside modsynth's own answer:
// its design points, its arm, the path its RRT motion really traces, and
// where the true path leaves its reachable space; and a table of both
// methods' figures.
#include <string>

#include <modsynth/baseline/comparison.h>

#include "plot.h"

namespace modsynth::output::comparison {

/// SVG group id="baseline".
std::string layer(const baseline::Comparison& c, const plot::Frame& f);
/// HTML: a heading and a table, id="comparison".
std::string section(const baseline::Comparison& c);

}  // namespace modsynth::output::comparison
