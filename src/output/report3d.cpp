#include <modsynth/output/report3d.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <modsynth/control/spatial_samples.h>
#include <modsynth/kinematics/dh_chain.h>
#include <modsynth/output/recertify.h>
#include <modsynth/task/part.h>
#include <modsynth/task/spatial_strokes.h>
#include <modsynth/text/format.h>
#include <modsynth/text/xml.h>

#include "plot.h"
#include "report_assets.h"
#include "report_figures.h"
#include "report_timing.h"

namespace modsynth::output {

namespace assets {
/// The 3-D view (web/report3d/viewer.js with three.js), bundled and
/// embedded at build time (cmake/embed_script.cmake).
extern const std::string_view kViewerScript;
}  // namespace assets

namespace {

using geometry::Vec3;
using text::xml_text;
using namespace figures;

std::string deg(double radians) {
    return text::format("%.1f", radians * 180.0 / geometry::kPi) + "&deg;";
}
std::string point_text(const Vec3& p) {
    return "(" + text::format("%.4f", p.x()) + ", " + text::format("%.4f", p.y()) + ", " +
           text::format("%.4f", p.z()) + ") m";
}

// -------------------------------------------------------------- scene data

std::string num(double v) { return text::format("%.6f", v); }
std::string vec(const Vec3& p) {
    return "[" + num(p.x()) + "," + num(p.y()) + "," + num(p.z()) + "]";
}

bool in_core(const synth::Solution& s, const task::TaskPart& part) {
    return s.status != synth::Status::Solved &&
           std::find(s.explanation.core.begin(), s.explanation.core.end(), part) !=
               s.explanation.core.end();
}

/// Axis-aligned bounds of everything the view shows.
struct Bounds {
    Vec3 min = Vec3::Constant(std::numeric_limits<double>::infinity());
    Vec3 max = Vec3::Constant(-std::numeric_limits<double>::infinity());
    void add(const Vec3& p, double r = 0.0) {
        min = min.cwiseMin(p - Vec3::Constant(r));
        max = max.cwiseMax(p + Vec3::Constant(r));
    }
};

/// Points along a primitive every 5 mm, and closer where it turns tightly.
std::vector<Vec3> polyline(const geometry::Primitive3& p) {
    const double length = geometry::length(p);
    const double by_length = length / 0.005;
    const double by_turn = length * geometry::max_curvature(p) * 16.0;
    const int n =
        static_cast<int>(std::clamp(std::ceil(std::max(by_length, by_turn)), 2.0, 4000.0));
    std::vector<Vec3> out;
    for (int i = 0; i <= n; ++i) out.push_back(geometry::point_at(p, length * i / n));
    return out;
}

std::string task_data(const task::SpatialTask& task, const synth::Solution& s, Bounds& b) {
    std::string prims;
    for (std::size_t j = 0; j < task.trajectory.size(); ++j) {
        std::string pts;
        for (const Vec3& p : polyline(task.trajectory[j])) {
            pts += (pts.empty() ? "" : ",") + vec(p);
            b.add(p);
        }
        prims += std::string(j ? "," : "") + "{\"i\":" + std::to_string(j) + ",\"col\":\"" +
                 plot::primitive_colour(static_cast<int>(j)) + "\",\"core\":" +
                 (in_core(s, task::primitive_part(task, static_cast<int>(j))) ? "true" : "false") +
                 ",\"pts\":[" + pts + "]}";
    }
    std::string obstacles;
    for (std::size_t i = 0; i < task.obstacles.size(); ++i) {
        const std::string core =
            in_core(s, task::TaskPart::obstacle(static_cast<int>(i))) ? "true" : "false";
        std::string o = std::visit(
            [&](const auto& x) -> std::string {
                using T = std::decay_t<decltype(x)>;
                if constexpr (std::is_same_v<T, geometry::Sphere>) {
                    b.add(x.center, x.radius);
                    return "{\"type\":\"sphere\",\"c\":" + vec(x.center) +
                           ",\"r\":" + num(x.radius);
                } else if constexpr (std::is_same_v<T, geometry::Capsule>) {
                    b.add(x.a, x.radius);
                    b.add(x.b, x.radius);
                    return "{\"type\":\"capsule\",\"a\":" + vec(x.a) + ",\"b\":" + vec(x.b) +
                           ",\"r\":" + num(x.radius);
                } else {
                    b.add(x.min);
                    b.add(x.max);
                    return "{\"type\":\"box\",\"min\":" + vec(x.min) + ",\"max\":" + vec(x.max);
                }
            },
            task.obstacles[i]);
        obstacles += std::string(i ? "," : "") + o + ",\"core\":" + core + "}";
    }
    std::string regions;
    const std::string region_core = in_core(s, task::TaskPart::base_regions()) ? "true" : "false";
    for (std::size_t i = 0; i < task.base_regions.size(); ++i) {
        const auto& r = task.base_regions[i];
        b.add(r.min);
        b.add(r.max);
        regions += std::string(i ? "," : "") + "{\"min\":" + vec(r.min) + ",\"max\":" + vec(r.max) +
                   ",\"core\":" + region_core + "}";
    }
    return "\"task\":{\"prims\":[" + prims + "],\"obstacles\":[" + obstacles + "],\"regions\":[" +
           regions + "]}";
}

std::string list(const std::vector<double>& values, const char* format) {
    std::string out = "[";
    for (std::size_t i = 0; i < values.size(); ++i)
        out += (i ? "," : "") + text::format(format, values[i]);
    return out + "]";
}

std::string motion_data(const task::SpatialTask& task, const synth::Solution& s, Bounds& b) {
    const kinematics::DhChain& chain = *s.dh_robot;
    const auto& spec = task.robot;
    std::string rows;
    for (const auto& r : chain.rows)
        rows += std::string(rows.empty() ? "" : ",") + "[" + num(r.a) + "," +
                text::format("%.9f", r.alpha) + "," + num(r.d) + "]";
    std::vector<double> t, q, ph, pr;
    for (const auto& x : s.samples) {
        t.push_back(x.t);
        q.insert(q.end(), x.q.begin(), x.q.end());
        ph.push_back(x.phase == control::Phase::Transition ? 1.0
                     : x.phase == control::Phase::Travel   ? 2.0
                                                           : 0.0);
        pr.push_back(control::primitive_index(task, x));
    }
    // Every pose the arm takes, so that the view frames it all.
    const std::size_t stride = std::max<std::size_t>(1, s.samples.size() / 200);
    for (std::size_t i = 0; i < s.samples.size(); i += stride)
        for (const auto& f : kinematics::frames(chain, s.samples[i].q))
            b.add(f.translation(), std::max(spec.module_length, chain.link_diameter) / 2.0);
    return ",\"robot\":{\"base\":" + vec(chain.base) + ",\"dh\":[" + rows +
           "],\"D\":" + num(chain.link_diameter) + ",\"tool\":" + num(spec.tool_length) +
           ",\"mod\":[" + num(spec.module_length) + "," + num(spec.module_width) + "," +
           num(spec.module_height) + "]},\"motion\":{\"t\":" + list(t, "%.6f") +
           ",\"q\":" + list(q, "%.6f") + ",\"ph\":" + list(ph, "%.0f") +
           ",\"pr\":" + list(pr, "%.0f") + "}";
}

/// A wall's witness (formats.md "explanation.enclosure"): each run of
/// enclosed cells as a box [min, max].
std::string enclosure_data(const prove::EnclosureWitness& w) {
    std::string walls;
    for (const prove::Enclosure& e : w.walls) {
        std::string runs;
        const auto at = [&](int i, int j, int k) -> Vec3 {
            return e.grid.origin + e.grid.cell * Vec3(i, j, k);
        };
        for (const prove::CellRun& r : e.cells) {
            const Vec3 lo = at(r.i0, r.j, r.k), hi = at(r.i1 + 1, r.j + 1, r.k + 1);
            runs += std::string(runs.empty() ? "" : ",") + "[" + num(lo.x()) + "," + num(lo.y()) +
                    "," + num(lo.z()) + "," + num(hi.x()) + "," + num(hi.y()) + "," + num(hi.z()) +
                    "]";
        }
        std::string ids;
        for (int i : e.obstacles) ids += (ids.empty() ? "" : ",") + std::to_string(i);
        walls += std::string(walls.empty() ? "" : ",") + "{\"inside\":\"" +
                 (e.base_inside ? "base_region" : "point") +
                 "\",\"base_region\":" + std::to_string(e.base_region) +
                 ",\"point\":" + vec(e.point) + ",\"obstacles\":[" + ids + "],\"runs\":[" + runs +
                 "]}";
    }
    return ",\"enclosure\":[" + walls + "]";
}

std::string scene_data(const task::SpatialTask& task, const synth::Solution& s) {
    Bounds b;
    std::string out = "{" + task_data(task, s, b);
    if (s.status != synth::Status::Solved && s.explanation.enclosure)
        out += enclosure_data(*s.explanation.enclosure);
    const bool solved = s.status == synth::Status::Solved && s.dh_robot && !s.samples.empty();
    out += solved ? motion_data(task, s, b) : ",\"robot\":null,\"motion\":null";
    std::string names;
    for (int j = 0; j < static_cast<int>(task.trajectory.size()); ++j)
        names += (j ? ",\"" : "\"") + task::part_name(task, j) + "\"";
    if (!std::isfinite(b.min.x())) b.add(Vec3::Zero());
    out += ",\"names\":[" + names + "],\"bounds\":{\"min\":" + vec(b.min) +
           ",\"max\":" + vec(b.max) + "}}";
    return "<script type=\"application/json\" id=\"scene-data\">" + out + "</script>\n";
}

// ------------------------------------------------------------------ figures

std::string base_text(const task::SpatialTask& task, const Vec3& base) {
    for (std::size_t i = 0; i < task.base_regions.size(); ++i)
        if (task.base_regions[i].contains(base, 1e-9))
            return point_text(base) + ", in base_regions[" + std::to_string(i) + "]";
    return point_text(base);
}

std::string dh_text(const kinematics::DhChain& chain) {
    std::string s =
        "<table class=\"dh\"><tr><th>joint</th><th>a</th><th>&alpha;</th><th>d</th></tr>";
    for (int k = 0; k < chain.dof(); ++k) {
        const auto& r = chain.rows[static_cast<std::size_t>(k)];
        s += "<tr><td>" + std::to_string(k + 1) + "</td><td>" + mm(r.a) + "</td><td>" +
             deg(r.alpha) + "</td><td>" + mm(r.d) + "</td></tr>";
    }
    return s + "</table>";
}

std::string solved_figures(const task::SpatialTask& task, const synth::Solution& s,
                           const ReportFigures& figures) {
    const kinematics::DhChain& chain = *s.dh_robot;
    std::string out = "<table id=\"figures\">\n";
    out += row("fig-status", "Status", synth::to_string(s.status));
    out += row("fig-dof", "Joints (DOF)", std::to_string(chain.dof()));
    out += row("fig-dh", "DH rows", dh_text(chain));
    out += row("fig-base", "Base", base_text(task, chain.base));
    out += row("fig-length", "Chain length", mm(chain.total_length()) + " (sum of a and |d|)");
    if (task.robot.tool_length > 0.0) out += row("fig-tool", "Tool", mm(task.robot.tool_length));
    out += certificate_rows(s, figures, "beyond obstacle + half the link diameter");
    if (s.modules)
        out += row("fig-modules", "Modules",
                   (s.modules->checked && !s.modules->carried() ? "<strong>overloaded</strong>: "
                                                                : std::string()) +
                       xml_text(s.modules->message));
    out += row("fig-samples", "Motion",
               std::to_string(s.samples.size()) + " samples over " +
                   text::format("%.2f s", s.samples.back().t - s.samples.front().t));
    out += row("stage-times", "Time per stage", stage_text(figures));
    return out + "</table>\n";
}

std::string explanation(const synth::Solution& s) {
    return figures::explanation(
        s, "red in the view", [](const task::TaskPart&) { return std::string(); }, "");
}

std::string legend(const task::SpatialTask& task) {
    std::string out = "<h2>Trajectory</h2>\n<ul class=\"legend\" id=\"legend\">\n";
    for (std::size_t j = 0; j < task.trajectory.size(); ++j) {
        const auto& p = task.trajectory[j];
        out += "<li><span class=\"swatch\" style=\"background:" +
               plot::primitive_colour(static_cast<int>(j)) + "\"></span><code>" +
               task::part_name(task, static_cast<int>(j)) + "</code> " + geometry::type_name(p) +
               ", " + text::format("%.3f m", geometry::length(p)) + "</li>\n";
    }
    return out + "</ul>\n";
}

std::string controls() {
    return "<div id=\"controls\"><button id=\"play\" type=\"button\">Play</button>"
           "<input id=\"scrub\" type=\"range\" value=\"0\" aria-label=\"time\">"
           "<span id=\"clock\"></span><select id=\"speed\" aria-label=\"speed\">"
           "<option value=\"0.5\">0.5x</option><option value=\"1\" selected>1x</option>"
           "<option value=\"2\">2x</option><option value=\"5\">5x</option></select></div>\n"
           "<div id=\"readout\"></div>\n"
           "<div id=\"toggles\"><label><input type=\"checkbox\" id=\"show-modules\" checked> "
           "modules</label><label><input type=\"checkbox\" id=\"show-trail\" checked> "
           "trail</label></div>\n";
}

constexpr const char* kStyle3d = R"CSS(
#view { width: 900px; height: 640px; border: 1px solid #ccc; background: #fff; }
#view canvas { display: block; }
#view.no-webgl { display: flex; align-items: center; justify-content: center; padding: 24px; box-sizing: border-box; color: #8a1414; }
table.dh td, table.dh th { padding: 0 6px; border: none; }
)CSS";

/// A script element's text ends at the first "</script": the bundle must
/// never hold one (a JavaScript string may write it as "<\/script").
std::string inline_script(std::string_view code) {
    std::string out(code);
    for (std::size_t at = out.find("</script"); at != std::string::npos;
         at = out.find("</script", at + 2))
        out.replace(at, 2, "<\\/");
    return out;
}

/// The timing charts are the plane's: they read only the joint limits of
/// the task.
std::string timing_section(const task::SpatialTask& task, const synth::Solution& s) {
    task::Task limits;
    limits.robot.joint_limits = task.robot.joint_limits;
    return timing::section(limits, s);
}

}  // namespace

