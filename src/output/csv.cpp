#include <modsynth/output/csv.h>

#include <algorithm>
#include <cstdio>

#include <modsynth/text/format.h>

namespace modsynth::output {
namespace {

// A `stroke` column only for motions of several strokes, so that one-stroke
// files keep their columns.
std::string header(int dof, bool strokes) {
    std::string h = "t";
    for (int k = 1; k <= dof; ++k) h += ",q" + std::to_string(k);
    return h + ",phase,primitive" + (strokes ? ",stroke\n" : "\n");
}

// Nanoradians and microseconds: finer than any actuator resolves, and
// fixed-point so that the file diffs cleanly.
std::string row(const control::Sample& s, bool strokes) {
    std::string r = text::format("%.6f", s.t);
    for (double q : s.q) r += text::format(",%.9f", q);
    r += s.phase == control::Phase::Trace        ? ",trace,"
         : s.phase == control::Phase::Transition ? ",transition,"
                                                 : ",travel,";
    r += std::to_string(s.primitive);
    return r + (strokes ? "," + std::to_string(s.stroke) + "\n" : "\n");
}

}  // namespace

std::string trajectory_csv(const synth::Solution& solution) {
    const int dof = solution.samples.empty() ? 2 : static_cast<int>(solution.samples[0].q.size());
    const bool strokes = std::any_of(solution.samples.begin(), solution.samples.end(),
                                     [](const control::Sample& s) { return s.stroke != 0; });
    std::string out = header(dof, strokes);
    for (const auto& s : solution.samples) out += row(s, strokes);
    return out;
}

}  // namespace modsynth::output
