#pragma once
// A task document of either kind: planar (formats.md base format) or
// spatial (`"space": "3d"`). Callers that take both read a TaskDocument and
// std::visit it; callers that take one kind only refuse the other by name.
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include <modsynth/run/deadline.h>
#include <modsynth/task/input_error.h>
#include <modsynth/task/spatial_task.h>
#include <modsynth/task/task.h>

namespace modsynth::io {

using TaskDocument = std::variant<task::Task, task::SpatialTask>;

/// Whether a document is a spatial task: an object whose `space` is "3d".
/// (Any other `space` is refused by the planar reader by name.)
bool is_spatial(const nlohmann::json& doc);

/// The checks of a spatial task's geometry stop at `deadline` with
/// io::CheckTimeout (io/check_timeout.h); by default they run to the end.
TaskDocument parse_task_document(const nlohmann::json& doc, const run::Deadline& deadline = {});
TaskDocument parse_task_document_text(std::string_view text, const run::Deadline& deadline = {});
/// A task file; a task without a name takes the file's name without its
/// extension, as io::load_task does (a CheckTimeout's task_name too).
TaskDocument load_task_document(const std::string& path, const run::Deadline& deadline = {});
/// What looks like a mistake in a task file (io/task_checks.h), each said
/// of the file.
struct TaskWarnings {
    std::vector<task::InputError> unknown_keys;
    std::vector<task::InputError> units;
};
/// The same, with the warnings about the file.
TaskDocument load_task_document(const std::string& path, TaskWarnings& warnings,
                                const run::Deadline& deadline = {});

}  // namespace modsynth::io
