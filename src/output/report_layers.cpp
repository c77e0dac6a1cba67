#include "report_layers.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <modsynth/geometry/polygon.h>
#include <modsynth/kinematics/chain_layout.h>
#include <modsynth/kinematics/kinematics.h>
#include <modsynth/kinematics/reachable_space.h>
#include <modsynth/task/strokes.h>

namespace modsynth::output::layers {
namespace {

using geometry::Vec2;
using kinematics::distal_pair;
using kinematics::DistalPair;
using kinematics::reachable_space;
using kinematics::ReachGrid;
using plot::n2;
using plot::pt;

/// Pixels per reachable-space cell: fine enough to show the shape, coarse
/// enough to keep the file small.
constexpr double kReachCellPixels = 3.0;
/// Joint change (rad) between the poses that outline a swept region; the
/// outline then strays far less than a pixel from the true one.
constexpr double kSweptStep = 0.03;

std::string text_format_overlap(int i, int j, double depth) {
    char buf[128];
    std::snprintf(buf, sizeof buf,
                  "the no-go discs of obstacles[%d] and obstacles[%d] overlap by %.1f mm: no tube "
                  "passes between",
                  i, j, depth * 1000.0);
    return buf;
}

std::string length_label(double bound, double reach) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "at least %.2f m; reach %.2f m", bound, reach);
    return buf;
}

int primitive_count(const task::Task& task) { return static_cast<int>(task.trajectory.size()); }

/// A sample's primitive as an index into task.trajectory, -1 when the
/// sample names none of the task's.
int global_primitive(const task::Task& task, const control::Sample& x) {
    if (x.stroke < 0 || x.stroke >= task::stroke_count(task) || x.primitive < 0) return -1;
    const int j = control::primitive_index(task, x);
    return j <= task::stroke_last(task, x.stroke) ? j : -1;
}

std::string part_attributes(const Core& core, const task::TaskPart& part, const char* cls) {
    return std::string(" class=\"") + cls + (in_core(core, part) ? " core" : "") +
           "\" data-part=\"" + task::to_string(part) + "\"";
}

/// Horizontal runs of reachable cells as one path.
std::string grid_path(const ReachGrid& g, const plot::Frame& f) {
    std::string d;
    const double h = g.cell * f.scale;
    for (int j = 0; j < g.ny; ++j) {
        for (int i = 0; i < g.nx;) {
            if (!g.at(i, j)) {
                ++i;
                continue;
            }
            int end = i;
            while (end < g.nx && g.at(end, j)) ++end;
            const Vec2 top_left = f.px(g.min + g.cell * Vec2(i, j + 1));
            const double w = (end - i) * h;
            d += "M" + n2(top_left.x()) + "," + n2(top_left.y()) + "h" + n2(w) + "v" + n2(h) + "h" +
                 n2(-w) + "Z";
            i = end;
        }
    }
    return d;
}

/// The first sample of each primitive's trace: where link 1 of a 3-joint
/// arm stands while the primitive is traced, and the pose drawn for it.
std::vector<int> primitive_starts(const task::Task& task, const synth::Solution& s) {
    std::vector<int> first(static_cast<std::size_t>(primitive_count(task)), -1);
    for (int i = 0; i < static_cast<int>(s.samples.size()); ++i) {
        const auto& x = s.samples[i];
        const int j = global_primitive(task, x);
        if (x.phase == control::Phase::Trace && j >= 0 && first[j] < 0) first[j] = i;
    }
    return first;
}

std::string reach_path(const DistalPair& arm, const task::Task& task, const synth::Solution& s,
                       const plot::Frame& f, const std::string& attributes) {
    const ReachGrid g = reachable_space(arm, task.obstacles, s.robot.link_diameter, f.min, f.max,
                                        kReachCellPixels / f.scale);
    return "<path class=\"reach\"" + attributes + " d=\"" + grid_path(g, f) + "\"/>\n";
}

