#pragma once
// The strokes of a task (formats.md "Several strokes"): which primitives are
// traced without lifting the pen, and how the document names each one
// ("trajectory[j]" with one stroke written as `trajectory`, "strokes[s][k]"
// otherwise). Within a stroke consecutive primitives meet at a transition
// point; between strokes the arm travels freely.
#include <algorithm>
#include <cstddef>
#include <string>

#include <modsynth/task/part.h>
#include <modsynth/task/task.h>

namespace modsynth::task {

/// The task was written with `strokes` (even if it has only one).
inline bool has_strokes(const Task& task) { return !task.stroke_starts.empty(); }

inline int stroke_count(const Task& task) {
    return has_strokes(task) ? static_cast<int>(task.stroke_starts.size()) : 1;
}

/// Index in task.trajectory of stroke s's first primitive.
inline int stroke_first(const Task& task, int s) {
    return has_strokes(task) ? task.stroke_starts.at(static_cast<std::size_t>(s)) : 0;
}

/// Index in task.trajectory of stroke s's last primitive.
inline int stroke_last(const Task& task, int s) {
    return s + 1 < stroke_count(task) ? stroke_first(task, s + 1) - 1
                                      : static_cast<int>(task.trajectory.size()) - 1;
}

/// The stroke primitive j belongs to.
inline int stroke_of(const Task& task, int j) {
    if (!has_strokes(task)) return 0;
    const auto& st = task.stroke_starts;
    return static_cast<int>(std::upper_bound(st.begin(), st.end(), j) - st.begin()) - 1;
}

/// Primitive j's index within its stroke.
inline int index_in_stroke(const Task& task, int j) {
    return j - stroke_first(task, stroke_of(task, j));
}

/// Index in task.trajectory of primitive k of stroke s.
inline int primitive_index(const Task& task, int s, int k) { return stroke_first(task, s) + k; }

/// Whether primitive j ends its stroke: no transition follows it.
inline bool ends_stroke(const Task& task, int j) {
    return j == stroke_last(task, stroke_of(task, j));
}

/// Whether a transition point follows primitive j (the next primitive
/// continues the same stroke).
inline bool has_transition_after(const Task& task, int j) {
    return j + 1 < static_cast<int>(task.trajectory.size()) && !ends_stroke(task, j);
}

/// How the document names primitive j: "trajectory[j]" or "strokes[s][k]"
/// (task/part.h makes it a value).
inline std::string part_name(const Task& task, int j) {
    return to_string(TaskPart::primitive(task, j));
}

}  // namespace modsynth::task
