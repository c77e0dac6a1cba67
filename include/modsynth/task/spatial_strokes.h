#pragma once
// The strokes of a spatial task and how the document names its primitives,
// as task/strokes.h says them for a planar task.
#include <algorithm>
#include <cstddef>
#include <string>

#include <modsynth/task/part.h>
#include <modsynth/task/spatial_task.h>

namespace modsynth::task {

inline bool has_strokes(const SpatialTask& task) { return !task.stroke_starts.empty(); }

inline int stroke_count(const SpatialTask& task) {
    return has_strokes(task) ? static_cast<int>(task.stroke_starts.size()) : 1;
}

/// Index in task.trajectory of stroke s's first primitive.
inline int stroke_first(const SpatialTask& task, int s) {
    return has_strokes(task) ? task.stroke_starts.at(static_cast<std::size_t>(s)) : 0;
}

/// Index in task.trajectory of stroke s's last primitive.
inline int stroke_last(const SpatialTask& task, int s) {
    return s + 1 < stroke_count(task) ? stroke_first(task, s + 1) - 1
                                      : static_cast<int>(task.trajectory.size()) - 1;
}

/// The stroke primitive j belongs to.
inline int stroke_of(const SpatialTask& task, int j) {
    if (!has_strokes(task)) return 0;
    const auto& st = task.stroke_starts;
    return static_cast<int>(std::upper_bound(st.begin(), st.end(), j) - st.begin()) - 1;
}

/// Whether primitive j ends its stroke: no transition follows it.
inline bool ends_stroke(const SpatialTask& task, int j) {
    return j == stroke_last(task, stroke_of(task, j));
}

/// Whether a transition point follows primitive j.
inline bool has_transition_after(const SpatialTask& task, int j) {
    return j + 1 < static_cast<int>(task.trajectory.size()) && !ends_stroke(task, j);
}

/// Primitive j of task.trajectory as a part (task/part.h), named as the
/// document names it, as TaskPart::primitive names a planar one.
inline TaskPart primitive_part(const SpatialTask& task, int j) {
    if (!has_strokes(task)) return TaskPart::trajectory(j);
    const int s = stroke_of(task, j);
    return TaskPart::stroke_primitive(s, j - stroke_first(task, s));
}

/// "trajectory[j]" or "strokes[s][k]".
inline std::string part_name(const SpatialTask& task, int j) {
    return to_string(primitive_part(task, j));
}

}  // namespace modsynth::task
