#pragma once
// Samples read from a file carry no `s`: what both kinds of task recover of
// it the same way (transitions, travel, the snap to a primitive's ends),
// around how each finds the EE's place on its primitive.
#include <cmath>
#include <vector>

#include <modsynth/control/sample.h>

namespace modsynth::control {

/// `place(i, primitive, first)` gives trace sample i's arc length along
/// its primitive (task.trajectory[j]); `first` says it begins its run.
template <class Task, class Place>
void recover_parameters_with(const Task& task, std::vector<Sample>& samples, Place place) {
    constexpr double kSnap = 1e-5;
    for (std::size_t i = 0; i < samples.size(); ++i) {
        Sample& a = samples[i];
        if (a.phase == Phase::Transition) {
            a.s = a.q.empty() ? 0.0 : a.q[0];
            continue;
        }
        if (a.phase == Phase::Travel) {
            a.s = 0.0;
            continue;
        }
        const auto& prim = task.trajectory[static_cast<std::size_t>(primitive_index(task, a))];
        const double length = geometry::length(prim);
        double s = place(i, prim, starts_run(samples, i));
        if (std::abs(s) < kSnap) s = 0.0;
        if (std::abs(s - length) < kSnap) s = length;
        a.s = s;
    }
}

}  // namespace modsynth::control
