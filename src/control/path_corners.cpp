#include <modsynth/control/path_corners.h>

#include <algorithm>
#include <cmath>

#include <modsynth/geometry/primitive.h>

namespace modsynth::control {

std::vector<std::size_t> path_corners(const task::Task& task, const std::vector<Sample>& samples,
                                      double angle) {
    std::vector<std::size_t> out;
    const int m = static_cast<int>(task.trajectory.size());
    for (std::size_t i = 0; i + 1 < samples.size(); ++i) {
        const Sample& a = samples[i];
        const Sample& b = samples[i + 1];
        if (a.phase != Phase::Trace || b.phase != Phase::Trace || a.stroke != b.stroke ||
            b.primitive != a.primitive + 1)
            continue;
        const int j = primitive_index(task, a);
        if (j < 0 || j + 1 >= m) continue;
        const geometry::Primitive& p = task.trajectory[j];
        const geometry::Vec2 before = geometry::tangent_at(p, geometry::length(p));
        const geometry::Vec2 after = geometry::tangent_at(task.trajectory[j + 1], 0.0);
        const double cos = before.dot(after) / (before.norm() * after.norm());
        if (std::acos(std::clamp(cos, -1.0, 1.0)) > angle) out.push_back(i);
    }
    return out;
}

std::vector<Sample> retime_for(const task::Task& task, std::vector<Sample> samples,
                               const JointLimits& limits, const RetimeOptions& options,
                               RetimeStats* stats) {
    const std::vector<std::size_t> stops = path_corners(task, samples);
    return retime(std::move(samples), limits, options, stats, stops);
}

}  // namespace modsynth::control
