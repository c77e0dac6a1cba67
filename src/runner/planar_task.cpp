#include "planar_task.h"

#include <variant>

#include <nlohmann/json.hpp>

#include <modsynth/io/check_timeout.h>
#include <modsynth/io/task_document.h>

namespace modsynth::app {

task::InputError spatial_not_supported(const std::string& command) {
    return task::InputError("space", "spatial tasks are not supported by " + command + " yet");
}

// A spatial task is refused without checking its geometry (hours for a
// long path among many obstacles): an expired deadline stops those checks
// at once, and only a spatial task's reader looks at it.
task::Task load_planar_task(const std::string& path, const std::string& command) {
    try {
        io::TaskDocument doc = io::load_task_document(path, run::Deadline::in(0.0));
        if (std::holds_alternative<task::SpatialTask>(doc)) throw spatial_not_supported(command);
        return std::get<task::Task>(std::move(doc));
    } catch (const io::CheckTimeout&) {
        throw spatial_not_supported(command);
    }
}

task::Task parse_planar_task(const nlohmann::json& doc, const std::string& command) {
    try {
        io::TaskDocument task = io::parse_task_document(doc, run::Deadline::in(0.0));
        if (std::holds_alternative<task::SpatialTask>(task)) throw spatial_not_supported(command);
        return std::get<task::Task>(std::move(task));
    } catch (const io::CheckTimeout&) {
        throw spatial_not_supported(command);
    }
}

}  // namespace modsynth::app
