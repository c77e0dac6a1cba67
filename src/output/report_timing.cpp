#include "report_timing.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include <modsynth/control/joint_limits.h>
#include <modsynth/task/input_error.h>
#include <modsynth/text/format.h>
#include <modsynth/text/xml.h>

#include "plot.h"

namespace modsynth::output::timing {
namespace {

using Samples = std::vector<control::Sample>;
using Pick = std::function<const std::vector<double>&(const control::Sample&)>;

constexpr double kWidth = 860.0, kHeight = 170.0;
constexpr double kLeft = 64.0, kRight = 12.0, kTop = 22.0, kBottom = 26.0;

struct Axes {
    double t_end = 1.0, lo = -1.0, hi = 1.0;
    double x(double t) const { return kLeft + (kWidth - kLeft - kRight) * t / t_end; }
    double y(double v) const { return kTop + (kHeight - kTop - kBottom) * (hi - v) / (hi - lo); }
};

/// The curve of joint k, at most two points (its lowest and highest) per
/// pixel column: a long motion stays a small file, and no peak is lost.
std::string curve(const Samples& s, const Pick& pick, std::size_t k, const Axes& a) {
    std::string out;
    const int columns = static_cast<int>(kWidth - kLeft - kRight);
    std::size_t i = 0;
    while (i < s.size()) {
        const int column = static_cast<int>(std::floor(s[i].t / a.t_end * columns));
        std::size_t lo = i, hi = i;
        std::size_t j = i;
        for (; j < s.size() && static_cast<int>(std::floor(s[j].t / a.t_end * columns)) == column;
             ++j) {
            if (pick(s[j])[k] < pick(s[lo])[k]) lo = j;
            if (pick(s[j])[k] > pick(s[hi])[k]) hi = j;
        }
        for (std::size_t m : {std::min(lo, hi), std::max(lo, hi)}) {
            out += (out.empty() ? "" : " ") + plot::n2(a.x(s[m].t)) + "," +
                   plot::n2(a.y(pick(s[m])[k]));
            if (lo == hi) break;
        }
        i = j;
    }
    return out;
}

/// `end`: the motion's duration, when `s` is drawn from its steps and ends
/// before it.
std::string chart(const char* id, const std::string& title, const Samples& s, const Pick& pick,
                  const std::vector<double>* limits, double end = 0.0) {
    const std::size_t dof = pick(s[0]).size();
    Axes a;
    a.t_end = std::max({s.back().t, end, 1e-9});
    a.lo = 1e300;
    a.hi = -1e300;
    for (const auto& x : s) {
        for (double v : pick(x)) {
            a.lo = std::min(a.lo, v);
            a.hi = std::max(a.hi, v);
        }
    }
    if (limits) {
        for (double l : *limits) {
            a.lo = std::min(a.lo, -l);
            a.hi = std::max(a.hi, l);
        }
    }
    const double span = std::max(a.hi - a.lo, 1e-6);
    a.lo -= 0.05 * span;
    a.hi += 0.05 * span;
    std::string out = std::string("<svg class=\"chart\" id=\"") + id + "\" width=\"" +
                      plot::n2(kWidth) + "\" height=\"" + plot::n2(kHeight) + "\" viewBox=\"0 0 " +
                      plot::n2(kWidth) + " " + plot::n2(kHeight) + "\" role=\"img\">\n";
    out += "<text x=\"" + plot::n2(kLeft) + "\" y=\"14\" font-size=\"12\">" +
           text::xml_text(title) + "</text>\n";
    // Frame, zero line and the axis figures.
    out += "<rect x=\"" + plot::n2(kLeft) + "\" y=\"" + plot::n2(kTop) + "\" width=\"" +
           plot::n2(kWidth - kLeft - kRight) + "\" height=\"" + plot::n2(kHeight - kTop - kBottom) +
           "\" fill=\"none\" stroke=\"#bbb\"/>\n";
    if (a.lo < 0.0 && a.hi > 0.0)
        out += "<line x1=\"" + plot::n2(kLeft) + "\" x2=\"" + plot::n2(kWidth - kRight) +
               "\" y1=\"" + plot::n2(a.y(0.0)) + "\" y2=\"" + plot::n2(a.y(0.0)) +
               "\" stroke=\"#ddd\"/>\n";
    for (double v : {a.lo, a.hi})
        out += "<text x=\"" + plot::n2(kLeft - 4.0) + "\" y=\"" + plot::n2(a.y(v) + 4.0) +
               "\" font-size=\"10\" text-anchor=\"end\">" + text::format("%.3g", v) + "</text>\n";
    out += "<text x=\"" + plot::n2(kWidth - kRight) + "\" y=\"" + plot::n2(kHeight - 8.0) +
           "\" font-size=\"10\" text-anchor=\"end\">" + text::format("%.3f s", a.t_end) +
           "</text>\n<text x=\"" + plot::n2(kLeft) + "\" y=\"" + plot::n2(kHeight - 8.0) +
           "\" font-size=\"10\">0 s</text>\n";
    for (std::size_t k = 0; k < dof; ++k) {
        const std::string colour = plot::primitive_colour(static_cast<int>(k));
        if (limits) {
            for (double v : {(*limits)[k], -(*limits)[k]})
                out += "<line class=\"limit\" x1=\"" + plot::n2(kLeft) + "\" x2=\"" +
                       plot::n2(kWidth - kRight) + "\" y1=\"" + plot::n2(a.y(v)) + "\" y2=\"" +
                       plot::n2(a.y(v)) + "\" stroke=\"" + colour +
                       "\" stroke-dasharray=\"6 4\" stroke-width=\"1\"/>\n";
        }
        out += "<polyline class=\"joint-curve\" data-joint=\"" + std::to_string(k + 1) +
               "\" fill=\"none\" stroke=\"" + colour + "\" stroke-width=\"1.2\" points=\"" +
               curve(s, pick, k, a) + "\"/>\n";
    }
    return out + "</svg>\n";
}

/// Per step, the change of each joint's acceleration over its time, drawn
/// at the step's middle: what a jerk limit bounds.
Samples jerk_points(const Samples& s) {
    Samples out;
    for (std::size_t i = 0; i + 1 < s.size(); ++i) {
        const double dt = s[i + 1].t - s[i].t;
        if (!(dt > 0.0)) continue;
        control::Sample x;
        x.t = 0.5 * (s[i].t + s[i + 1].t);
        x.q = s[i].q;
        x.qd.resize(s[i].q.size());
        for (std::size_t k = 0; k < x.qd.size(); ++k)
            x.qd[k] = (s[i + 1].qdd[k] - s[i].qdd[k]) / dt;
        out.push_back(std::move(x));
    }
    return out;
}

/// Per traced step, the EE's mean speed along the path, drawn at the
/// step's middle as the single curve of joint "1"; 0 off the path.
Samples tool_speed_points(const Samples& s) {
    Samples out;
    for (std::size_t i = 0; i + 1 < s.size(); ++i) {
        const control::Sample& a = s[i];
        const control::Sample& b = s[i + 1];
        const double dt = b.t - a.t;
        if (!(dt > 0.0)) continue;
        double ds = 0.0;
        if (a.phase == control::Phase::Trace && b.phase == control::Phase::Trace &&
            a.stroke == b.stroke)
            ds = a.primitive == b.primitive       ? std::abs(b.s - a.s)
                 : b.primitive == a.primitive + 1 ? b.s
                                                  : 0.0;
        control::Sample x;
        x.t = 0.5 * (a.t + b.t);
        x.q = {0.0};
        x.qd = {ds / dt};
        out.push_back(std::move(x));
    }
    return out;
}

std::string limit_text(const std::vector<double>& values, const char* unit) {
    std::string out;
    for (std::size_t k = 0; k < values.size(); ++k)
        out += (k ? ", " : "") + text::format("%.3g", values[k]);
    return out + " " + unit;
}

}  // namespace

std::string section(const task::Task& task, const synth::Solution& solution) {
    const Samples& s = solution.samples;
    if (solution.status != synth::Status::Solved || s.empty() || s[0].qd.empty() ||
        s[0].qdd.empty())
        return "";
    const std::size_t dof = s[0].q.size();
    std::optional<control::JointLimits> limits;
    try {
        limits = control::joint_limits_for(task, static_cast<int>(dof));
    } catch (const task::InputError&) {
        // Limits for another joint count: the charts go without them.
    }
    std::string legend;
    for (std::size_t k = 0; k < dof; ++k)
        legend += "<li data-joint=\"" + std::to_string(k + 1) +
                  "\"><span class=\"swatch\" style=\"background:" +
                  plot::primitive_colour(static_cast<int>(k)) + "\"></span>joint " +
                  std::to_string(k + 1) + "</li>";
    std::string out = "<section id=\"timing\">\n<h2>Timing</h2>\n<p class=\"note\">";
    int stops = 0;
    for (std::size_t i = 1; i + 1 < s.size(); ++i) {
        bool still = true;
        for (double v : s[i].qd) still = still && std::abs(v) <= 1e-9;
        stops += still ? 1 : 0;
    }
    out += text::format("Motion time %.3f s, with %d stop%s inside. ", s.back().t, stops,
                        stops == 1 ? "" : "s");
    if (limits) {
        out += std::string(task.robot.joint_limits ? "Joint limits of the task"
                                                   : "Joint limits of the modules (HEBI X8-9)") +
               ": velocity " + limit_text(limits->velocity, "rad/s") + ", acceleration " +
               limit_text(limits->acceleration, "rad/s&sup2;");
        if (!limits->jerk.empty()) out += ", jerk " + limit_text(limits->jerk, "rad/s&sup3;");
        out += " (dashed). ";
    }
    out +=
        "At rest at the start and the end, at corners of the path and at both ends of "
        "transitions and travel; through smooth junctions the tool keeps moving.</p>\n"
        "<ul class=\"legend\">" +
        legend + "</ul>\n";
    out += chart(
        "chart-q", "Joint angles q (rad)", s,
        [](const control::Sample& x) -> const std::vector<double>& { return x.q; }, nullptr);
    out += chart(
        "chart-qd", "Joint velocities qd (rad/s)", s,
        [](const control::Sample& x) -> const std::vector<double>& { return x.qd; },
        limits ? &limits->velocity : nullptr);
    out += chart(
        "chart-qdd", "Joint accelerations qdd (rad/s\u00b2)", s,
        [](const control::Sample& x) -> const std::vector<double>& { return x.qdd; },
        limits ? &limits->acceleration : nullptr);
    const auto rate = [](const control::Sample& x) -> const std::vector<double>& { return x.qd; };
    const Samples jerk = jerk_points(s);
    if (!jerk.empty())
        out += chart("chart-jerk", "Joint jerks, change of qdd per step (rad/s\u00b3)", jerk, rate,
                     limits && !limits->jerk.empty() ? &limits->jerk : nullptr, s.back().t);
    const Samples tool = tool_speed_points(s);
    if (!tool.empty())
        out += chart("chart-tool-speed", "Tool speed along the path (m/s)", tool, rate, nullptr,
                     s.back().t);
    return out + "</section>\n";
}

}  // namespace modsynth::output::timing
