#include <modsynth/modsynth.h>

#include <utility>

#include <modsynth/io/input.h>
#include <modsynth/io/solution_io.h>
#include <modsynth/io/spatial_task_io.h>
#include <modsynth/io/task_document.h>
#include <modsynth/io/task_io.h>
#include <modsynth/output/recertify.h>
#include <modsynth/synth/solve.h>

#include <nlohmann/json.hpp>

namespace modsynth {

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
    o.cancel = options.cancel;
    return synth::solve(task, o);
}

Solution solve(const SpatialTask& task, const SolveOptions& options) {
    synth::SpatialSynthesisOptions o;
    o.time_limit = options.time_limit;
    o.seed = options.seed;
    o.progress = options.progress;
    o.cancel = options.cancel;
    return synth::solve(task, o);
}

Explanation explain(const Task& task, double time_limit, double solve_seconds) {
    explanation::ExplainOptions o;
    o.time_limit = time_limit;
    o.solve_seconds = solve_seconds;
    return explanation::explain(task, o);
}

Explanation explain(const SpatialTask& task, double time_limit, double solve_seconds) {
    explanation::ExplainOptions o;
    o.time_limit = time_limit;
    o.solve_seconds = solve_seconds;
    return explanation::explain(task, o);
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
