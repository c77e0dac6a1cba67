#pragma once
// The commands that take planar tasks only (solve, explain, export, ...)
// refuse a spatial one by name, exit 2, rather than misread it: "space:
// spatial tasks are not supported by solve yet".
#include <string>

#include <nlohmann/json_fwd.hpp>

#include <modsynth/task/input_error.h>
#include <modsynth/task/task.h>

namespace modsynth::app {

/// The planar task in the file; task::InputError naming `space` for a
/// spatial one, after it has been validated (so that a broken spatial task
/// is told what is broken first).
task::Task load_planar_task(const std::string& path, const std::string& command);
task::Task parse_planar_task(const nlohmann::json& doc, const std::string& command);

/// The error a command that takes planar tasks only gives a spatial one.
task::InputError spatial_not_supported(const std::string& command);

}  // namespace modsynth::app
