#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <variant>

#include <modsynth/hardware/task_catalog.h>
#include <modsynth/io/progress_json.h>
#include <modsynth/io/solution_io.h>
#include <modsynth/io/task_document.h>
#include <modsynth/io/task_io.h>
#include <modsynth/output/exports.h>
#include <modsynth/run/stopwatch.h>
#include <modsynth/synth/module_choice.h>
#include <modsynth/synth/solve.h>
#include <modsynth/task/part_list.h>
#include <modsynth/task/strokes.h>
#include <modsynth/text/format.h>
#include <modsynth/text/printable.h>

#include "command.h"
#include "number_checks.h"
#include "solve_guard.h"
#include "spatial_solve.h"
#include "task_file.h"

namespace modsynth::app {
namespace {

struct SolveArgs : SolveRequest {
    std::string task;
    bool strict = false;
    std::string swept = "auto";
    double shorten_gap = synth::SynthesisOptions{}.shorten_gap;
};

/// Where along the path a stretch of samples lies, by the task's names.
std::string stretch_text(const task::Task& task, const std::vector<control::Sample>& s,
                         const control::SlowStretch& st) {
    const auto at = [&](const control::Sample& x) {
        return task::part_name(task, control::primitive_index(task, x)) +
               text::format(" at %.3f m", x.s);
    };
    return at(s[st.first]) + " to " + at(s[st.last]) +
           text::format(" (down to %.3f m/s; joint %d near its %s limit)", st.slowest, st.joint + 1,
                        st.limit.c_str());
}

void print_summary(const task::Task& task, const synth::Solution& solution, double seconds,
                   const synth::SynthesisStats& stats, const std::string& output,
                   double ee_speed = std::numeric_limits<double>::infinity()) {
    // A certified motion that no allowed module carries is still solved;
    // the status line says which joint is overloaded.
    // Said after the times, so that no time reads as the overload's.
    const bool overloaded = solution.modules && solution.modules->overloaded_joint > 0;
    const std::string overload = overloaded ? text::format(", but joint %d is overloaded",
                                                           solution.modules->overloaded_joint)
                                            : std::string();
    std::printf("%s: %s in %.3f s (front stage %.3f s, refinement %.3f s, verification %.3f s)%s\n",
                text::printable(task.name, 80).c_str(), synth::to_string(solution.status), seconds,
                stats.front_seconds, stats.refine_seconds, stats.verify_seconds, overload.c_str());
    if (solution.status != synth::Status::Solved) {
        std::printf("  %s\n", solution.explanation.message.c_str());
        if (!solution.explanation.core.empty()) {
            std::printf("  core: %s\n", task::to_short_list(solution.explanation.core).c_str());
        }
        return;
    }
    const auto& r = solution.robot;
    std::printf("  robot: %s\n", robot_summary(r).c_str());
    const auto& c = solution.certificate;
    // Without obstacles there is no clearance to report, only its absence.
    const std::string clearance = text::clearance_text(c.min_clearance);
    std::printf(
        "  certified over the whole motion: %s, self-collision margin %.4f m, EE deviation <= "
        "%.2e m\n",
        clearance.c_str(), c.min_self_clearance, c.max_deviation);
    if (!stats.certified_by.empty())
        std::printf(
            "  refinement: certified by the %s model (first certified robot: %s; %d "
            "fallback(s))\n",
            stats.certified_by.c_str(), stats.first_certified_by.c_str(), stats.fallbacks);
    std::printf("  motion: %.3f s, %zu samples -> %s\n", solution.samples.back().t,
                solution.samples.size(), output.c_str());
    const control::RetimeStats& timing = stats.timing;
    if (timing.rests > 0)
        std::printf("  stops inside the motion: %d (corners, transitions, pen up and down)\n",
                    std::max(0, timing.rests - 2));
    if (std::isfinite(ee_speed) && timing.traced_seconds > 0.0) {
        std::printf("  tool at %.3f m/s along the path but for the ramps at stops", ee_speed);
        if (timing.slow.empty()) {
            std::printf("\n");
        } else {
            std::printf("; the limits force it slower for %.2f s of %.2f s:\n", timing.slow_seconds,
                        timing.traced_seconds);
            for (const auto& st : timing.slow)
                std::printf("    %s\n", stretch_text(task, solution.samples, st).c_str());
        }
    }
    if (solution.modules)
        std::printf("  %s\n", text::printable(solution.modules->message, 2000).c_str());
}

/// The part of the time limit kept for what follows the search: module
/// choice and writing the solution and the exports take about 0.3 ms per
/// primitive (zigzag of 3,000 primitives, 127,036 samples: 1.0 s), and a
/// search that ends at the limit must still leave the run within it.
double output_reserve(const task::Task& task, double time_limit) {
    constexpr double kSecondsPerPrimitive = 4e-4;
    return std::min(0.2 * time_limit,
                    kSecondsPerPrimitive * static_cast<double>(task.trajectory.size()));
}

int run_solve(const SolveArgs& a) {
    const run::Stopwatch clock;
    std::vector<io::OutputFile> outputs = export_outputs(a.exports);
    outputs.push_back({"-o", a.output});
    outputs.push_back({"--events", a.events});
    // Before the parts folder is made: a bad output leaves nothing behind.
    io::check_outputs(outputs, {a.task});
    if (!a.exports.parts.empty()) parts::prepare_parts_folder(a.exports.parts);
    // Checking the task counts against the time limit: a long path among
    // many obstacles takes minutes to check.
    io::TaskDocument doc;
    try {
        doc = read_task_file(a.task, a.strict, run::Deadline::in(a.time_limit - clock.seconds()));
    } catch (const io::CheckTimeout& e) {
        return answer_unchecked(e, a.output, a.exports, a.time_limit, clock.seconds());
    }
    if (const auto* spatial = std::get_if<task::SpatialTask>(&doc))
        return run_spatial_solve(*spatial, a, clock.started());
    const task::Task task = std::get<task::Task>(std::move(doc));
    const auto elapsed = [&] { return clock.seconds(); };
    // The same files as any other answer: a report that says "unknown" and
    // why, and a note for each export an unknown answer cannot give.
    SolveGuard guard(task.name, a.time_limit, elapsed(), [&](const synth::Solution& unknown) {
        write_answer(task, unknown, a.output, a.exports);
        print_summary(task, unknown, elapsed(), {}, a.output);
    });
    synth::SynthesisOptions options;
    options.time_limit =
        std::max(0.0, a.time_limit - elapsed() - output_reserve(task, a.time_limit));
    options.seed = a.seed;
    options.swept = *synth::swept_choice_from(a.swept);
    options.shorten_gap = a.shorten_gap;
    options.retime.ee_speed = a.ee_speed;
    options.retime.joint_speed = a.joint_speed;
    SolveProgress progress(a.events, a.quiet);
    options.progress = progress.sink(guard);
    synth::SynthesisStats stats;
    synth::Solution solution = synth::solve(task, options, &stats);
    const double seconds = elapsed();
    guard.claim();
    for (const auto& note : stats.notes) std::fprintf(stderr, "note: %s\n", note.c_str());
    const std::optional<parts::PrintedParts> printed =
        print_parts(task, hardware::catalog_for(task).catalog, solution, a.exports.parts);
    const std::string overload = synth::overload_warning(solution);
    if (!overload.empty()) std::fprintf(stderr, "warning: %s\n", overload.c_str());
    write_answer(task, solution, a.output, a.exports,
                 {stats.front_seconds, stats.refine_seconds, stats.verify_seconds, {}},
                 printed ? &*printed : nullptr);
    print_summary(task, solution, seconds, stats, a.output, a.ee_speed);
    progress.finish();
    return exit_code(solution.status);
}

}  // namespace

std::string robot_summary(const kinematics::Robot& r) {
    std::string links;
    for (double l : r.link_lengths) links += text::format(" %.4f", l);
    return text::format("%d joints, base (%.4f, %.4f), links", r.dof(), r.base.x(), r.base.y()) +
           links + text::format(" m (total %.4f m), elbow %+d", r.total_length(), r.elbow);
}

Command add_solve(CLI::App& parent) {
    auto a = std::make_shared<SolveArgs>();
    CLI::App* sub = parent.add_subcommand("solve", "Synthesise a robot and its control for a task");
    sub->add_option("TASK", a->task, "modsynth-task/1 JSON file")->required();
    add_strict_option(*sub, a->strict);
    sub->add_option("-o,--output", a->output, "where to write the modsynth-solution/1 JSON")
        ->required();
    sub->add_option("--time-limit", a->time_limit, "seconds for the whole run (default 60)")
        ->check(seconds());
    sub->add_option("--seed", a->seed,
                    "varies initial guesses; same seed, same output (default 0)");
    sub->add_option("--ee-speed", a->ee_speed,
                    "end-effector speed along the path, m/s: held where the joint limits allow, "
                    "and the summary says where they force it slower (default: none; the "
                    "joint limits decide)")
        ->check(speed());
    sub->add_option("--joint-speed", a->joint_speed,
                    "cap on every joint's speed below its limit, rad/s (default: none)")
        ->check(speed());
    sub->add_option("--swept", a->swept,
                    "model of the swept area the refinement starts from: auto (SV-over for two "
                    "joints where it can hold, then lines), app (paper III-D), over (paper "
                    "III-B), lines (separating lines at sampled points); a model whose robot "
                    "is not certified gives way to lines (default auto)")
        ->check(CLI::IsMember({"auto", "app", "over", "lines"}));
    sub->add_option("--shorten-gap", a->shorten_gap,
                    "m: after the first certified robot, other elbow signs and base regions are "
                    "refined only where a robot more than this shorter could exist (0: "
                    "wherever any shorter one could; default 0.0005)")
        ->check(within(0.0, 10.0));
    sub->add_flag("-q,--quiet", a->quiet, "no progress lines on stderr");
    sub->add_option("--events", a->events,
                    "also write every progress event to this file, one JSON object a line "
                    "({\"stage\", \"message\", \"elapsed\"}), for a program that follows the run");
    add_export_options(*sub, a->exports);
    return {sub, [a] { return run_solve(*a); }};
}

}  // namespace modsynth::app
