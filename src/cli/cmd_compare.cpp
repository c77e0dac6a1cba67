#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <modsynth/baseline/comparison.h>
#include <modsynth/io/task_io.h>
#include <modsynth/output/baseline_io.h>
#include <modsynth/output/exports.h>
#include <modsynth/text/format.h>

#include "command.h"
#include "number_checks.h"
#include "planar_task.h"
#include "watchdog.h"

namespace modsynth::app {
namespace {

struct CompareArgs {
    std::string task, report;
    double time_limit = 60.0;
    bool json = false;
    bool quiet = false;
    baseline::BaselineOptions options;
};

std::string fixed(double v, int digits) { return text::format("%.*f", digits, v); }

std::string links(const kinematics::Robot& r) {
    std::string out;
    for (double l : r.link_lengths) out += (out.empty() ? "" : " ") + fixed(l, 3);
    return out;
}

std::string ratio(double theirs, double ours) {
    return ours > 0.0 ? fixed(theirs / ours, 1) + "x" : "";
}

std::string reach(const baseline::Fidelity& f) {
    return f.whole_path_reachable() ? "yes"
                                    : "no: " + fixed(1e3 * f.outside_length, 1) + " mm outside";
}

void print_table(const baseline::Comparison& c, int points) {
    const synth::Solution& s = c.solution;
    const baseline::BaselineResult& b = c.baseline;
    const bool ours = s.status == synth::Status::Solved;
    const bool theirs = b.design.found;
    std::vector<std::vector<std::string>> rows = {
        {"", "modsynth", "discretized (" + std::to_string(points) + " points)", "ratio"},
        {"status", synth::to_string(s.status), baseline::to_string(b.status), ""},
        {"time (s)", fixed(c.solve_seconds, 3), fixed(b.seconds, 3),
         ratio(b.seconds, c.solve_seconds)},
    };
    auto robot_rows = [&](const std::string& name, auto value) {
        rows.push_back(
            {name, ours ? value(s.robot) : "-", theirs ? value(b.design.robot) : "-", ""});
    };
    robot_rows("joints", [](const kinematics::Robot& r) { return std::to_string(r.dof()); });
    robot_rows("link lengths (m)", links);
    robot_rows("total length (m)",
               [](const kinematics::Robot& r) { return fixed(r.total_length(), 4); });
    const baseline::Fidelity* f = c.fidelity ? &*c.fidelity : nullptr;
    const baseline::Fidelity* g = theirs ? &b.fidelity : nullptr;
    rows.push_back({"max EE deviation (mm)", f ? fixed(1e3 * f->max_deviation, 3) : "-",
                    g ? fixed(1e3 * g->max_deviation, 3) : "-",
                    f && g ? ratio(g->max_deviation, f->max_deviation) : ""});
    rows.push_back({"path to EE trail (mm)", f ? fixed(1e3 * f->coverage_gap, 3) : "-",
                    g ? fixed(1e3 * g->coverage_gap, 3) : "-", ""});
    rows.push_back({"path in reachable space", f ? reach(*f) : "-", g ? reach(*g) : "-", ""});
    rows.push_back({"clearance (mm)",
                    ours ? fixed(1e3 * s.certificate.min_clearance, 2) + " certified" : "-",
                    g ? fixed(1e3 * g->min_clearance, 2) + " sampled" : "-", ""});
    std::vector<std::size_t> width(4, 0);
    for (const auto& row : rows)
        for (std::size_t i = 0; i < row.size(); ++i) width[i] = std::max(width[i], row[i].size());
    for (const auto& row : rows) {
        std::string line;
        for (std::size_t i = 0; i < row.size(); ++i) {
            line += row[i];
            if (i + 1 < row.size()) line += std::string(width[i] + 2 - row[i].size(), ' ');
        }
        std::printf("%s\n", line.substr(0, line.find_last_not_of(' ') + 1).c_str());
    }
    if (!s.explanation.message.empty() && !ours)
        std::printf("modsynth: %s\n", s.explanation.message.c_str());
    if (!b.message.empty()) std::printf("discretized: %s\n", b.message.c_str());
}

// The two runs take their own limits one after the other; past their sum
// by this much (measuring both motions included), the watchdog answers.
constexpr double kWatchdogMargin = 1.0;

int run_compare(CompareArgs& a) {
    io::check_outputs({{"--report", a.report}}, {a.task});
    const task::Task task = load_planar_task(a.task, "compare");
    const double limit = a.time_limit + a.options.time_limit;
    Watchdog watchdog(limit + kWatchdogMargin, [&] {
        std::fprintf(stderr, "compare: stopped after %.3g s (the two time limits) while: %s\n",
                     limit, watchdog.stage().c_str());
        return int{kUnknown};
    });
    synth::SynthesisOptions ours;
    ours.time_limit = a.time_limit;
    auto say = [&, quiet = a.quiet](const run::ProgressEvent& e) {
        watchdog.set_stage(e.message);
        if (!quiet) std::cerr << run::console_line(e) << std::endl;
    };
    ours.progress = say;
    a.options.progress = say;
    const baseline::Comparison c = baseline::compare_methods(task, ours, a.options);
    watchdog.claim();
    if (!a.report.empty()) {
        output::ReportFigures figures;
        figures.comparison = &c;
        output::write_text_file(a.report, output::html_report(task, c.solution, figures));
    }
    if (a.json) {
        std::printf("%s\n", output::to_json(c).dump(1).c_str());
    } else {
        std::printf("%s\n", task.name.c_str());
        print_table(c, a.options.points);
    }
    return kOk;
}

}  // namespace

Command add_compare(CLI::App& parent) {
    auto a = std::make_shared<CompareArgs>();
    CLI::App* sub = parent.add_subcommand(
        "compare",
        "Solve a task with modsynth and with the discretized baseline; print both side by side");
    sub->add_option("TASK", a->task, "modsynth-task/1 JSON file")->required();
    sub->add_option("--time-limit", a->time_limit, "seconds for modsynth's run (default 60)")
        ->check(seconds());
    sub->add_option("--report", a->report, "write an HTML report that shows both robots");
    sub->add_flag("--json", a->json,
                  "print one JSON object (modsynth-comparison/1) instead of the table");
    sub->add_flag("-q,--quiet", a->quiet, "no progress lines on stderr");
    add_baseline_options(*sub, a->options);
    return {sub, [a] { return run_compare(*a); }};
}

}  // namespace modsynth::app
