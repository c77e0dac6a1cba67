#pragma once
// Reading modsynth-task/1 documents. Every function validates fully and
// throws InputError naming the offending part; what it returns is sound input
// for every later stage.
#include <string>
#include <string_view>

#include <nlohmann/json_fwd.hpp>

#include <modsynth/task/input_error.h>
#include <modsynth/task/task.h>

namespace modsynth::task {

/// Tolerance on connections between primitives and on equal radii (formats.md).
constexpr double kJoinTolerance = 1e-6;

Task parse_task(const nlohmann::json& doc);
/// Parses JSON text; syntax errors name the line and column.
Task parse_task_text(std::string_view text);
/// Reads and parses a file; an unreadable file is an InputError too.
Task load_task(const std::string& path);
/// The task as a modsynth-task/1 document (round-trips through parse_task).
nlohmann::json to_json(const Task& task);

}  // namespace modsynth::task
