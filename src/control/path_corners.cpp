#include <modsynth/control/path_corners.h>

#include <algorithm>
#include <cmath>

#include <modsynth/control/spatial_samples.h>
#include <modsynth/geometry/primitive.h>
#include <modsynth/geometry/primitive3.h>

namespace modsynth::control {

namespace {

/// The samples at junctions j -> j + 1 traced without a transition where
/// turn(j) (the tangent's turn there, rad) exceeds `angle`.
template <class Task, class Turn>
std::vector<std::size_t> corners(const Task& task, const std::vector<Sample>& samples, double angle,
                                 const Turn& turn) {
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
        if (turn(j) > angle) out.push_back(i);
    }
    return out;
}

template <class V>
double angle_between(const V& a, const V& b) {
    return std::acos(std::clamp(a.dot(b) / (a.norm() * b.norm()), -1.0, 1.0));
}

}  // namespace

std::vector<std::size_t> path_corners(const task::Task& task, const std::vector<Sample>& samples,
                                      double angle) {
    return corners(task, samples, angle, [&](int j) {
        const geometry::Primitive& p = task.trajectory[j];
        return angle_between(geometry::tangent_at(p, geometry::length(p)),
                             geometry::tangent_at(task.trajectory[j + 1], 0.0));
    });
}

std::vector<std::size_t> path_corners(const task::SpatialTask& task,
                                      const std::vector<Sample>& samples, double angle) {
    return corners(task, samples, angle, [&](int j) {
        const geometry::Primitive3& p = task.trajectory[j];
        return angle_between(geometry::tangent_at(p, geometry::length(p)),
                             geometry::tangent_at(task.trajectory[j + 1], 0.0));
    });
}

std::vector<Sample> retime_for(const task::Task& task, std::vector<Sample> samples,
                               const JointLimits& limits, const RetimeOptions& options,
                               RetimeStats* stats) {
    const std::vector<std::size_t> stops = path_corners(task, samples);
    return retime(std::move(samples), limits, options, stats, stops);
}

std::vector<Sample> retime_for(const task::SpatialTask& task, std::vector<Sample> samples,
                               const JointLimits& limits, const RetimeOptions& options,
                               RetimeStats* stats) {
    const std::vector<std::size_t> stops = path_corners(task, samples);
    return retime(std::move(samples), limits, options, stats, stops);
}

}  // namespace modsynth::control
