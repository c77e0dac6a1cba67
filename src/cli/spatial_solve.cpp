#include "spatial_solve.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

#include <modsynth/hardware/select_dh_modules.h>
#include <modsynth/io/solution_io.h>
#include <modsynth/synth/spatial_module_choice.h>
#include <modsynth/synth/spatial_synthesizer.h>
#include <modsynth/task/part.h>
#include <modsynth/text/format.h>
#include <modsynth/text/printable.h>

#include "command.h"
#include "watchdog.h"

namespace modsynth::app {
namespace {

// Past the time limit by this much, the watchdog answers for the run.
constexpr double kWatchdogMargin = 0.6;

std::string chain_summary(const kinematics::DhChain& c) {
    std::string rows;
    for (const auto& r : c.rows)
        rows += text::format(
            rows.empty() ? "(a %.4f, alpha %+.4f, d %.4f)" : " (a %.4f, alpha %+.4f, d %.4f)", r.a,
            r.alpha, r.d);
    return text::format("%d joints, base (%.4f, %.4f, %.4f), DH ", c.dof(), c.base.x(), c.base.y(),
                        c.base.z()) +
           rows + text::format(", chain %.4f m", c.total_length());
}

void print_summary(const task::SpatialTask& task, const synth::Solution& solution, double seconds,
                   const synth::SynthesisStats& stats, const std::string& output) {
    const std::string status = synth::to_string(solution.status);
    std::printf("%s: %s in %.3f s (front stage %.3f s, refinement %.3f s, verification %.3f s)\n",
                text::printable(task.name, 80).c_str(), status.c_str(), seconds,
                stats.front_seconds, stats.refine_seconds, stats.verify_seconds);
    if (solution.status != synth::Status::Solved) {
        std::printf("  %s\n", solution.explanation.message.c_str());
        if (!solution.explanation.core.empty()) {
            std::printf("  core:");
            for (const auto& c : solution.explanation.core)
                std::printf(" %s", task::to_string(c).c_str());
            std::printf("\n");
        }
        return;
    }
    std::printf("  robot: %s\n", chain_summary(*solution.dh_robot).c_str());
    const auto& c = solution.certificate;
    const std::string clearance = std::isfinite(c.min_clearance)
                                      ? text::format("clearance margin %.4f m", c.min_clearance)
                                      : std::string("no obstacles");
    std::printf(
        "  certified over the whole motion: %s, self-collision margin %.4f m, EE deviation <= "
        "%.2e m\n",
        clearance.c_str(), c.min_self_clearance, c.max_deviation);
    std::printf("  control: %zu samples over %.2f s -> %s\n", solution.samples.size(),
                solution.samples.back().t, output.c_str());
    if (solution.modules) std::printf("  %s\n", solution.modules->message.c_str());
}

}  // namespace

int run_spatial_solve(const task::SpatialTask& task, const SpatialSolveRequest& a,
                      std::chrono::steady_clock::time_point t0) {
    const auto elapsed = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    };
    Watchdog watchdog(a.time_limit + kWatchdogMargin - elapsed(), [&] {
        synth::Solution unknown;
        unknown.task_name = task.name;
        unknown.status =
            synth::Status(synth::Status::Unknown, text::printable(watchdog.stage(), 200),
                          text::format("time limit (%.3g s)", a.time_limit));
        unknown.explanation.message = "No certified robot found within the " +
                                      unknown.status.reason +
                                      "; the last stage reached: " + unknown.status.stage + ".";
        io::write_solution(unknown, a.output);
        for (const auto& note : output::write_exports(task, unknown, a.exports, {}))
            std::fprintf(stderr, "note: %s\n", note.c_str());
        print_summary(task, unknown, elapsed(), {}, a.output);
        return int{kUnknown};
    });
    std::string catalog_note;
    const std::optional<hardware::Catalog> catalog = hardware::spatial_catalog(task, &catalog_note);
    if (!catalog_note.empty() && !a.quiet) std::fprintf(stderr, "note: %s\n", catalog_note.c_str());
    synth::SpatialSynthesisOptions options;
    options.time_limit = std::max(0.0, a.time_limit - elapsed());
    options.seed = a.seed;
    options.retime.ee_speed = a.ee_speed;
    options.retime.joint_speed = std::min(a.joint_speed, hardware::module_speed_cap(task, catalog));
    options.progress = [&](const std::string& line) {
        watchdog.set_stage(line.size() > 11 ? line.substr(11) : line);  // without the clock
        if (!a.quiet) std::cerr << line << std::endl;
    };
    synth::SynthesisStats stats;
    synth::Solution solution = synth::synthesize(task, options, &stats);
    const double seconds = elapsed();
    watchdog.claim();
    synth::choose_modules(task, catalog, solution);
    if (solution.modules && solution.modules->checked && !solution.modules->carried())
        std::fprintf(stderr, "warning: the certified robot overloads its modules: %s\n",
                     solution.modules->message.c_str());
    io::write_solution(solution, a.output);
    for (const auto& note : output::write_exports(
             task, solution, a.exports,
             {stats.front_seconds, stats.refine_seconds, stats.verify_seconds, {}})) {
        std::fprintf(stderr, "note: %s\n", note.c_str());
    }
    print_summary(task, solution, seconds, stats, a.output);
    switch (solution.status) {
        case synth::Status::Solved:
            return kOk;
        case synth::Status::Infeasible:
            return kInfeasible;
        case synth::Status::Unknown:
            return kUnknown;
    }
    return kInternal;
}

}  // namespace modsynth::app