/// Poses every kSweptStep of joint motion among the given samples.
std::vector<std::vector<Vec2>> outline_poses(const synth::Solution& s,
                                             const std::vector<int>& idx) {
    std::vector<std::vector<Vec2>> poses;
    const std::vector<double>* kept = nullptr;
    for (std::size_t n = 0; n < idx.size(); ++n) {
        const auto& q = s.samples[idx[n]].q;
        double change = kept ? 0.0 : 1e9;
        if (kept) {
            for (std::size_t k = 0; k < q.size(); ++k)
                change = std::max(change, std::abs(q[k] - (*kept)[k]));
        }
        if (change >= kSweptStep || n + 1 == idx.size()) {
            poses.push_back(kinematics::forward(s.robot.base, s.robot.link_lengths, q));
            kept = &q;
        }
    }
    return poses;
}

/// Each link between consecutive poses covers (nearly) the hull of its two
/// positions; hulls all wind the same way, so their union fills solidly.
std::string swept_path_data(const std::vector<std::vector<Vec2>>& poses, const plot::Frame& f) {
    std::string d;
    for (std::size_t i = 0; i < poses.size(); ++i) {
        const auto& a = poses[i];
        const auto& b = i + 1 < poses.size() ? poses[i + 1] : poses[i];
        for (std::size_t k = 0; k + 1 < a.size(); ++k) {
            d += plot::path_data(f, geometry::convex_hull({a[k], a[k + 1], b[k + 1], b[k]}), true);
        }
    }
    return d;
}

std::string swept_element(const synth::Solution& s, const plot::Frame& f,
                          const std::vector<int>& idx, const char* cls, int j) {
    if (idx.empty()) return "";
    const std::string colour = plot::primitive_colour(j);
    return std::string("<path class=\"") + cls + "\" data-primitive=\"" + std::to_string(j) +
           "\" fill=\"" + colour + "\" stroke=\"" + colour + "\" stroke-width=\"" +
           n2(s.robot.link_diameter * f.scale) + "\" d=\"" +
           swept_path_data(outline_poses(s, idx), f) + "\"/>\n";
}

std::string arrow(const geometry::Primitive& p, const plot::Frame& f, const std::string& colour) {
    const double mid = geometry::length(p) / 2.0;
    const Vec2 tip = f.px(geometry::point_at(p, mid));
    Vec2 t = geometry::tangent_at(p, mid);
    t.y() = -t.y();  // screen y points down
    const Vec2 n = geometry::perp(t);
    const Vec2 a = tip - 9.0 * t + 4.5 * n;
    const Vec2 b = tip - 9.0 * t - 4.5 * n;
    return "<path class=\"arrow\" fill=\"" + colour + "\" d=\"M" + n2(tip.x()) + "," + n2(tip.y()) +
           "L" + n2(a.x()) + "," + n2(a.y()) + "L" + n2(b.x()) + "," + n2(b.y()) + "Z\"/>";
}

/// Angle of v in [0, 2 pi).
double angle_of(const Vec2& v) {
    const double a = std::atan2(v.y(), v.x());
    return a < 0.0 ? a + 2.0 * M_PI : a;
}

/// SVG arc (screen pixels) from `from` to `to` on the circle around `c` of
/// radius `r`, the way that passes the angle `via` around `c`.
std::string arc_to(const Vec2& c, double r, const Vec2& from, const Vec2& to, double via) {
    const double a = angle_of(from - c);
    const double span = std::fmod(angle_of(to - c) - a + 4.0 * M_PI, 2.0 * M_PI);
    const double at = std::fmod(via - a + 4.0 * M_PI, 2.0 * M_PI);
    const bool positive = at <= span;  // the way of increasing screen angle
    const double travelled = positive ? span : 2.0 * M_PI - span;
    return "A" + n2(r) + "," + n2(r) + " 0 " + (travelled > M_PI ? "1" : "0") + "," +
           (positive ? "1" : "0") + " " + n2(to.x()) + "," + n2(to.y());
}

/// Where two no-go discs overlap (a lens), as path data; the smaller disc
/// when one holds the other.
std::string lens(const Vec2& c1, double r1, const Vec2& c2, double r2) {
    const double d = (c2 - c1).norm();
    if (d <= std::abs(r1 - r2) || d == 0.0) {
        const Vec2 c = r1 < r2 ? c1 : c2;
        const double r = std::min(r1, r2);
        return "M" + n2(c.x() - r) + "," + n2(c.y()) + "a" + n2(r) + "," + n2(r) + " 0 1,0 " +
               n2(2 * r) + ",0a" + n2(r) + "," + n2(r) + " 0 1,0 " + n2(-2 * r) + ",0Z";
    }
    const Vec2 u = (c2 - c1) / d;
    const Vec2 n(-u.y(), u.x());
    const double a = (d * d + r1 * r1 - r2 * r2) / (2.0 * d);
    const double h = std::sqrt(std::max(0.0, r1 * r1 - a * a));
    const Vec2 p = c1 + a * u + h * n, q = c1 + a * u - h * n;
    // On each circle, the arc inside the other passes the point facing it.
    return "M" + n2(p.x()) + "," + n2(p.y()) + arc_to(c1, r1, p, q, angle_of(u)) +
           arc_to(c2, r2, q, p, angle_of(-u)) + "Z";
}

