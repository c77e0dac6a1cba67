#include <algorithm>
#include <cstdio>
#include <memory>
#include <mutex>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include <modsynth/explanation/explain.h>
#include <modsynth/io/check_timeout.h>
#include <modsynth/io/solution_io.h>
#include <modsynth/io/task_document.h>
#include <modsynth/io/task_io.h>
#include <modsynth/prove/conflict_text.h>
#include <modsynth/run/stopwatch.h>
#include <modsynth/task/part_list.h>
#include <modsynth/text/format.h>

#include "command.h"
#include "number_checks.h"
#include "task_file.h"
#include "watchdog.h"

namespace modsynth::app {
namespace {

struct ExplainArgs {
    std::string task;
    bool strict = false;
    double time_limit = 60.0;
    double solve_seconds = 10.0;
    bool json = false;
};

// Past the time limit by this much, the watchdog answers for the run.
constexpr double kWatchdogMargin = 0.6;

nlohmann::json suggestion_json(const explanation::Relaxation& r) {
    return {{"part", task::to_string(r.part)}, {"change", r.change}, {"outcome", r.outcome}};
}

std::string describe(const task::Task& task, const task::TaskPart& part) {
    return prove::describe_part(task, part);
}

// A spatial core's parts with the values they stand for.
std::string describe(const task::SpatialTask& task, const task::TaskPart& part) {
    const std::string name = task::to_string(part);
    const auto& r = task.robot;
    switch (part.kind()) {
        case task::TaskPart::Kind::Primitive:
            return name + " (a primitive of the path)";
        case task::TaskPart::Kind::Obstacle:
            return name + " (an obstacle)";
        case task::TaskPart::Kind::BaseRegions:
            return name + text::format(" (where the base may stand: %zu box(es))",
                                       task.base_regions.size());
        case task::TaskPart::Kind::BaseRegion:
            return name + " (a box the base may stand in)";
        case task::TaskPart::Kind::ToolAxis:
            return name + " (which way the tool points along every primitive without its own)";
        case task::TaskPart::Kind::Robot:
            break;
    }
    if (part.is_robot(task::RobotKey::MaxLinkLength))
        return name + text::format(
                          " = %.3f m (the longest a or |d| of a link: a chain of n joints "
                          "reaches at most 2 n times it)",
                          r.max_link_length);
    if (part.is_robot(task::RobotKey::MinLinkLength))
        return name + text::format(" = %.3f m", r.min_link_length);
    if (part.is_robot(task::RobotKey::Dof)) {
        std::string counts;
        for (int d : r.dof) counts += (counts.empty() ? "" : ", ") + std::to_string(d);
        return name + " = " + counts + " joints";
    }
    if (part.is_robot(task::RobotKey::Twists)) {
        std::string twists;
        for (double t : r.twists) twists += text::format(twists.empty() ? "%.4f" : ", %.4f", t);
        return name + " = " + twists + " rad (every joint axis vertical: the EE keeps one height)";
    }
    if (part.is_robot(task::RobotKey::ToolLength))
        return name + text::format(" = %.3f m", r.tool_length);
    return name;
}

// The changes a builder acts on first: those the synthesis confirmed (with
// the robot and how long it took), then, apart, those it did not within
// its time, then those after which the task is still infeasible.
void print_suggestions(const std::vector<explanation::Relaxation>& all, double solve_seconds) {
    const auto group = [&](synth::Status::Kind kind) {
        std::vector<const explanation::Relaxation*> out;
        for (const auto& r : all)
            if (r.status.kind == kind ||
                (kind == synth::Status::Kind::Unknown && r.status != synth::Status::Solved &&
                 r.status != synth::Status::Infeasible))
                out.push_back(&r);
        return out;
    };
    const auto solved = group(synth::Status::Kind::Solved);
    const auto open = group(synth::Status::Kind::Unknown);
    const auto still = group(synth::Status::Kind::Infeasible);
    if (all.empty()) {
        std::printf("\nNo change of one part alone removes the conflict.\n");
        return;
    }
    if (!solved.empty()) {
        std::printf("\nChanges that solve the task (each re-checked, then solved):\n");
        for (const auto* r : solved)
            std::printf("  - %s\n      %s\n", r->change.c_str(), r->outcome.c_str());
    }
    if (!open.empty()) {
        std::printf("\n%s", solved.empty() ? "No change was confirmed by a synthesis. " : "");
        std::printf(
            "Changes that remove the conflict, not confirmed in %.0f s (no robot found "
            "in that time):\n",
            solve_seconds);
        for (const auto* r : open) std::printf("  - %s\n", r->change.c_str());
    }
    if (!still.empty()) {
        std::printf(
            "\nChanges that remove this conflict, after which the task is still "
            "infeasible:\n");
        for (const auto* r : still)
            std::printf("  - %s\n      %s\n", r->change.c_str(), r->outcome.c_str());
    }
}

// --time-limit bounds the whole command: the proof, or the full run when
// there is none, and then the suggestions (explanation/explain.h). Planar
// and spatial tasks take the same flow and print the same way.
template <class TaskT>
int run_explain(const ExplainArgs& a, const TaskT& task, const run::Stopwatch& clock) {
    std::mutex mutex;  // `out` is shared with the watchdog
    nlohmann::json out;
    // What the JSON says so far: unknown until a proof or a full run answers.
    synth::Status status = synth::Status::Kind::Unknown;
    out["task"] = task.name;
    out["status"] = synth::to_string(status);
    const auto fill = [&](const explanation::Explanation& e) {
        out["status"] = synth::to_string(e.status);
        out["message"] = e.message;
        out["core"] = task::to_strings(e.core);
        io::add_witnesses({e.message, e.core, e.separation, e.geodesic, e.enclosure}, out);
    };
    const double time_limit = std::max(0.0, a.time_limit - clock.seconds());
    Watchdog watchdog(time_limit + kWatchdogMargin, [&] {
        std::lock_guard<std::mutex> lock(mutex);
        const std::string note = "stopped at the time limit while " + watchdog.stage();
        if (a.json) {
            out["note"] = note;
            std::printf("%s\n",
                        out.dump(1, ' ', false, nlohmann::json::error_handler_t::replace).c_str());
        } else {
            std::printf("%s%s\n", status == synth::Status::Kind::Infeasible ? "  " : "",
                        note.c_str());
        }
        return status == synth::Status::Kind::Infeasible ? int{kInfeasible} : int{kUnknown};
    });
    explanation::ExplainOptions options;
    options.time_limit = time_limit;
    options.solve_seconds = a.solve_seconds;
    options.progress = [&](const run::ProgressEvent& e) { watchdog.set_stage(e.message); };
    // Once proved, the proof is printed at once: the suggestions take most
    // of the time, and a run stopped among them still says why.
    options.proved = [&](const explanation::Explanation& e) {
        std::lock_guard<std::mutex> lock(mutex);
        status = e.status;
        fill(e);
        out["suggestions"] = nlohmann::json::array();
        if (!a.json) {
            std::printf("%s\n\nThe conflicting parts:\n", e.message.c_str());
            for (const task::PartRun& run : task::part_runs(e.core)) {
                // A run (a shell of 80 spheres, a polyline's segments) is one line.
                if (run.size() >= 3) {
                    const bool primitives =
                        e.core[run.first].kind() == task::TaskPart::Kind::Primitive;
                    std::printf("  - %s (%zu %s)\n", task::run_text(e.core, run).c_str(),
                                run.size(), primitives ? "primitives of the path" : "obstacles");
                    continue;
                }
                for (std::size_t k = run.first; k <= run.last; ++k)
                    std::printf("  - %s\n", describe(task, e.core[k]).c_str());
            }
            std::fflush(stdout);
        }
    };
    const explanation::Explanation e = explanation::explain(task, options);
    watchdog.claim();
    if (!e.proved) {
        // Not proved infeasible: what a full run found.
        fill(e);
        if (a.json) {
            std::printf("%s\n",
                        out.dump(1, ' ', false, nlohmann::json::error_handler_t::replace).c_str());
        } else {
            std::printf("%s\n", e.message.c_str());
        }
        return e.status == synth::Status::Kind::Solved       ? kOk
               : e.status == synth::Status::Kind::Infeasible ? kInfeasible
                                                             : kUnknown;
    }
    for (const auto& r : e.suggestions) out["suggestions"].push_back(suggestion_json(r));
    if (a.json) {
        // A reader (the server's page) shows why there are none.
        if (e.suggestions.empty()) out["note"] = "none found by changing one part alone";
        std::printf("%s\n",
                    out.dump(1, ' ', false, nlohmann::json::error_handler_t::replace).c_str());
    } else {
        print_suggestions(e.suggestions, a.solve_seconds);
    }
    return kInfeasible;
}

int run_explain(const ExplainArgs& a) {
    const run::Stopwatch clock;
    io::TaskDocument doc;
    try {
        // Checking the task is part of the command's time.
        doc = read_task_file(a.task, a.strict, run::Deadline::in(a.time_limit));
    } catch (const io::CheckTimeout& e) {
        const std::string message =
            "Not proved infeasible: the task's checks did not end (" + std::string(e.what()) + ").";
        if (a.json) {
            const nlohmann::json out = {{"task", e.task_name()},
                                        {"status", synth::to_string(synth::Status::Kind::Unknown)},
                                        {"message", message},
                                        {"core", nlohmann::json::array()},
                                        {"suggestions", nlohmann::json::array()}};
            std::printf("%s\n",
                        out.dump(1, ' ', false, nlohmann::json::error_handler_t::replace).c_str());
        } else {
            std::printf("%s\n", message.c_str());
        }
        return kUnknown;
    }
    if (const auto* spatial = std::get_if<task::SpatialTask>(&doc))
        return run_explain(a, *spatial, clock);
    return run_explain(a, std::get<task::Task>(doc), clock);
}

}  // namespace

Command add_explain(CLI::App& parent) {
    auto a = std::make_shared<ExplainArgs>();
    CLI::App* sub = parent.add_subcommand(
        "explain", "Say why a task cannot be done, and the smallest changes that would fix it");
    sub->add_option("TASK", a->task, "modsynth-task/1 JSON file (planar or spatial)")->required();
    add_strict_option(*sub, a->strict);
    sub->add_option("--time-limit", a->time_limit,
                    "seconds for the whole command: the proof or the full run, then the "
                    "suggestions (default 60)")
        ->check(seconds());
    sub->add_option("--solve-seconds", a->solve_seconds,
                    "seconds of full synthesis to try on each relaxed task (default 10)")
        ->check(seconds());
    sub->add_flag("--json", a->json, "print one JSON object instead of text");
    return {sub, [a] { return run_explain(*a); }};
}

}  // namespace modsynth::app
