#include "planar_task.h"

#include <variant>

#include <nlohmann/json.hpp>

#include <modsynth/io/task_document.h>

namespace modsynth::app {

task::InputError spatial_not_supported(const std::string& command) {
    return task::InputError("space", "spatial tasks are not supported by " + command + " yet");
}

task::Task load_planar_task(const std::string& path, const std::string& command) {
    io::TaskDocument doc = io::load_task_document(path);
    if (std::holds_alternative<task::SpatialTask>(doc)) throw spatial_not_supported(command);
    return std::get<task::Task>(std::move(doc));
}

task::Task parse_planar_task(const nlohmann::json& doc, const std::string& command) {
    io::TaskDocument task = io::parse_task_document(doc);
    if (std::holds_alternative<task::SpatialTask>(task)) throw spatial_not_supported(command);
    return std::get<task::Task>(std::move(task));
}

}  // namespace modsynth::app
