#include <modsynth/task/tool_axis.h>

#include <variant>

#include <modsynth/task/spatial_strokes.h>
#include <modsynth/task/spatial_task.h>

namespace modsynth::task {

std::optional<std::pair<geometry::Vec3, geometry::Vec3>> turn_axis(const geometry::Primitive3& p) {
    return std::visit(
        [](const auto& x) -> std::optional<std::pair<geometry::Vec3, geometry::Vec3>> {
            using T = std::decay_t<decltype(x)>;
            if constexpr (std::is_same_v<T, geometry::Line3>) {
                return std::nullopt;
            } else {
                static_assert(std::is_same_v<T, geometry::Arc3> ||
                              std::is_same_v<T, geometry::Circle3> ||
                              std::is_same_v<T, geometry::Helix3>);
                return std::pair{x.turn.center, x.turn.axis};
            }
        },
        p);
}

std::optional<geometry::Vec3> wanted_tool_axis(const ToolAxis& axis, const geometry::Primitive3& p,
                                               const geometry::Vec3& ee) {
    switch (axis.kind) {
        case ToolAxis::Kind::Direction:
            return geometry::Vec3(axis.direction.normalized());
        case ToolAxis::Kind::TowardAxis:
        case ToolAxis::Kind::AwayFromAxis: {
            const auto line = turn_axis(p);
            if (!line) return std::nullopt;
            const geometry::Vec3 r = ee - line->first;
            const geometry::Vec3 w = r - r.dot(line->second) * line->second;
            const double n = w.norm();
            if (!(n > 1e-12)) return std::nullopt;
            return geometry::Vec3((axis.kind == ToolAxis::Kind::TowardAxis ? -1.0 : 1.0) * w / n);
        }
    }
    return std::nullopt;
}

std::optional<WantedTool> wanted_tool(const SpatialTask& task, int j, const geometry::Vec3& ee) {
    const ToolAxis* axis = tool_axis_of(task, j);
    if (!axis) return std::nullopt;
    const auto direction =
        wanted_tool_axis(*axis, task.trajectory[static_cast<std::size_t>(j)], ee);
    if (!direction) return std::nullopt;
    return WantedTool{*direction, axis->tolerance};
}

TaskPart tool_axis_part(const SpatialTask& task, int j) {
    const bool own = !task.tool_axes.empty() && task.tool_axes[static_cast<std::size_t>(j)];
    return own ? primitive_part(task, j).with_field("tool_axis") : TaskPart::tool_axis();
}

}  // namespace modsynth::task
