#include "report_figures.h"

#include <cmath>

#include <modsynth/output/recertify.h>
#include <modsynth/text/format.h>
#include <modsynth/text/xml.h>

#include "plot.h"

namespace modsynth::output::figures {

using text::xml_text;

std::string mm(double metres, const char* format) {
    return text::format(format, 1000.0 * metres) + " mm";
}

std::string row(const char* id, const std::string& name, const std::string& value) {
    return std::string("<tr id=\"") + id + "\"><th>" + name + "</th><td>" + value + "</td></tr>\n";
}

std::string margin_text(double metres, const char* what) {
    return std::isfinite(metres) ? mm(metres, "%.2f") + " " + what : "nothing to check";
}

std::string stage_text(const ReportFigures& f) {
    if (!f.front_seconds && !f.refine_seconds && !f.verify_seconds)
        return "n/a (a saved solution does not record them)";
    const auto t = [](const std::optional<double>& s) {
        return s ? text::format("%.3f s", *s) : std::string("n/a");
    };
    return "front stage " + t(f.front_seconds) + ", refinement " + t(f.refine_seconds) +
           ", verification " + t(f.verify_seconds);
}

std::string certificate_rows(const synth::Solution& s, const ReportFigures& figures,
                             const char* clearance_beyond) {
    const auto& c = s.certificate;
    // Without a certificate these are only what the check found, not bounds.
    const std::string prefix = c.ok ? "Certified " : "Uncertified ";
    std::string out;
    out += row("fig-clearance", prefix + "min. clearance",
               margin_text(c.min_clearance, clearance_beyond));
    out += row("fig-self-clearance", prefix + "self-collision margin",
               margin_text(c.min_self_clearance, "beyond one link diameter"));
    out += row("fig-deviation", "Max. EE deviation", mm(c.max_deviation, "%.3f") + " (bound)");
    out += row("fig-joint-step", "Max. joint step", text::format("%.4f rad", c.max_joint_step));
    if (!c.ok)
        out += row("fig-certificate", "Certificate",
                   "<strong>not certified</strong>: " + xml_text(uncertified_reason(c)));
    if (!figures.certificate_note.empty())
        out +=
            row("fig-certificate-note", "Certificate source", xml_text(figures.certificate_note));
    return out;
}

std::string failed_figures(const synth::Solution& s, const ReportFigures& figures) {
    std::string out = "<table id=\"figures\">\n";
    out += row("fig-status", "Status", synth::to_string(s.status));
    out += row("fig-core", "Parts in conflict", std::to_string(s.explanation.core.size()));
    out += row("stage-times", "Time per stage", stage_text(figures));
    return out + "</table>\n";
}

std::string explanation(const synth::Solution& s, const char* core_caption,
                        const std::function<std::string(const task::TaskPart&)>& describe,
                        const std::string& proof) {
    std::string out = "<section id=\"explanation\">\n<h2>";
    out += s.status == synth::Status::Infeasible ? "Why no robot can do this task"
                                                 : "Why no robot was found";
    out += "</h2>\n<p id=\"explanation-message\">" + xml_text(s.explanation.message) + "</p>\n";
    if (!s.explanation.core.empty()) {
        out += std::string("<p>The task parts that together cannot be satisfied (") + core_caption +
               "):</p>\n<ul id=\"core\">\n";
        for (const auto& part : s.explanation.core) {
            const std::string what = describe(part);
            const std::string name = task::to_string(part);
            out += "<li class=\"core-part\" data-part=\"" + xml_text(name) + "\"><code>" +
                   xml_text(name) + "</code>" + (what.empty() ? "" : ": " + xml_text(what)) +
                   "</li>\n";
        }
        out += "</ul>\n";
    }
    return out + proof + "</section>\n";
}

}  // namespace modsynth::output::figures
