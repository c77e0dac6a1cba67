#pragma once
// Reading and writing modsynth-task/1 documents (formats.md). Every reader
// validates fully and throws task::InputError naming the offending part; what
// it returns is sound input for every later stage.
#include <string>
#include <string_view>

#include <nlohmann/json_fwd.hpp>

#include <modsynth/task/input_error.h>
#include <modsynth/task/task.h>

namespace modsynth::io {

/// Tolerance on connections between primitives and on equal radii (formats.md).
constexpr double kJoinTolerance = 1e-6;

task::Task parse_task(const nlohmann::json& doc);
/// Parses JSON text; syntax errors name the line and column.
task::Task parse_task_text(std::string_view text);
/// Reads and parses a file; an unreadable file is an InputError too.
task::Task load_task(const std::string& path);
/// The task as a modsynth-task/1 document (round-trips through parse_task).
nlohmann::json to_json(const task::Task& task);

}  // namespace modsynth::io
