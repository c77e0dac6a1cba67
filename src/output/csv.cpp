#include <modsynth/output/csv.h>

#include <cstdio>

#include <modsynth/text/format.h>

namespace modsynth::output {
namespace {

std::string header(int dof) {
    std::string h = "t";
    for (int k = 1; k <= dof; ++k) h += ",q" + std::to_string(k);
    return h + ",phase,primitive\n";
}

// Nanoradians and microseconds: finer than any actuator resolves, and
// fixed-point so that the file diffs cleanly.
std::string row(const control::Sample& s) {
    std::string r = text::format("%.6f", s.t);
    for (double q : s.q) r += text::format(",%.9f", q);
    r += s.phase == control::Phase::Trace ? ",trace," : ",transition,";
    return r + std::to_string(s.primitive) + "\n";
}

}  // namespace

std::string trajectory_csv(const synth::Solution& solution) {
    const int dof = solution.samples.empty() ? 2 : static_cast<int>(solution.samples[0].q.size());
    std::string out = header(dof);
    for (const auto& s : solution.samples) out += row(s);
    return out;
}

}  // namespace modsynth::output