std::string arm_points(const plot::Frame& f, const std::vector<Vec2>& joints) {
    std::string s;
    for (const Vec2& p : joints) s += (s.empty() ? "" : " ") + pt(f, p);
    return s;
}

}  // namespace

bool in_core(const Core& core, const task::TaskPart& part) {
    return std::any_of(core.begin(), core.end(),
                       [&](const task::TaskPart& c) { return c.holds(part); });
}

std::string reachable(const task::Task& task, const synth::Solution& s, const plot::Frame& f,
                      std::string* caption) {
    std::string out = "<g id=\"reachable\">\n";
    if (!s.robot.has_proximal_link()) {
        out += reach_path(distal_pair(s.robot, std::vector<double>{}), task, s, f,
                          " data-primitive=\"all\"");
        *caption =
            "Shaded grey: every point the arm reaches, on either elbow branch, with both "
            "links clear of every obstacle and the end-effector clear of link 1.";
        return out + "</g>\n";
    }
    const auto starts = primitive_starts(task, s);
    for (int j = 0; j < static_cast<int>(starts.size()); ++j) {
        if (starts[j] < 0) continue;
        out += reach_path(distal_pair(s.robot, s.samples[starts[j]].q), task, s, f,
                          " data-primitive=\"" + std::to_string(j) + "\"");
    }
    *caption =
        "Shaded grey: for the primitive being traced, every point the last two links "
        "reach, on either elbow branch, with the leading links held as at the start of "
        "that primitive, all links clear of every obstacle and the end-effector clear of "
        "every link but the last.";
    return out + "</g>\n";
}

std::string swept(const task::Task& task, const synth::Solution& s, const plot::Frame& f) {
    const int primitives = primitive_count(task);
    std::vector<std::vector<int>> trace(primitives), transition(primitives);
    for (int i = 0; i < static_cast<int>(s.samples.size()); ++i) {
        const auto& x = s.samples[i];
        const int j = global_primitive(task, x);
        if (j < 0 || x.phase == control::Phase::Travel) continue;
        (x.phase == control::Phase::Trace ? trace : transition)[j].push_back(i);
    }
    std::string out = "<g id=\"swept\">\n";
    for (int j = 0; j < primitives; ++j) {
        out += swept_element(s, f, trace[j], "swept", j);
        out += swept_element(s, f, transition[j], "swept-transition", j);
    }
    return out + "</g>\n";
}

std::string base_regions(const task::Task& task, const plot::Frame& f, const Core& core) {
    std::string out = "<g id=\"base-regions\">\n";
    for (std::size_t i = 0; i < task.base_regions.size(); ++i) {
        const auto& r = task.base_regions[i];
        const Vec2 tl = f.px({r.min.x(), r.max.y()});
        const Vec2 br = f.px({r.max.x(), r.min.y()});
        out +=
            "<rect" +
            part_attributes(core, task::TaskPart::base_region(static_cast<int>(i)), "base-region") +
            " x=\"" + n2(tl.x()) + "\" y=\"" + n2(tl.y()) + "\" width=\"" +
            n2(std::max(1.0, br.x() - tl.x())) + "\" height=\"" +
            n2(std::max(1.0, br.y() - tl.y())) + "\"/>\n";
    }
    return out + "</g>\n";
}

