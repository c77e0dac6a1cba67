#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include <modsynth/baseline/baseline.h>
#include <modsynth/io/task_io.h>
#include <modsynth/output/baseline_io.h>
#include <modsynth/output/exports.h>

#include "command.h"
#include "number_checks.h"
#include "planar_task.h"

namespace modsynth::app {
namespace {

struct BaselineArgs {
    std::string task, output;
    bool quiet = false;
    baseline::BaselineOptions options;
};

void print_result(const task::Task& task, const baseline::BaselineResult& r) {
    std::printf("%s: discretized baseline (%zu points): %s in %.3f s (design %.3f s, RRT %.3f s)\n",
                task.name.c_str(), r.points.size(), baseline::to_string(r.status), r.seconds,
                r.design_seconds, r.planning_seconds);
    if (!r.message.empty()) std::printf("  %s\n", r.message.c_str());
    if (!r.design.found) return;
    std::printf("  robot: %s\n", robot_summary(r.design.robot).c_str());
    const baseline::Fidelity& f = r.fidelity;
    std::printf(
        "  executed EE strays up to %.2f mm from the path (mean %.2f mm, worst at (%.4f, %.4f));\n"
        "  the path lies up to %.2f mm from the EE's trail\n",
        1e3 * f.max_deviation, 1e3 * f.mean_deviation, f.worst_point.x(), f.worst_point.y(),
        1e3 * f.coverage_gap);
    if (f.whole_path_reachable()) {
        std::printf(
            "  the whole path lies in the obstacle-free reachable space (sampled every %.1f mm)\n",
            1e3 * baseline::FidelityOptions{}.path_spacing);
    } else {
        std::printf(
            "  %.1f mm of the %.3f m path lie outside the obstacle-free reachable space, "
            "first at (%.4f, %.4f)\n",
            1e3 * f.outside_length, f.path_length, f.outside_points.front().x(),
            f.outside_points.front().y());
    }
    std::printf("  clearance along the motion (sampled): %.2f mm%s\n", 1e3 * f.min_clearance,
                f.min_clearance < 0.0 ? "  (a collision)" : "");
}

int run_baseline(BaselineArgs& a) {
    io::check_outputs({{"-o", a.output}}, {a.task});
    const task::Task task = load_planar_task(a.task, "baseline");
    if (!a.quiet)
        a.options.progress = [](const run::ProgressEvent& e) {
            std::cerr << run::console_line(e) << std::endl;
        };
    const baseline::BaselineResult r = baseline::run_baseline(task, a.options);
    if (!a.output.empty())
        output::write_text_file(a.output, output::to_json(r, true).dump(1) + "\n");
    print_result(task, r);
    return r.status == baseline::BaselineResult::Status::Executed ? kOk : kUnknown;
}

}  // namespace

void add_baseline_options(CLI::App& sub, baseline::BaselineOptions& o) {
    sub.add_option("--points", o.points,
                   "equidistant points of the path the design sees (default 25)")
        ->check(CLI::Range(2, 10000));
    sub.add_option("--baseline-seed", o.planner.seed, "seed of the RRT samples (default 0)");
    sub.add_option("--baseline-time-limit", o.time_limit,
                   "seconds for the baseline's design and planning (default 120)")
        ->check(seconds());
    sub.add_option("--rrt-iterations", o.planner.max_iterations,
                   "RRT iterations allowed per pair of points (default 20000)")
        ->check(CLI::PositiveNumber);
    sub.add_option("--goal-bias", o.planner.goal_bias,
                   "chance an RRT sample is the next point (default 0.1)")
        ->check(within(0.0, 1.0));
    sub.add_flag("!--no-shortcut", o.planner.shortcut,
                 "keep RRT's path as found, without shortcutting");
}

Command add_baseline(CLI::App& parent) {
    auto a = std::make_shared<BaselineArgs>();
    CLI::App* sub = parent.add_subcommand(
        "baseline",
        "Run the paper's discretized baseline: design from N path points, RRT between them, "
        "and measure how far the result strays from the path");
    sub->add_option("TASK", a->task, "modsynth-task/1 JSON file")->required();
    sub->add_option("-o,--output", a->output,
                    "write the robot, poses, waypoints and figures as JSON");
    sub->add_flag("-q,--quiet", a->quiet, "no progress lines on stderr");
    add_baseline_options(*sub, a->options);
    return {sub, [a] { return run_baseline(*a); }};
}

}  // namespace modsynth::app
