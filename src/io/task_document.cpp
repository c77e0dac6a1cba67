#include <modsynth/io/task_document.h>

#include <filesystem>

#include <nlohmann/json.hpp>

#include <modsynth/io/check_timeout.h>
#include <modsynth/io/input.h>
#include <modsynth/io/spatial_task_io.h>
#include <modsynth/io/task_checks.h>
#include <modsynth/io/task_io.h>
#include <modsynth/task/limits.h>

namespace modsynth::io {

bool is_spatial(const nlohmann::json& doc) {
    if (!doc.is_object()) return false;
    const auto it = doc.find("space");
    return it != doc.end() && it->is_string() && it->get<std::string>() == "3d";
}

TaskDocument parse_task_document(const nlohmann::json& doc, const run::Deadline& deadline) {
    if (is_spatial(doc)) return parse_spatial_task(doc, deadline);
    return parse_task(doc);
}

TaskDocument parse_task_document_text(std::string_view text, const run::Deadline& deadline) {
    if (text.size() > task::kMaxTaskBytes)
        throw task::InputError("(document)",
                               std::to_string(text.size()) + " bytes, more than the " +
                                   std::to_string(task::kMaxTaskBytes) + " allowed for a task");
    return parse_task_document(parse_json_text(text), deadline);
}

namespace {

void name_after_file(TaskDocument& doc, const std::string& path) {
    std::visit(
        [&](auto& t) {
            if (t.name.empty()) t.name = std::filesystem::path(path).stem().string();
        },
        doc);
}

// A check that did not end is said of the task, named after its file when
// it has no name of its own.
template <class Parse>
TaskDocument parse_checked(const std::string& path, Parse&& parse) {
    try {
        return read_document_file(path, parse);
    } catch (const CheckTimeout& e) {
        if (!e.task_name().empty()) throw;
        throw CheckTimeout(std::filesystem::path(path).stem().string(), e.doing());
    }
}

}  // namespace

TaskDocument load_task_document(const std::string& path, TaskWarnings& warnings,
                                const run::Deadline& deadline) {
    const nlohmann::json json = read_document_file(path, [](const std::string& p) {
        return parse_json_text(read_input_file(p, "task", task::kMaxTaskBytes));
    });
    for (const task::InputError& w : unknown_keys(json))
        warnings.unknown_keys.push_back(w.in_file(path));
    for (const task::InputError& w : unit_warnings(json)) warnings.units.push_back(w.in_file(path));
    TaskDocument doc = parse_checked(
        path, [&](const std::string&) { return parse_task_document(json, deadline); });
    name_after_file(doc, path);
    return doc;
}

TaskDocument load_task_document(const std::string& path, const run::Deadline& deadline) {
    TaskDocument doc = parse_checked(path, [&](const std::string& p) {
        return parse_task_document_text(read_input_file(p, "task", task::kMaxTaskBytes), deadline);
    });
    name_after_file(doc, path);
    return doc;
}

}  // namespace modsynth::io