std::string obstacles(const task::Task& task, const plot::Frame& f, double diameter,
                      const Core& core) {
    std::string out = "<g id=\"obstacles\">\n";
    for (std::size_t i = 0; i < task.obstacles.size(); ++i) {
        const auto& o = task.obstacles[i];
        const Vec2 c = f.px(o.center);
        const auto part = task::TaskPart::obstacle(static_cast<int>(i));
        out += "<circle class=\"obstacle-margin\" cx=\"" + n2(c.x()) + "\" cy=\"" + n2(c.y()) +
               "\" r=\"" + n2((o.radius + diameter / 2.0) * f.scale) + "\"/>";
        out += "<circle" + part_attributes(core, part, "obstacle") + " cx=\"" + n2(c.x()) +
               "\" cy=\"" + n2(c.y()) + "\" r=\"" + n2(o.radius * f.scale) + "\"><title>" +
               task::to_string(part) + "</title></circle>\n";
    }
    return out + "</g>\n";
}

std::string trajectory(const task::Task& task, const plot::Frame& f, const Core& core) {
    std::string out = "<g id=\"trajectory\">\n";
    for (std::size_t j = 0; j < task.trajectory.size(); ++j) {
        const auto& p = task.trajectory[j];
        const auto part = task::TaskPart::primitive(task, static_cast<int>(j));
        const std::string colour = plot::primitive_colour(static_cast<int>(j));
        out += "<path" + part_attributes(core, part, "primitive") + " data-primitive=\"" +
               std::to_string(j) + "\" stroke=\"" + colour + "\" d=\"" +
               plot::path_data(f, plot::polyline(p, f), false) + "\"><title>" +
               task::to_string(part) + "</title></path>" + arrow(p, f, colour) + "\n";
    }
    for (int k = 0; k < task::stroke_count(task); ++k) {
        const Vec2 start = f.px(task.trajectory[task::stroke_first(task, k)].start);
        out += "<circle class=\"path-start\" cx=\"" + n2(start.x()) + "\" cy=\"" + n2(start.y()) +
               "\" r=\"4\"><title>start of the " +
               (task::has_strokes(task) ? "stroke strokes[" + std::to_string(k) + "]"
                                        : std::string("path")) +
               "</title></circle>\n";
    }
    return out + "</g>\n";
}

std::string poses(const task::Task& task, const synth::Solution& s, const plot::Frame& f) {
    const int primitives = primitive_count(task);
    const auto starts = primitive_starts(task, s);
    std::string out = "<g id=\"poses\">\n";
    for (int j = 0; j < primitives; ++j) {
        if (starts[j] < 0) continue;
        const auto joints =
            kinematics::forward(s.robot.base, s.robot.link_lengths, s.samples[starts[j]].q);
        out += "<polyline class=\"pose\" data-primitive=\"" + std::to_string(j) + "\" points=\"" +
               arm_points(f, joints) + "\" stroke-width=\"" + n2(s.robot.link_diameter * f.scale) +
               "\"><title>the arm at the start of " + task::part_name(task, j) +
               "</title></polyline>\n";
    }
    return out + "</g>\n";
}

std::string travel(const synth::Solution& s, const plot::Frame& f) {
    std::string out = "<g id=\"travel\">\n";
    std::vector<Vec2> run;
    auto flush = [&] {
        if (run.size() >= 2)
            out += "<path class=\"travel\" d=\"" + plot::path_data(f, run, false) +
                   "\"><title>travel between strokes</title></path>\n";
        run.clear();
    };
    for (std::size_t i = 0; i + 1 < s.samples.size(); ++i) {
        const auto& a = s.samples[i];
        const auto& b = s.samples[i + 1];
        const bool free = a.phase == control::Phase::Travel || b.phase == control::Phase::Travel ||
                          a.stroke != b.stroke;
        if (!free) {
            flush();
            continue;
        }
        if (run.empty())
            run.push_back(kinematics::forward(s.robot.base, s.robot.link_lengths, a.q).back());
        run.push_back(kinematics::forward(s.robot.base, s.robot.link_lengths, b.q).back());
    }
    flush();
    return out + "</g>\n";
}

