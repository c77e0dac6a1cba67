#pragma once
#include <functional>
// The task an imported drawing becomes, as `modsynth import` writes it and
// POST /api/import answers it.
#include <nlohmann/json.hpp>

#include <modsynth/drawing/import.h>
#include <modsynth/drawing/surface.h>
#include <modsynth/task/spatial_task.h>
#include <modsynth/task/task.h>

namespace modsynth::app {

/// One stroke as `trajectory`, several as `strokes`, with the drawing's
/// obstacles; the name, base regions and robot come from `base`. The whole
/// task goes through the task reader once, so what is returned is valid;
/// throws task::InputError naming the part (`strokes[2][5]`, `obstacles`)
/// otherwise.
nlohmann::json imported_task_json(const drawing::ImportResult& r, const task::Task& base);

/// The same for a drawing placed on a surface in space (`import --plane`,
/// `--cylinder`): a spatial task with the placed strokes and obstacles;
/// the name, base regions and robot come from `base`. Checked by the
/// spatial task reader.
/// `finish` may add what depends on the placed trajectory (a tool axis per
/// primitive) before the task is written and checked.
nlohmann::json imported_spatial_task_json(
    const drawing::PlacedStrokes& placed, const std::vector<geometry::Obstacle3>& obstacles,
    const task::SpatialTask& base, const std::function<void(task::SpatialTask&)>& finish = {});

/// What POST /api/import answers for an imported drawing (README, "serve"):
/// the task, its counts, the deviation reached and the pen-up travel, the
/// placement, the map that puts the file's page under the task, the
/// warnings (what was skipped) and the layers with their entity counts.
nlohmann::json import_reply_json(const drawing::ImportResult& r,
                                 const drawing::ImportOptions& options, const task::Task& base);

/// The same for a drawing placed on a surface in space: `task` is its
/// spatial task (surface_import.h), `surface` "plane" or "cylinder",
/// `tolerance` the one asked for (round a cylinder the import's own is
/// half of it). No page lies under a task in space: `underlay` is null.
nlohmann::json surface_import_reply_json(const drawing::ImportResult& r,
                                         const drawing::ImportOptions& options,
                                         const nlohmann::json& task, const char* surface,
                                         double tolerance);

}  // namespace modsynth::app
