#pragma once
// The strokes of a task, planar or spatial (formats.md "Several strokes"):
// which primitives are traced without lifting the pen, and how the document
// names each one ("trajectory[j]" with one stroke written as `trajectory`,
// "strokes[s][k]" otherwise). Within a stroke consecutive primitives meet
// at a transition point; between strokes the arm travels freely.
//
// Both task types keep their primitives in one list, `trajectory`, split by
// `stroke_starts`; these functions take either.
#include <algorithm>
#include <concepts>
#include <cstddef>
#include <string>
#include <vector>

#include <modsynth/task/part.h>
#include <modsynth/task/task.h>

namespace modsynth::task {

/// A task whose primitives are one list split into strokes.
template <class T>
concept StrokedTask = requires(const T& t) {
    { t.trajectory.size() } -> std::convertible_to<std::size_t>;
    { t.stroke_starts } -> std::convertible_to<const std::vector<int>&>;
};

/// The task was written with `strokes` (even if it has only one).
template <StrokedTask T>
bool has_strokes(const T& task) {
    return !task.stroke_starts.empty();
}

template <StrokedTask T>
int stroke_count(const T& task) {
    return has_strokes(task) ? static_cast<int>(task.stroke_starts.size()) : 1;
}

/// Index in task.trajectory of stroke s's first primitive.
template <StrokedTask T>
int stroke_first(const T& task, int s) {
    return has_strokes(task) ? task.stroke_starts.at(static_cast<std::size_t>(s)) : 0;
}

/// Index in task.trajectory of stroke s's last primitive.
template <StrokedTask T>
int stroke_last(const T& task, int s) {
    return s + 1 < stroke_count(task) ? stroke_first(task, s + 1) - 1
                                      : static_cast<int>(task.trajectory.size()) - 1;
}

/// The stroke primitive j belongs to.
template <StrokedTask T>
int stroke_of(const T& task, int j) {
    if (!has_strokes(task)) return 0;
    const auto& st = task.stroke_starts;
    return static_cast<int>(std::upper_bound(st.begin(), st.end(), j) - st.begin()) - 1;
}

/// Primitive j's index within its stroke.
template <StrokedTask T>
int index_in_stroke(const T& task, int j) {
    return j - stroke_first(task, stroke_of(task, j));
}

/// Index in task.trajectory of primitive k of stroke s.
template <StrokedTask T>
int primitive_index(const T& task, int s, int k) {
    return stroke_first(task, s) + k;
}

/// Whether primitive j ends its stroke: no transition follows it.
template <StrokedTask T>
bool ends_stroke(const T& task, int j) {
    return j == stroke_last(task, stroke_of(task, j));
}

/// Whether a transition point follows primitive j (the next primitive
/// continues the same stroke).
template <StrokedTask T>
bool has_transition_after(const T& task, int j) {
    return j + 1 < static_cast<int>(task.trajectory.size()) && !ends_stroke(task, j);
}

/// Primitive j of task.trajectory as a part (task/part.h), named as the
/// document names it.
template <StrokedTask T>
TaskPart primitive_part(const T& task, int j) {
    if (!has_strokes(task)) return TaskPart::trajectory(j);
    const int s = stroke_of(task, j);
    return TaskPart::stroke_primitive(s, j - stroke_first(task, s));
}

/// "trajectory[j]" or "strokes[s][k]".
template <StrokedTask T>
std::string part_name(const T& task, int j) {
    return to_string(primitive_part(task, j));
}

}  // namespace modsynth::task
