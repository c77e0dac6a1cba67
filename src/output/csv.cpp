#include <modsynth/output/csv.h>

#include <algorithm>
#include <cstdio>

#include <modsynth/text/format.h>

namespace modsynth::output {
namespace {

bool timed(const synth::Solution& solution) {
    return !solution.samples.empty() && !solution.samples[0].qd.empty() &&
           !solution.samples[0].qdd.empty();
}

// Velocities and accelerations come after the columns a position-only
// reader already knows, so that their positions stay; a `stroke` column
// only for motions of several strokes, so that one-stroke files keep theirs.
std::string header(int dof, bool with_rates, bool strokes) {
    std::string h = "t";
    for (int k = 1; k <= dof; ++k) h += ",q" + std::to_string(k);
    h += ",phase,primitive";
    if (with_rates) {
        for (int k = 1; k <= dof; ++k) h += ",qd" + std::to_string(k);
        for (int k = 1; k <= dof; ++k) h += ",qdd" + std::to_string(k);
    }
    return h + (strokes ? ",stroke\n" : "\n");
}

// Nanoradians and microseconds: finer than any actuator resolves, and
// fixed-point so that the file diffs cleanly.
std::string row(const control::Sample& s, bool with_rates, bool strokes) {
    std::string r = text::format("%.6f", s.t);
    for (double q : s.q) r += text::format(",%.9f", q);
    r += s.phase == control::Phase::Trace        ? ",trace,"
         : s.phase == control::Phase::Transition ? ",transition,"
                                                 : ",travel,";
    r += std::to_string(s.primitive);
    if (with_rates) {
        for (double v : s.qd) r += text::format(",%.9f", v);
        for (double a : s.qdd) r += text::format(",%.9f", a);
    }
    return r + (strokes ? "," + std::to_string(s.stroke) + "\n" : "\n");
}

}  // namespace

std::string trajectory_csv(const synth::Solution& solution) {
    const int dof = solution.samples.empty() ? 2 : static_cast<int>(solution.samples[0].q.size());
    const bool strokes = std::any_of(solution.samples.begin(), solution.samples.end(),
                                     [](const control::Sample& s) { return s.stroke != 0; });
    const bool with_rates = timed(solution);
    std::string out = header(dof, with_rates, strokes);
    for (const auto& s : solution.samples) out += row(s, with_rates, strokes);
    return out;
}

}  // namespace modsynth::output
