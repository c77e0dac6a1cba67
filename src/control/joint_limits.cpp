#include <modsynth/control/joint_limits.h>

#include <cmath>

#include <modsynth/task/input_error.h>
#include <modsynth/text/format.h>

namespace modsynth::control {
namespace {

std::vector<double> spread(const std::vector<double>& values, int dof, const char* key) {
    if (values.size() == 1) return std::vector<double>(static_cast<std::size_t>(dof), values[0]);
    if (static_cast<int>(values.size()) != dof) {
        throw task::InputError(std::string("robot.joint_limits.") + key,
                               text::format("has %d values, but the robot has %d joints",
                                            static_cast<int>(values.size()), dof));
    }
    return values;
}

}  // namespace

JointLimits default_joint_limits(int dof) {
    const auto n = static_cast<std::size_t>(dof);
    return {std::vector<double>(n, kDefaultJointSpeed),
            std::vector<double>(n, kDefaultJointAcceleration)};
}

JointLimits joint_limits_for(const task::Task& task, int dof) {
    const auto& spec = task.robot.joint_limits;
    if (!spec) return default_joint_limits(dof);
    return {spread(spec->velocity, dof, "velocity"),
            spread(spec->acceleration, dof, "acceleration"),
            spec->jerk.empty() ? std::vector<double>{} : spread(spec->jerk, dof, "jerk")};
}

bool valid(const JointLimits& limits, std::string* error) {
    const auto fail = [&](const std::string& message) {
        if (error) *error = message;
        return false;
    };
    if (limits.velocity.empty()) return fail("JointLimits: no joints");
    if (limits.acceleration.size() != limits.velocity.size())
        return fail("JointLimits: one velocity and one acceleration per joint");
    if (!limits.jerk.empty() && limits.jerk.size() != limits.velocity.size())
        return fail("JointLimits: one jerk per joint, or none");
    for (std::size_t k = 0; k < limits.jerk.size(); ++k) {
        const double j = limits.jerk[k];
        if (!std::isfinite(j) || j <= 0.0)
            return fail(text::format(
                "JointLimits::jerk[%zu] must be a finite number greater than 0, got %g", k, j));
    }
    for (std::size_t k = 0; k < limits.velocity.size(); ++k) {
        const double v = limits.velocity[k], a = limits.acceleration[k];
        if (!std::isfinite(v) || v <= 0.0)
            return fail(
                text::format("JointLimits::velocity[%zu] must be a finite number greater "
                             "than 0, got %g",
                             k, v));
        if (!std::isfinite(a) || a <= 0.0)
            return fail(
                text::format("JointLimits::acceleration[%zu] must be a finite number "
                             "greater than 0, got %g",
                             k, a));
    }
    return true;
}

}  // namespace modsynth::control
