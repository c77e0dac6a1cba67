#include <modsynth/output/report.h>

#include <cmath>
#include <cstdio>
#include <string>

#include <modsynth/output/recertify.h>
#include <modsynth/task/strokes.h>
#include <modsynth/text/format.h>
#include <modsynth/text/xml.h>

#include "plot.h"
#include "report_assets.h"
#include "report_comparison.h"
#include "report_figures.h"
#include "report_layers.h"
#include "report_timing.h"

namespace modsynth::output {
namespace {

using text::xml_text;
using namespace figures;
using plot::Frame;

constexpr double kPlotWidth = 900.0;
constexpr double kPlotHeight = 720.0;

std::string point_text(const geometry::Vec2& p) {
    return "(" + text::format("%.4f", p.x()) + ", " + text::format("%.4f", p.y()) + ") m";
}

// ------------------------------------------------------------------ figures

std::string base_text(const task::Task& task, const kinematics::Robot& robot) {
    std::string s = point_text(robot.base);
    for (std::size_t i = 0; i < task.base_regions.size(); ++i) {
        if (task.base_regions[i].contains(robot.base, 1e-9)) {
            return s + ", in base_regions[" + std::to_string(i) + "]";
        }
    }
    return s;
}

std::string links_text(const kinematics::Robot& robot) {
    std::string s;
    for (double r : robot.link_lengths) s += (s.empty() ? "" : ", ") + mm(r);
    return s + " (total " + mm(robot.total_length()) + ")";
}

std::string solved_figures(const task::Task& task, const synth::Solution& s,
                           const ReportFigures& figures) {
    const auto& r = s.robot;
    std::string out = "<table id=\"figures\">\n";
    out += row("fig-status", "Status", synth::to_string(s.status));
    out += row("fig-dof", "Joints (DOF)", std::to_string(r.dof()));
    out += row("fig-links", "Link lengths", links_text(r));
    out += row("fig-base", "Base", base_text(task, r));
    out += row(
        "fig-elbow", "Elbow",
        r.elbow > 0 ? "+1 (last joint bent counter-clockwise)" : "-1 (last joint bent clockwise)");
    out += certificate_rows(s, figures, "beyond obstacle radius + link radius");
    out += row("fig-samples", "Control",
               std::to_string(s.samples.size()) + " samples over " +
                   text::format("%.2f s", s.samples.back().t - s.samples.front().t));
    out += row("stage-times", "Time per stage", stage_text(figures));
    return out + "</table>\n";
}

// -------------------------------------------------------------- explanation

const char* kind_name(geometry::PrimitiveKind k) {
    switch (k) {
        case geometry::PrimitiveKind::Line:
            return "line";
        case geometry::PrimitiveKind::Arc:
            return "arc";
        case geometry::PrimitiveKind::Circle:
            return "circle";
    }
    return "";
}

std::string describe_part(const task::Task& task, const task::TaskPart& part) {
    if (!part.field().empty()) return "";
    const auto& r = task.robot;
    switch (part.kind()) {
        case task::TaskPart::Kind::Primitive: {
            const auto j = task::primitive_index(task, part);
            if (!j) return "";
            const auto& p = task.trajectory[*j];
            return std::string(kind_name(p.kind)) + " of " +
                   text::format("%.3f m", geometry::length(p)) + " from " + point_text(p.start);
        }
        case task::TaskPart::Kind::Obstacle: {
            const int o = part.index();
            if (o >= static_cast<int>(task.obstacles.size())) return "";
            return "disc at " + point_text(task.obstacles[o].center) + ", radius " +
                   text::format("%.3f m", task.obstacles[o].radius);
        }
        case task::TaskPart::Kind::BaseRegions:
            return std::to_string(task.base_regions.size()) + " rectangle(s) for the base";
        case task::TaskPart::Kind::BaseRegion:
        case task::TaskPart::Kind::ToolAxis:
            return "";
        case task::TaskPart::Kind::Robot:
            if (part.index() >= 0) return "";
            if (part.key() == task::RobotKey::MaxLinkLength) {
                return text::format("%.3f m", r.max_link_length) +
                       (task.base_regions.empty()
                            ? std::string()
                            : "; dashed: the farthest " + std::to_string(r.dof.back()) +
                                  " such links reach from the base regions");
            }
            if (part.key() == task::RobotKey::MinLinkLength)
                return text::format("%.3f m", r.min_link_length);
            if (part.key() == task::RobotKey::LinkDiameter)
                return text::format("%.4f m", r.link_diameter);
            return "";
    }
    return "";
}

/// What the plot's proof layer shows, in words and numbers.
std::string proof_text(const synth::Solution& s) {
    const auto& e = s.explanation;
    std::string out;
    if (e.separation) {
        out +=
            "<p id=\"proof-caption\" class=\"note\">Drawn in red: the wall. Each obstacle grown by "
            "half the tube (no part of an arm enters these discs), joined through their centres; "
            "dark red: where neighbours overlap, so that no tube passes between them. The marked "
            "point of the path lies on the other side of the wall from the base.</p>\n<ul "
            "id=\"proof-list\">\n";
        for (const auto& w : e.separation->walls) {
            double least = 1e300;
            for (double o : w.overlaps) least = std::min(least, o);
            out += "<li class=\"wall-item\">base_regions[" + std::to_string(w.base_region) +
                   "]: a wall of " + std::to_string(w.cycle.size()) +
                   " obstacles; the narrowest overlap " +
                   text::format("%.1f mm", 1000.0 * (w.overlaps.empty() ? 0.0 : least)) + "</li>\n";
        }
        out += "</ul>\n";
    }
    if (e.geodesic) {
        out +=
            "<p id=\"proof-caption\" class=\"note\">Drawn in red: the shortest way through the "
            "free space from the base region to the marked point of the path, around the obstacles "
            "grown by half the tube; every arm's links would have to be at least that long.</p>\n"
            "<ul id=\"proof-list\">\n";
        for (const auto& d : e.geodesic->detours)
            out += "<li class=\"detour-item\">base_regions[" + std::to_string(d.base_region) +
                   "] to trajectory[" + std::to_string(d.primitive) + "]: at least " +
                   text::format("%.2f m", d.lower_bound) + "; the longest arm reaches " +
                   text::format("%.2f m", e.geodesic->reach) + "</li>\n";
        out += "</ul>\n";
    }
    return out;
}

std::string explanation(const task::Task& task, const synth::Solution& s) {
    return figures::explanation(
        s, "outlined in red", [&](const task::TaskPart& part) { return describe_part(task, part); },
        proof_text(s));
}

// ------------------------------------------------------------------- legend

std::string legend(const task::Task& task, const layers::Core& core) {
    std::string out = "<h2>Trajectory</h2>\n<ul class=\"legend\" id=\"legend\">\n";
    for (std::size_t j = 0; j < task.trajectory.size(); ++j) {
        const auto& p = task.trajectory[j];
        const auto part = task::TaskPart::primitive(task, static_cast<int>(j));
        out += "<li><span class=\"swatch\" style=\"background:" +
               plot::primitive_colour(static_cast<int>(j)) + "\"></span><code>" +
               task::to_string(part) + "</code> " + kind_name(p.kind) + ", " +
               text::format("%.3f m", geometry::length(p)) +
               (layers::in_core(core, part) ? " <strong>(in the core)</strong>" : "") + "</li>\n";
    }
    return out + "</ul>\n";
}

// --------------------------------------------------------------------- plot

std::string svg(const task::Task& task, const synth::Solution& s, const Frame& f,
                const baseline::Comparison* comparison, std::string* reach_caption) {
    const bool solved = s.status == synth::Status::Solved;
    const layers::Core core = solved ? layers::Core{} : s.explanation.core;
    std::string out = "<svg id=\"plot\" width=\"" + plot::n2(f.width()) + "\" height=\"" +
                      plot::n2(f.height()) + "\" viewBox=\"0 0 " + plot::n2(f.width()) + " " +
                      plot::n2(f.height()) + "\" role=\"img\">\n";
    if (solved) {
        out += layers::reachable(task, s, f, reach_caption);
        out += layers::swept(task, s, f);
    }
    if (!solved) out += layers::reach_limit(task, f, core);
    out += layers::base_regions(task, f, core);
    out +=
        layers::obstacles(task, f, solved ? s.robot.link_diameter : task.robot.link_diameter, core);
    if (!solved) out += layers::proof(task, s, f);
    out += layers::trajectory(task, f, core);
    if (solved) {
        if (task::has_strokes(task)) out += layers::travel(s, f);
        out += layers::poses(task, s, f);
        out += layers::robot(s, f);
    }
    if (comparison) out += comparison::layer(*comparison, f);
    return out + layers::scale_bar(f) + "</svg>\n";
}

std::string controls(bool comparison) {
    return "<div id=\"controls\"><button id=\"play\" type=\"button\">Play</button>"
           "<input id=\"scrub\" type=\"range\" value=\"0\" aria-label=\"time\">"
           "<span id=\"clock\"></span><select id=\"speed\" aria-label=\"speed\">"
           "<option value=\"0.5\">0.5x</option><option value=\"1\" selected>1x</option>"
           "<option value=\"2\">2x</option><option value=\"5\">5x</option></select></div>\n"
           "<div id=\"readout\"></div>\n"
           "<div id=\"toggles\">"
           "<label><input type=\"checkbox\" data-layer=\"reachable\" checked> reachable "
           "space</label>"
           "<label><input type=\"checkbox\" data-layer=\"swept\" checked> swept regions</label>"
           "<label><input type=\"checkbox\" id=\"only-current\"> only the current "
           "primitive's</label>"
           "<label><input type=\"checkbox\" data-layer=\"poses\" checked> poses</label>"
           "<label><input type=\"checkbox\" data-layer=\"trail\" checked> trail</label>" +
           std::string(comparison
                           ? "<label><input type=\"checkbox\" data-layer=\"baseline\" checked> "
                             "discretized baseline</label>"
                           : "") +
           "</div>\n";
}

/// The motion for the script: numbers only, so it can sit in a script element.
std::string motion_data(const task::Task& task, const synth::Solution& s, const Frame& f) {
    // One number per sample and joint: formatted without printf's cost.
    const auto list = [](const auto& values, char style, int digits) {
        std::string out = "[";
        for (std::size_t i = 0; i < values.size(); ++i) {
            if (i) out += ',';
            if (style == 'f')
                text::append_fixed(out, values[i], digits);
            else
                text::append_general(out, values[i], digits);
        }
        return out + "]";
    };
    std::vector<double> t, q, ph, pr;
    for (const auto& x : s.samples) {
        t.push_back(x.t);
        q.insert(q.end(), x.q.begin(), x.q.end());
        ph.push_back(x.phase == control::Phase::Transition ? 1.0
                     : x.phase == control::Phase::Travel   ? 2.0
                                                           : 0.0);
        pr.push_back(control::primitive_index(task, x));
    }
    // The parts' names, for the readout, only where they are not
    // "trajectory[j]" (the script's default).
    std::string names;
    if (task::has_strokes(task)) {
        names = ",\"nm\":[";
        for (int j = 0; j < static_cast<int>(task.trajectory.size()); ++j)
            names += (j ? ",\"" : "\"") + task::part_name(task, j) + "\"";
        names += "]";
    }
    return "<script type=\"application/json\" id=\"motion-data\">{\"base\":[" +
           text::format("%.9g", s.robot.base.x()) + "," + text::format("%.9g", s.robot.base.y()) +
           "],\"L\":" + list(s.robot.link_lengths, 'g', 9) +
           ",\"f\":{\"x0\":" + text::format("%.9g", f.min.x()) +
           ",\"y1\":" + text::format("%.9g", f.max.y()) +
           ",\"s\":" + text::format("%.9g", f.scale) + ",\"p\":" + text::format("%.9g", f.pad) +
           "},\"t\":" + list(t, 'f', 6) + ",\"q\":" + list(q, 'f', 6) +
           ",\"ph\":" + list(ph, 'f', 0) + ",\"pr\":" + list(pr, 'f', 0) + names + "}</script>\n";
}

std::string header(const task::Task& task, const synth::Solution& s) {
    const std::string status = synth::to_string(s.status);
    const std::string name = task.name.empty() ? "task" : task.name;
    return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta "
           "charset=\"utf-8\">\n<title>modsynth: " +
           xml_text(name) + "</title>\n<style>" + assets::kStyle +
           "</style>\n</head>\n<body>\n"
           "<header><h1>" +
           xml_text(name) + " <span class=\"status " + status + "\">" + status +
           "</span></h1>\n<p class=\"note\">" +
           (task::has_strokes(task) ? std::to_string(task::stroke_count(task)) + " strokes, "
                                    : std::string()) +
           std::to_string(task.trajectory.size()) + " primitives, " +
           std::to_string(task.obstacles.size()) + " obstacles, " +
           std::to_string(task.base_regions.size()) +
           " base regions. Task plane in metres, "
           "x to the right, y up.</p></header>\n";
}

}  // namespace

std::string html_report(const task::Task& task, const synth::Solution& solution,
                        const ReportFigures& figures) {
    const bool solved = solution.status == synth::Status::Solved;
    const Frame frame = plot::fit_frame(task, solution, kPlotWidth, kPlotHeight);
    std::string caption;
    const std::string plot_svg = svg(task, solution, frame, figures.comparison, &caption);
    std::string out = header(task, solution) + "<main>\n<section id=\"plot-section\">\n" + plot_svg;
    if (solved) out += controls(figures.comparison != nullptr);
    out += "</section>\n<aside>\n";
    if (!solved) out += explanation(task, solution);
    out += "<h2>Figures</h2>\n";
    out += solved ? solved_figures(task, solution, figures) : failed_figures(solution, figures);
    if (figures.comparison) out += comparison::section(*figures.comparison);
    out += legend(task, solved ? layers::Core{} : solution.explanation.core);
    if (solved) {
        out += "<p class=\"note\" id=\"reach-caption\">" + xml_text(caption) +
               " Coloured areas: the region the arm sweeps while tracing each primitive "
               "(dashed: transitions). Grey outlines: the arm at the start of each primitive. "
               "Dotted circles: how close a link's axis may come to each obstacle.</p>\n";
    }
    out += "</aside>\n</main>\n";
    out += timing::section(task, solution);
    if (solved) {
        out += motion_data(task, solution, frame);
        out += std::string("<script>") + assets::kScript + "</script>\n";
    }
    return out + "</body>\n</html>\n";
}

}  // namespace modsynth::output
