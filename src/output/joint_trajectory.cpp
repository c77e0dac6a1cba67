#include <modsynth/output/joint_trajectory.h>

#include <cmath>
#include <stdexcept>

#include <modsynth/output/urdf.h>
#include <modsynth/text/format.h>

namespace modsynth::output {
namespace {

std::string list(const std::vector<double>& values) {
    std::string out = "[";
    for (std::size_t k = 0; k < values.size(); ++k)
        out += (k ? ", " : "") + text::format("%.9f", values[k]);
    return out + "]";
}

}  // namespace

std::string joint_trajectory_yaml(const synth::Solution& solution) {
    if (solution.samples.empty())
        throw std::invalid_argument("joint trajectory: the solution has no samples");
    const std::size_t dof = solution.samples[0].q.size();
    std::string out =
        "# trajectory_msgs/msg/JointTrajectory; angles in rad, rates in rad/s and rad/s^2\n"
        "header:\n  stamp:\n    sec: 0\n    nanosec: 0\n  frame_id: \"\"\njoint_names: [";
    for (std::size_t k = 0; k < dof; ++k)
        out += (k ? ", " : "") + urdf_joint_name(static_cast<int>(k));
    out += "]\npoints:\n";
    for (std::size_t i = 0; i < solution.samples.size(); ++i) {
        const control::Sample& s = solution.samples[i];
        if (s.qd.size() != dof || s.qdd.size() != dof)
            throw std::invalid_argument(text::format(
                "joint trajectory: samples[%zu] has no velocities or accelerations; the motion "
                "is not timed",
                i));
        // Whole nanoseconds, as builtin_interfaces/Duration holds them: its
        // seconds are 32 bits, and a negative time means nothing here.
        if (!(s.t >= 0.0 && s.t <= 2147483647.0))
            throw std::invalid_argument(text::format(
                "joint trajectory: samples[%zu] is at t = %g s, which a Duration cannot hold", i,
                s.t));
        const long long ns = std::llround(s.t * 1e9);
        out += "  - positions: " + list(s.q) + "\n    velocities: " + list(s.qd) +
               "\n    accelerations: " + list(s.qdd) + "\n    effort: []\n" +
               text::format("    time_from_start:\n      sec: %lld\n      nanosec: %lld\n",
                            ns / 1'000'000'000LL, ns % 1'000'000'000LL);
    }
    return out;
}

}  // namespace modsynth::output
