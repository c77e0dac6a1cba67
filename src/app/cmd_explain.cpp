#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <mutex>
#include <string>

#include <nlohmann/json.hpp>

#include <modsynth/io/solution_io.h>
#include <modsynth/io/task_io.h>
#include <modsynth/synth/explanation.h>
#include <modsynth/synth/synthesizer.h>

#include "command.h"
#include "number_checks.h"
#include "planar_task.h"
#include "watchdog.h"

namespace modsynth::app {
namespace {

struct ExplainArgs {
    std::string task;
    double time_limit = 60.0;
    double solve_seconds = 10.0;
    bool json = false;
};

// Past the time limit by this much, the watchdog answers for the run.
constexpr double kWatchdogMargin = 0.6;

// --time-limit bounds the whole command: the proof, or the full run when
// there is none, and then the suggestions.
int run_explain(const ExplainArgs& a) {
    const auto t0 = std::chrono::steady_clock::now();
    const task::Task task = load_planar_task(a.task, "explain");
    const auto left = [&] {
        return a.time_limit -
               std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    };
    std::mutex mutex;  // `out` is shared with the watchdog
    nlohmann::json out;
    // What the JSON says so far: unknown until a proof or a full run answers.
    synth::Status status = synth::Status::Unknown;
    out["task"] = task.name;
    out["status"] = synth::to_string(status);
    Watchdog watchdog(left() + kWatchdogMargin, [&] {
        std::lock_guard<std::mutex> lock(mutex);
        const std::string note = "stopped at the time limit while " + watchdog.stage();
        if (a.json) {
            out["note"] = note;
            std::printf("%s\n",
                        out.dump(1, ' ', false, nlohmann::json::error_handler_t::replace).c_str());
        } else {
            std::printf("%s%s\n", status == synth::Status::Infeasible ? "  " : "", note.c_str());
        }
        return status == synth::Status::Infeasible ? int{kInfeasible} : int{kUnknown};
    });
    watchdog.set_stage("proving infeasibility");
    const synth::InfeasibilityProof proof = synth::prove_infeasible(task, std::min(10.0, left()));
    if (!proof.proved) {
        // Not proved infeasible: say what a full run finds.
        watchdog.set_stage("solving the task");
        synth::SynthesisOptions options;
        options.time_limit = std::max(0.0, left());
        const synth::Solution s = synth::synthesize(task, options);
        watchdog.claim();
        out["status"] = synth::to_string(s.status);
        const std::string message = synth::unproved_message(proof, s);
        out["message"] = message;
        out["core"] = s.explanation.core;
        io::add_witnesses(s.explanation, out);
        if (a.json) {
            std::printf("%s\n",
                        out.dump(1, ' ', false, nlohmann::json::error_handler_t::replace).c_str());
        } else {
            std::printf("%s\n", message.c_str());
        }
        return s.status == synth::Status::Solved       ? kOk
               : s.status == synth::Status::Infeasible ? kInfeasible
                                                       : kUnknown;
    }
    const std::string message = synth::proved_message(proof);
    {
        std::lock_guard<std::mutex> lock(mutex);
        status = synth::Status::Infeasible;
        out["status"] = synth::to_string(status);
        out["message"] = message;
        out["core"] = proof.core;
        io::add_witnesses({message, proof.core, proof.separation, proof.geodesic}, out);
        out["suggestions"] = nlohmann::json::array();
        if (!a.json) {
            std::printf("%s\n\nThe conflicting parts:\n", message.c_str());
            for (const auto& part : proof.core)
                std::printf("  - %s\n", synth::describe_part(task, part).c_str());
            std::printf("\nSmallest changes that remove the conflict (each re-checked):\n");
            std::fflush(stdout);
        }
    }
    watchdog.set_stage("looking for the smallest changes");
    const auto relaxations = synth::suggest_relaxations(task, proof.core, a.solve_seconds, left());
    watchdog.claim();
    for (const auto& r : relaxations) {
        out["suggestions"].push_back(
            {{"part", r.part}, {"change", r.change}, {"outcome", r.outcome}});
        if (!a.json) std::printf("  - %s\n      then: %s\n", r.change.c_str(), r.outcome.c_str());
    }
    if (a.json) {
        std::printf("%s\n",
                    out.dump(1, ' ', false, nlohmann::json::error_handler_t::replace).c_str());
    } else if (relaxations.empty()) {
        std::printf("  (none found by changing one part alone)\n");
    }
    return kInfeasible;
}

}  // namespace

Command add_explain(CLI::App& parent) {
    auto a = std::make_shared<ExplainArgs>();
    CLI::App* sub = parent.add_subcommand(
        "explain", "Say why a task cannot be done, and the smallest changes that would fix it");
    sub->add_option("TASK", a->task, "modsynth-task/1 JSON file")->required();
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
