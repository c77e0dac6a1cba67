#include "imported_task.h"

#include <string>

#include <modsynth/io/task_io.h>
#include <modsynth/task/input_error.h>

namespace modsynth::app {

nlohmann::json imported_task_json(const drawing::ImportResult& r, const task::Task& base) {
    nlohmann::json doc;
    nlohmann::json strokes = nlohmann::json::array();
    for (std::size_t s = 0; s < r.strokes.size(); ++s) {
        // A task holding one stroke as its trajectory: how the task writer
        // and reader, which know trajectories, check and write each stroke.
        task::Task t = base;
        t.trajectory = r.strokes[s];
        t.obstacles = r.obstacles;
        const nlohmann::json one = io::to_json(t);
        try {
            io::parse_task(one);
        } catch (const task::InputError& e) {
            throw task::InputError("strokes[" + std::to_string(s) + "]", e.what());
        }
        if (s == 0) doc = one;
        strokes.push_back(one["trajectory"]);
    }
    if (r.strokes.size() > 1) {
        doc.erase("trajectory");
        doc["strokes"] = strokes;
    }
    return doc;
}

}  // namespace modsynth::app
