#pragma once
// Reading and writing spatial task documents (formats.md "Spatial tasks",
// `"space": "3d"`). The reader validates every rule of the contract and
// throws task::InputError naming the offending part
// ("trajectory[2].normal: not perpendicular to start - center (0.004 m)").
#include <string>
#include <string_view>

#include <nlohmann/json_fwd.hpp>

#include <modsynth/run/deadline.h>
#include <modsynth/task/input_error.h>
#include <modsynth/task/spatial_task.h>

namespace modsynth::io {

/// A modsynth-task/1 document with `"space": "3d"`; one without it (or with
/// "plane") is refused naming `space`: it is a planar task (io::parse_task).
/// Checking that the path keeps off the obstacles costs primitives x turns
/// x obstacles: it stops at `deadline` with io::CheckTimeout
/// (io/check_timeout.h); by default it runs to the end.
task::SpatialTask parse_spatial_task(const nlohmann::json& doc, const run::Deadline& deadline = {});
task::SpatialTask parse_spatial_task_text(std::string_view text,
                                          const run::Deadline& deadline = {});
task::SpatialTask load_spatial_task(const std::string& path, const run::Deadline& deadline = {});
/// The task as a document (round-trips through parse_spatial_task).
nlohmann::json to_json(const task::SpatialTask& task);

}  // namespace modsynth::io
