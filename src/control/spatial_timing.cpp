#include <modsynth/control/spatial_timing.h>

#include <algorithm>
#include <cmath>

#include <modsynth/control/spatial_samples.h>
#include <modsynth/geometry/primitive3.h>
#include <modsynth/task/input_error.h>
#include <modsynth/text/format.h>

namespace modsynth::control {
namespace {

std::vector<double> spread(const std::vector<double>& values, int dof, const char* key) {
    if (values.size() == 1) return std::vector<double>(static_cast<std::size_t>(dof), values[0]);
    if (static_cast<int>(values.size()) != dof)
        throw task::InputError(std::string("robot.joint_limits.") + key,
                               text::format("has %d values, but the robot has %d joints",
                                            static_cast<int>(values.size()), dof));
    return values;
}

}  // namespace

JointLimits joint_limits_for(const task::SpatialTask& task, int dof) {
    const auto& spec = task.robot.joint_limits;
    if (!spec) return default_joint_limits(dof);
    return {spread(spec->velocity, dof, "velocity"),
            spread(spec->acceleration, dof, "acceleration"),
            spec->jerk.empty() ? std::vector<double>{} : spread(spec->jerk, dof, "jerk")};
}

std::vector<std::size_t> path_corners(const task::SpatialTask& task,
                                      const std::vector<Sample>& samples, double angle) {
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
        const auto& p = task.trajectory[static_cast<std::size_t>(j)];
        const geometry::Vec3 before = geometry::tangent_at(p, geometry::length(p));
        const geometry::Vec3 after =
            geometry::tangent_at(task.trajectory[static_cast<std::size_t>(j) + 1], 0.0);
        if (std::acos(std::clamp(before.dot(after), -1.0, 1.0)) > angle) out.push_back(i);
    }
    return out;
}

std::vector<Sample> retime_for(const task::SpatialTask& task, std::vector<Sample> samples,
                               const JointLimits& limits, const RetimeOptions& options,
                               RetimeStats* stats) {
    const std::vector<std::size_t> stops = path_corners(task, samples);
    return retime(std::move(samples), limits, options, stats, stops);
}

}  // namespace modsynth::control
