#include <cstdio>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include <modsynth/synth/explanation.h>
#include <modsynth/synth/synthesizer.h>
#include <modsynth/task/task_io.h>

#include "command.h"

namespace modsynth::app {
namespace {

struct ExplainArgs {
    std::string task;
    double time_limit = 60.0;
    double solve_seconds = 10.0;
    bool json = false;
};

int run_explain(const ExplainArgs& a) {
    const task::Task task = task::load_task(a.task);
    nlohmann::json out;
    out["task"] = task.name;
    const synth::InfeasibilityProof proof = synth::prove_infeasible(task, std::min(10.0, a.time_limit));
    if (!proof.proved) {
        // Not proved infeasible: say what a full run finds.
        synth::SynthesisOptions options;
        options.time_limit = a.time_limit;
        const synth::Solution s = synth::synthesize(task, options);
        out["status"] = synth::to_string(s.status);
        const std::string message =
            s.status == synth::Status::Solved
                ? "No conflict: a " + std::to_string(s.robot.dof()) + "-joint robot does this task (run solve)."
                : "Not proved infeasible (" + proof.open + "); " + s.explanation.message;
        out["message"] = message;
        out["core"] = s.explanation.core;
        if (a.json) {
            std::printf("%s\n", out.dump(1).c_str());
        } else {
            std::printf("%s\n", message.c_str());
        }
        return s.status == synth::Status::Solved ? kOk : s.status == synth::Status::Infeasible ? kInfeasible : kUnknown;
    }
    const std::string message = "Proved infeasible: " + synth::describe_conflict(task, proof.core);
    out["status"] = "infeasible";
    out["message"] = message;
    out["core"] = proof.core;
    if (!a.json) {
        std::printf("%s\n\nThe conflicting parts:\n", message.c_str());
        for (const auto& part : proof.core) std::printf("  - %s\n", synth::describe_part(task, part).c_str());
        std::printf("\nSmallest changes that remove the conflict (each re-checked):\n");
        std::fflush(stdout);
    }
    const auto relaxations = synth::suggest_relaxations(task, proof.core, a.solve_seconds);
    out["suggestions"] = nlohmann::json::array();
    for (const auto& r : relaxations) {
        out["suggestions"].push_back({{"part", r.part}, {"change", r.change}, {"outcome", r.outcome}});
        if (!a.json) std::printf("  - %s\n      then: %s\n", r.change.c_str(), r.outcome.c_str());
    }
    if (a.json) {
        std::printf("%s\n", out.dump(1).c_str());
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
    sub->add_option("--time-limit", a->time_limit, "seconds for the proof or the full run (default 60)")
        ->check(CLI::PositiveNumber);
    sub->add_option("--solve-seconds", a->solve_seconds,
                    "seconds of full synthesis to try on each relaxed task (default 10)")
        ->check(CLI::PositiveNumber);
    sub->add_flag("--json", a->json, "print one JSON object instead of text");
    return {sub, [a] { return run_explain(*a); }};
}

}  // namespace modsynth::app
