#pragma once
// The task an imported drawing becomes, as `modsynth import` writes it and
// POST /api/import answers it.
#include <nlohmann/json.hpp>

#include <modsynth/drawing/import.h>
#include <modsynth/task/task.h>

namespace modsynth::app {

/// One stroke as `trajectory`, several as `strokes`, with the drawing's
/// obstacles; the name, base regions and robot come from `base`. Every
/// stroke goes through the task reader, so what is returned is valid;
/// throws task::InputError naming the stroke otherwise.
nlohmann::json imported_task_json(const drawing::ImportResult& r, const task::Task& base);

}  // namespace modsynth::app