std::string html_report(const task::SpatialTask& task, const synth::Solution& solution,
                        const ReportFigures& figures) {
    const bool solved =
        solution.status == synth::Status::Solved && solution.dh_robot && !solution.samples.empty();
    const std::string status = synth::to_string(solution.status);
    const std::string name = task.name.empty() ? "task" : task.name;
    std::string out =
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>modsynth: " +
        xml_text(name) + "</title>\n<style>" + assets::kStyle + kStyle3d +
        "</style>\n</head>\n<body>\n<header><h1>" + xml_text(name) + " <span class=\"status " +
        status + "\">" + status + "</span></h1>\n<p class=\"note\">" +
        (task::has_strokes(task) ? std::to_string(task::stroke_count(task)) + " strokes, "
                                 : std::string()) +
        std::to_string(task.trajectory.size()) + " primitives, " +
        std::to_string(task.obstacles.size()) + " obstacles, " +
        std::to_string(task.base_regions.size()) +
        " base regions. Task frame in metres, z up. Drag to orbit, right-drag (or Shift-drag) to "
        "pan, wheel to zoom.</p></header>\n";
    out += "<main>\n<section id=\"plot-section\">\n<div id=\"view\"></div>\n";
    if (solved) out += controls();
    out += "</section>\n<aside>\n";
    if (!solved) out += explanation(solution);
    out += "<h2>Figures</h2>\n";
    out += solved ? solved_figures(task, solution, figures) : failed_figures(solution, figures);
    out += legend(task);
    out +=
        "<p class=\"note\" id=\"view-caption\">Red: obstacles (translucent); dashed boxes: "
        "base regions; the grid is the task's xy-plane (z = 0, or lower when the scene is), "
        "with the task frame's axes (x red, y green, z blue) at its origin." +
        std::string(!solved && solution.explanation.enclosure
                        ? " The proof's wall: its obstacles red and outlined, the free space "
                          "it encloses (round the base region or round a path point) green, "
                          "and a black ring at the path point it keeps apart."
                        : "") +
        std::string(solved ? " The arm: the chain's segments as capsules of the link "
                             "diameter (the tool dark), module housings red at the joints; "
                             "black: the end-effector's trail."
                           : "") +
        "</p>\n</aside>\n</main>\n";
    if (solved) out += timing_section(task, solution);
    out += scene_data(task, solution);
    out += "<script>" + inline_script(assets::kViewerScript) + "</script>\n";
    return out + "</body>\n</html>\n";
}

}  // namespace modsynth::output
