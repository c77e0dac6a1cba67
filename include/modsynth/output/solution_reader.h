#pragma once
// Reading modsynth-solution/1 documents back (formats.md), e.g. to export a
// saved solution. Every function validates fully and throws task::InputError
// naming the JSON path of the offending part ("samples[12].q[1]").
#include <string>
#include <string_view>

#include <nlohmann/json_fwd.hpp>

#include <modsynth/synth/solution.h>
#include <modsynth/task/input_error.h>
#include <modsynth/task/task.h>

namespace modsynth::output {

struct ParsedSolution {
    synth::Solution solution;
    /// The document carried a "certificate" (optional: other tools may not
    /// write one). Without it solution.certificate is default (not ok).
    bool has_certificate = false;
};

ParsedSolution parse_solution(const nlohmann::json& doc);
/// Parses JSON text; syntax errors name the line and column.
ParsedSolution parse_solution_text(std::string_view text);
/// Reads and parses a file; an unreadable file is an InputError too.
ParsedSolution load_solution(const std::string& path);

/// Throws InputError when the solution cannot belong to the task: another
/// task's name, or samples tracing primitives the task does not have.
void check_solution_fits(const task::Task& task, const synth::Solution& solution);

}  // namespace modsynth::output