std::string robot(const synth::Solution& s, const plot::Frame& f) {
    const auto joints =
        kinematics::forward(s.robot.base, s.robot.link_lengths, s.samples.front().q);
    const std::string width = n2(s.robot.link_diameter * f.scale);
    std::string out = "<polyline id=\"trail\" points=\"\"/>\n<g id=\"robot\">\n";
    for (std::size_t k = 0; k + 1 < joints.size(); ++k) {
        const Vec2 a = f.px(joints[k]);
        const Vec2 b = f.px(joints[k + 1]);
        out += "<line class=\"link\" x1=\"" + n2(a.x()) + "\" y1=\"" + n2(a.y()) + "\" x2=\"" +
               n2(b.x()) + "\" y2=\"" + n2(b.y()) + "\" stroke-width=\"" + width + "\"/>\n";
    }
    for (std::size_t k = 0; k < joints.size(); ++k) {
        const Vec2 c = f.px(joints[k]);
        const bool ee = k + 1 == joints.size();
        out += std::string("<circle class=\"") + (ee ? "ee" : "joint") + "\" cx=\"" + n2(c.x()) +
               "\" cy=\"" + n2(c.y()) + "\" r=\"" + (ee ? "4" : "5") + "\"/>\n";
    }
    const Vec2 b = f.px(s.robot.base);
    out += "<rect class=\"base-marker\" x=\"" + n2(b.x() - 7) + "\" y=\"" + n2(b.y() - 7) +
           "\" width=\"14\" height=\"14\"><title>base (joint 1)</title></rect>\n";
    return out + "</g>\n";
}

std::string reach_limit(const task::Task& task, const plot::Frame& f, const Core& core) {
    const auto part = task::TaskPart::robot(task::RobotKey::MaxLinkLength);
    if (!in_core(core, part) || task.base_regions.empty()) return "";
    const double reach = task.robot.longest_arm();
    const std::string r = n2(reach * f.scale);
    std::string out = "<g id=\"reach-limit\">\n";
    for (const auto& b : task.base_regions) {
        const Vec2 tl = f.px({b.min.x() - reach, b.max.y() + reach});
        const Vec2 br = f.px({b.max.x() + reach, b.min.y() - reach});
        out += "<rect" + part_attributes(core, part, "reach-limit") + " x=\"" + n2(tl.x()) +
               "\" y=\"" + n2(tl.y()) + "\" width=\"" + n2(br.x() - tl.x()) + "\" height=\"" +
               n2(br.y() - tl.y()) + "\" rx=\"" + r + "\" ry=\"" + r +
               "\"><title>farthest reach of any allowed robot</title></rect>\n";
    }
    return out + "</g>\n";
}

