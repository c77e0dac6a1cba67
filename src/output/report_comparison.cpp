#include "report_comparison.h"

#include <cmath>
#include <cstdio>

#include <modsynth/kinematics/kinematics.h>
#include <modsynth/text/format.h>
#include <modsynth/text/xml.h>

namespace modsynth::output::comparison {
namespace {

using geometry::Vec2;
using plot::n2;

std::string dot(const plot::Frame& f, const Vec2& p, const char* cls, double r) {
    const Vec2 c = f.px(p);
    return std::string("<circle class=\"") + cls + "\" cx=\"" + n2(c.x()) + "\" cy=\"" + n2(c.y()) +
           "\" r=\"" + n2(r) + "\"/>";
}

std::string cell(const std::string& text) { return "<td>" + text + "</td>"; }

std::string row(const std::string& name, const std::string& ours, const std::string& theirs) {
    return "<tr><th>" + name + "</th>" + cell(ours) + cell(theirs) + "</tr>\n";
}

std::string length_text(const kinematics::Robot& r) {
    std::string s;
    for (double l : r.link_lengths) s += (s.empty() ? "" : ", ") + text::format("%.1f", 1e3 * l);
    return s + " mm (total " + text::format("%.1f", 1e3 * r.total_length()) + " mm)";
}

std::string reach_text(const baseline::Fidelity& f) {
    return f.whole_path_reachable()
               ? std::string("yes")
               : "<strong>no</strong>: " + text::format("%.1f mm", 1e3 * f.outside_length) +
                     " of the path outside";
}

}  // namespace

std::string layer(const baseline::Comparison& c, const plot::Frame& f) {
    const baseline::BaselineResult& b = c.baseline;
    std::string out = "<g id=\"baseline\">\n";
    if (b.design.found) {
        const kinematics::Robot& r = b.design.robot;
        const auto joints = kinematics::forward(r.base, r.link_lengths, b.design.poses.front());
        std::string arm;
        for (const Vec2& p : joints) arm += (arm.empty() ? "" : " ") + plot::pt(f, p);
        out += "<polyline class=\"baseline-arm\" points=\"" + arm + "\" stroke-width=\"" +
               n2(r.link_diameter * f.scale) +
               "\"><title>the discretized design at its first point</title></polyline>\n";
        out += "<path class=\"baseline-trail\" d=\"" + plot::path_data(f, b.fidelity.trail, false) +
               "\"><title>the path the discretized design's RRT motion traces</title></path>\n";
        for (const Vec2& p : b.fidelity.outside_points)
            out += dot(f, p, "baseline-outside", 2.5) + "\n";
    }
    for (const auto& p : b.points) out += dot(f, p.point, "baseline-point", 3.0) + "\n";
    return out + "</g>\n";
}

std::string section(const baseline::Comparison& c) {
    const synth::Solution& s = c.solution;
    const baseline::BaselineResult& b = c.baseline;
    const bool ours = s.status == synth::Status::Solved;
    const bool theirs = b.design.found;
    const baseline::Fidelity* f = c.fidelity ? &*c.fidelity : nullptr;
    std::string out = "<h2>Against the discretized baseline</h2>\n<table id=\"comparison\">\n";
    out += "<tr><th></th><th>modsynth</th><th>discretized, " + std::to_string(b.points.size()) +
           " points + RRT</th></tr>\n";
    out += row("Status", synth::to_string(s.status), baseline::to_string(b.status));
    out += row("Time", text::format("%.3f s", c.solve_seconds), text::format("%.3f s", b.seconds));
    out +=
        row("Links", ours ? length_text(s.robot) : "-", theirs ? length_text(b.design.robot) : "-");
    out += row("Max. EE deviation", f ? text::format("%.3f mm", 1e3 * f->max_deviation) : "-",
               theirs ? text::format("%.3f mm", 1e3 * b.fidelity.max_deviation) : "-");
    out += row("Path to EE trail", f ? text::format("%.3f mm", 1e3 * f->coverage_gap) : "-",
               theirs ? text::format("%.3f mm", 1e3 * b.fidelity.coverage_gap) : "-");
    out += row("Whole path reachable", f ? reach_text(*f) : "-",
               theirs ? reach_text(b.fidelity) : "-");
    out +=
        "</table>\n<p class=\"note\">Baseline in the drawing: its design points (hollow), its arm "
        "at the "
        "first point (dashed), the path its motion really traces (dashed black) and the points of "
        "the "
        "task's path outside its obstacle-free reachable space (red). Deviations are measured on "
        "both "
        "motions the same way, by dense sampling; modsynth's is also certified.</p>\n";
    if (!b.message.empty())
        out += "<p class=\"note\">Baseline: " + text::xml_text(b.message) + "</p>\n";
    return out;
}

}  // namespace modsynth::output::comparison
