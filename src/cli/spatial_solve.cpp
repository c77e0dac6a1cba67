#include "spatial_solve.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

#include <modsynth/geometry/vec.h>
#include <modsynth/hardware/select_dh_modules.h>
#include <modsynth/synth/module_choice.h>
#include <modsynth/synth/solve.h>
#include <modsynth/task/part.h>
#include <modsynth/task/part_list.h>
#include <modsynth/text/format.h>
#include <modsynth/text/printable.h>

#include "solve_guard.h"

namespace modsynth::app {
namespace {

/// `v` as "%.4f" shows it, but a value that rounds to zero shown as 0, not
/// -0: the sign of a base coordinate of -1e-9 m says nothing, and would
/// make the same robot read differently from run to run.
double shown(double v) { return std::abs(v) < 5e-5 ? 0.0 : v; }

std::string chain_summary(const kinematics::DhChain& c) {
    std::string rows;
    for (const auto& r : c.rows)
        rows += text::format(
            rows.empty() ? "(a %.4f, alpha %+.4f, d %.4f)" : " (a %.4f, alpha %+.4f, d %.4f)",
            shown(r.a), shown(r.alpha), shown(r.d));
    return text::format("%d joints, base (%.4f, %.4f, %.4f), DH ", c.dof(), shown(c.base.x()),
                        shown(c.base.y()), shown(c.base.z())) +
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
        if (!solution.explanation.core.empty())
            std::printf("  core: %s\n", task::to_short_list(solution.explanation.core).c_str());
        return;
    }
    std::printf("  robot: %s\n", chain_summary(*solution.dh_robot).c_str());
    const auto& c = solution.certificate;
    const std::string clearance = text::clearance_text(c.min_clearance);
    std::printf(
        "  certified over the whole motion: %s, self-collision margin %.4f m, EE deviation <= "
        "%.2e m%s\n",
        clearance.c_str(), c.min_self_clearance, c.max_deviation,
        std::isfinite(c.min_tool_angle_margin)
            ? text::format(", tool axis margin %.2f degrees",
                           c.min_tool_angle_margin * 180.0 / geometry::kPi)
                  .c_str()
            : "");
    std::printf("  control: %zu samples over %.2f s -> %s\n", solution.samples.size(),
                solution.samples.back().t, output.c_str());
    if (solution.modules)
        std::printf("  %s\n", text::printable(solution.modules->message, 2000).c_str());
}

}  // namespace

int run_spatial_solve(const task::SpatialTask& task, const SolveRequest& a,
                      std::chrono::steady_clock::time_point t0) {
    const auto elapsed = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    };
    SolveGuard guard(task.name, a.time_limit, elapsed(), [&](const synth::Solution& unknown) {
        write_answer(task, unknown, a.output, a.exports);
        print_summary(task, unknown, elapsed(), {}, a.output);
    });
    synth::SpatialSynthesisOptions options;
    options.time_limit = std::max(0.0, a.time_limit - elapsed());
    options.seed = a.seed;
    options.retime.ee_speed = a.ee_speed;
    options.retime.joint_speed = a.joint_speed;
    SolveProgress progress(a.events, a.quiet);
    options.progress = progress.sink(guard);
    synth::SynthesisStats stats;
    synth::Solution solution = synth::solve(task, options, &stats);
    const double seconds = elapsed();
    guard.claim();
    for (const auto& note : stats.notes) std::fprintf(stderr, "note: %s\n", note.c_str());
    std::optional<parts::PrintedParts> printed;
    if (!a.exports.parts.empty()) {
        std::string catalog_note;
        printed = print_parts(task, hardware::spatial_catalog(task, &catalog_note), solution,
                              a.exports.parts);
    }
    const std::string overload = synth::overload_warning(solution);
    if (!overload.empty()) std::fprintf(stderr, "warning: %s\n", overload.c_str());
    write_answer(task, solution, a.output, a.exports,
                 {stats.front_seconds, stats.refine_seconds, stats.verify_seconds, {}},
                 printed ? &*printed : nullptr);
    print_summary(task, solution, seconds, stats, a.output);
    progress.finish();
    return exit_code(solution.status);
}

}  // namespace modsynth::app