std::string proof(const task::Task& task, const synth::Solution& s, const plot::Frame& f) {
    const auto& e = s.explanation;
    if (s.status == synth::Status::Solved || (!e.separation && !e.geodesic)) return "";
    const double half = task.robot.link_diameter / 2.0;
    const auto valid = [&](int i) { return i >= 0 && i < static_cast<int>(task.obstacles.size()); };
    const auto no_go = [&](int i) { return (task.obstacles[i].radius + half) * f.scale; };
    const auto point_mark = [&](const Vec2& p, const std::string& what) {
        const Vec2 c = f.px(p);
        return "<circle class=\"proof-point\" cx=\"" + n2(c.x()) + "\" cy=\"" + n2(c.y()) +
               "\" r=\"5\"><title>" + what + "</title></circle>\n";
    };
    std::string out = "<g id=\"proof\">\n";
    if (e.separation) {
        std::vector<std::vector<int>> drawn;
        for (const auto& w : e.separation->walls) {
            bool ok = w.cycle.size() >= 2;
            for (int i : w.cycle) ok = ok && valid(i);
            if (!ok) continue;
            std::vector<int> sorted = w.cycle;
            std::sort(sorted.begin(), sorted.end());
            const std::string region = task::to_string(task::TaskPart::base_region(w.base_region));
            out += point_mark(w.point, task::part_name(task, w.primitive) + " at a point " +
                                           region + " cannot reach");
            if (std::find(drawn.begin(), drawn.end(), sorted) != drawn.end()) continue;
            drawn.push_back(sorted);
            out += "<g class=\"wall\" data-cycle=\"";
            for (std::size_t k = 0; k < w.cycle.size(); ++k)
                out += (k ? " " : "") + std::to_string(w.cycle[k]);
            out += "\">\n";
            for (int i : w.cycle) {
                const Vec2 c = f.px(task.obstacles[i].center);
                out += "<circle class=\"wall-disc\" data-obstacle=\"" + std::to_string(i) +
                       "\" cx=\"" + n2(c.x()) + "\" cy=\"" + n2(c.y()) + "\" r=\"" + n2(no_go(i)) +
                       "\"/>\n";
            }
            std::vector<Vec2> poly;
            for (int i : w.cycle) poly.push_back(task.obstacles[i].center);
            out += "<path class=\"wall-cycle\" d=\"" + plot::path_data(f, poly, true) + "\"/>\n";
            for (std::size_t k = 0; k < w.cycle.size(); ++k) {
                const int i = w.cycle[k], j = w.cycle[(k + 1) % w.cycle.size()];
                if (w.cycle.size() == 2 && k == 1) break;
                const double depth = k < w.overlaps.size() ? w.overlaps[k] : 0.0;
                out += "<path class=\"wall-overlap\" data-pair=\"" + std::to_string(i) + "-" +
                       std::to_string(j) + "\" d=\"" +
                       lens(f.px(task.obstacles[i].center), no_go(i),
                            f.px(task.obstacles[j].center), no_go(j)) +
                       "\"><title>" + text_format_overlap(i, j, depth) + "</title></path>\n";
            }
            out += "</g>\n";
        }
    }
    if (e.geodesic) {
        for (const auto& d : e.geodesic->detours) {
            if (d.route.size() < 2) continue;
            std::string path;
            Vec2 prev = f.px(d.route.front().point);
            path = "M" + n2(prev.x()) + "," + n2(prev.y());
            for (std::size_t k = 1; k < d.route.size(); ++k) {
                const auto& step = d.route[k];
                const Vec2 to = f.px(step.point);
                if (step.around >= 0 && valid(step.around)) {
                    // The shorter arc: it passes the middle of the chord's side.
                    const Vec2 c = f.px(task.obstacles[step.around].center);
                    const Vec2 mid = 0.5 * (prev + to) - c;
                    const double via =
                        mid.norm() > 1e-12 ? angle_of(mid) : angle_of(prev - c) + 1.0;
                    path += arc_to(c, no_go(step.around), prev, to, via);
                } else {
                    path += "L" + n2(to.x()) + "," + n2(to.y());
                }
                prev = to;
            }
            const std::string label = length_label(d.lower_bound, e.geodesic->reach);
            out += "<path class=\"detour\" data-base-region=\"" + std::to_string(d.base_region) +
                   "\" data-primitive=\"" + std::to_string(d.primitive) + "\" d=\"" + path +
                   "\"><title>the shortest way from base_regions[" + std::to_string(d.base_region) +
                   "] to trajectory[" + std::to_string(d.primitive) + "]: " + label +
                   "</title></path>\n";
            const Vec2 at = f.px(d.route[d.route.size() / 2].point);
            // In two lines, on whichever side of the route's middle leaves room.
            const bool left = at.x() > f.width() / 2.0;
            const std::string x = n2(at.x() + (left ? -10 : 10));
            const auto semicolon = label.find("; ");
            out += "<text class=\"detour-length\" x=\"" + x + "\" y=\"" + n2(at.y() - 22) +
                   "\" text-anchor=\"" + (left ? "end" : "start") + "\"><tspan x=\"" + x + "\">" +
                   label.substr(0, semicolon) + "</tspan><tspan x=\"" + x + "\" dy=\"15\">" +
                   label.substr(semicolon + 2) + "</tspan></text>\n";
            out += point_mark(d.point,
                              task::part_name(task, d.primitive) + " at a point beyond reach");
        }
    }
    return out + "</g>\n";
}

std::string scale_bar(const plot::Frame& f) {
    // The largest of 1, 2, 5 x 10^k metres that fits in a fifth of the plot.
    const double span = (f.max.x() - f.min.x()) / 5.0;
    double bar = std::pow(10.0, std::floor(std::log10(span)));
    if (5.0 * bar <= span)
        bar *= 5.0;
    else if (2.0 * bar <= span)
        bar *= 2.0;
    const double x0 = f.pad;
    const double y0 = f.height() - f.pad / 2.0;
    char label[32];
    std::snprintf(label, sizeof label, bar >= 1.0 ? "%.0f m" : "%.0f mm",
                  bar >= 1.0 ? bar : bar * 1000.0);
    return "<g id=\"scale-bar\"><path d=\"M" + n2(x0) + "," + n2(y0 - 4) + "v4h" +
           n2(bar * f.scale) + "v-4\"/><text x=\"" + n2(x0 + bar * f.scale + 6) + "\" y=\"" +
           n2(y0 + 4) + "\">" + label + "</text></g>\n";
}

}  // namespace modsynth::output::layers
