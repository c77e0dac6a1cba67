#include <modsynth/modsynth.h>

#include <algorithm>
#include <chrono>
#include <utility>

#include <modsynth/io/input.h>
#include <modsynth/io/solution_io.h>
#include <modsynth/io/spatial_task_io.h>
#include <modsynth/io/task_document.h>
#include <modsynth/io/task_io.h>
#include <modsynth/output/recertify.h>
#include <modsynth/synth/synthesizer.h>

#include <nlohmann/json.hpp>

namespace modsynth {
namespace {

// The proof gets at most this much of explain's time; the rest goes to a
// full run (when there is no proof) or to the suggestions.
constexpr double kProofSeconds = 10.0;

}  // namespace

Task read_task(std::string_view json_text) { return io::parse_task_text(json_text); }

Task load_task(const std::string& path) { return io::load_task(path); }

bool is_spatial_task(std::string_view json_text) {
    return io::is_spatial(io::parse_json_text(json_text));
}

SpatialTask read_spatial_task(std::string_view json_text) {
    return io::parse_spatial_task_text(json_text);
}

SpatialTask load_spatial_task(const std::string& path) { return io::load_spatial_task(path); }

Solution solve(const Task& task, const SolveOptions& options) {
    synth::SynthesisOptions o;
    o.time_limit = options.time_limit;
    o.seed = options.seed;
    o.progress = options.progress;
    return synth::synthesize(task, o);
}

Explanation explain(const Task& task, double time_limit, double solve_seconds) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    const auto left = [&] {
        return time_limit - std::chrono::duration<double>(Clock::now() - start).count();
    };
    Explanation out;
    const synth::InfeasibilityProof proof =
        synth::prove_infeasible(task, std::max(0.0, std::min(kProofSeconds, left())));
    if (!proof.proved) {
        SolveOptions o;
        o.time_limit = std::max(0.0, left());
        const Solution s = solve(task, o);
        out.status = s.status;
        out.core = s.explanation.core;
        out.message = synth::unproved_message(proof, s);
        out.separation = s.explanation.separation;
        out.geodesic = s.explanation.geodesic;
        return out;
    }
    out.status = Status::Infeasible;
    out.core = proof.core;
    out.message = synth::proved_message(proof);
    out.separation = proof.separation;
    out.geodesic = proof.geodesic;
    out.suggestions =
        synth::suggest_relaxations(task, proof.core, solve_seconds, std::max(0.0, left()));
    return out;
}

Certificate certify(const Task& task, const Solution& solution) {
    if (solution.status != Status::Solved) return {};
    // The same re-verification export gives a solution read from a file.
    io::ParsedSolution parsed{solution, true};
    output::recertify(task, parsed);
    return std::move(parsed.solution.certificate);
}

Certificate certify(const SpatialTask& task, const Solution& solution) {
    if (solution.status != Status::Solved) return {};
    io::ParsedSolution parsed{solution, true};
    output::recertify(task, parsed);
    return std::move(parsed.solution.certificate);
}

std::string write_solution_json(const Solution& solution) {
    return io::to_json(solution).dump(1) + '\n';
}

Solution read_solution(std::string_view json_text) {
    return io::parse_solution_text(json_text).solution;
}

}  // namespace modsynth
