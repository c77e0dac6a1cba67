#include <modsynth/arms/pointing.h>

#include <cmath>

#include <modsynth/geometry/primitive3.h>
#include <modsynth/geometry/vec.h>
#include <modsynth/task/spatial_strokes.h>

namespace modsynth::arms {

AlongPins along_pins(const Family& family, const task::SpatialTask& task, int dof, int variant) {
    const int n = family.along_count(dof, variant);
    if (n <= 0 || !task::holds_tool(task)) return {};
    AlongPins out(task.trajectory.size());
    bool any = false;
    for (int j = 0; j < static_cast<int>(task.trajectory.size()); ++j) {
        auto& slots = out[static_cast<std::size_t>(j)];
        slots.assign(static_cast<std::size_t>(2 * n), std::nullopt);
        const auto& prim = task.trajectory[static_cast<std::size_t>(j)];
        const geometry::Vec3 ends[] = {geometry::start_point(prim), geometry::end_point(prim)};
        for (int e = 0; e < 2; ++e) {
            const auto wanted = task::wanted_tool(task, j, ends[e]);
            if (!wanted) continue;
            const auto values =
                family.pointing_along(dof, variant, wanted->direction, wanted->tolerance);
            for (int h = 0; h < n && h < static_cast<int>(values.size()); ++h) {
                slots[static_cast<std::size_t>(e * n + h)] = values[static_cast<std::size_t>(h)];
                any = any || values[static_cast<std::size_t>(h)].has_value();
            }
        }
    }
    return any ? out : AlongPins{};
}

void pin_along(const AlongPins& pins, const task::SpatialTask& task,
               std::vector<std::vector<double>>& along, int first, int last) {
    if (pins.empty()) return;
    const auto near = [](double v, double to) {
        return v + 2.0 * geometry::kPi * std::round((to - v) / (2.0 * geometry::kPi));
    };
    if (last < 0) last = task::stroke_count(task) - 1;
    const int from = task::stroke_first(task, first), to = task::stroke_last(task, last);
    for (int i = from; i <= to && i < static_cast<int>(along.size()); ++i) {
        const auto j = static_cast<std::size_t>(i);
        auto& v = along[j];
        const std::size_t n = v.size() / 2;
        const bool joined = i > task::stroke_first(task, task::stroke_of(task, i));
        for (std::size_t h = 0; h < n; ++h) {
            if (const auto& p = pins[j][h])
                v[h] = joined ? near(*p, along[j - 1][n + h]) : near(*p, v[h]);
            if (const auto& p = pins[j][n + h]) v[n + h] = near(*p, v[h]);
        }
    }
}

}  // namespace modsynth::arms
