#include <modsynth/control/motion.h>

#include <algorithm>
#include <cmath>

#include <modsynth/geometry/primitive.h>
#include <modsynth/kinematics/kinematics.h>

namespace modsynth::control {
namespace {

double largest_change(const std::vector<double>& a, const std::vector<double>& b) {
    double m = 0.0;
    for (std::size_t k = 0; k < a.size(); ++k) m = std::max(m, std::abs(b[k] - a[k]));
    return m;
}

std::string point_name(int j, double s) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "trajectory[%d] at %.4f m from its start", j, s);
    return buf;
}

}  // namespace

std::optional<std::vector<double>> configuration_at(const task::Task& task,
                                                    const kinematics::Robot& robot, int j,
                                                    double s,
                                                    const std::vector<double>* previous) {
    const geometry::Vec2 p = geometry::point_at(task.trajectory[j], s);
    if (robot.dof() != 2) return std::nullopt;
    const auto ik = kinematics::inverse_two_link(robot.base, robot.link_lengths[0],
                                                 robot.link_lengths[1], p, robot.elbow);
    if (!ik) return std::nullopt;
    std::vector<double> q{ik->phi1, ik->q2};
    if (previous) {
        for (std::size_t k = 0; k < q.size(); ++k) q[k] = kinematics::unwrap_near(q[k], (*previous)[k]);
    }
    return q;
}

std::optional<std::vector<Sample>> plan_motion(const task::Task& task,
                                               const kinematics::Robot& robot,
                                               const MotionOptions& options, std::string* where) {
    std::vector<Sample> out;
    const std::vector<double>* prev = nullptr;
    for (int j = 0; j < static_cast<int>(task.trajectory.size()); ++j) {
        const double length = geometry::length(task.trajectory[j]);
        auto q = configuration_at(task, robot, j, 0.0, prev);
        if (!q) {
            if (where) *where = point_name(j, 0.0);
            return std::nullopt;
        }
        out.push_back({0.0, Phase::Trace, j, 0.0, *q});
        double s = 0.0;
        double ds = options.max_ee_step;
        while (s < length) {
            // Shrink the step until no joint moves more than allowed; grow it
            // back afterwards so easy stretches are not over-sampled.
            ds = std::min({options.max_ee_step, 2.0 * ds, length - s});
            std::optional<std::vector<double>> next;
            for (int attempt = 0; attempt < 60; ++attempt) {
                next = configuration_at(task, robot, j, s + ds, &out.back().q);
                if (!next) break;
                const double change = largest_change(out.back().q, *next);
                if (change <= options.max_joint_step) break;
                ds *= std::max(0.1, 0.9 * options.max_joint_step / change);
                next.reset();
                if (ds < 1e-9) break;
            }
            if (!next) {
                if (where) *where = point_name(j, s + ds);
                return std::nullopt;
            }
            s = (length - s - ds <= 1e-12) ? length : s + ds;
            out.push_back({0.0, Phase::Trace, j, s, *next});
        }
        prev = &out.back().q;
    }
    return out;
}

bool refine_motion(const task::Task& task, const kinematics::Robot& robot,
                   std::vector<Sample>& samples, const std::vector<int>& pairs) {
    std::vector<int> sorted = pairs;
    std::sort(sorted.rbegin(), sorted.rend());  // back to front keeps indices valid
    for (int i : sorted) {
        const Sample& a = samples[i];
        const Sample& b = samples[i + 1];
        if (a.phase != Phase::Trace || b.phase != Phase::Trace || a.primitive != b.primitive)
            return false;
        const double s = 0.5 * (a.s + b.s);
        auto q = configuration_at(task, robot, a.primitive, s, &a.q);
        if (!q) return false;
        Sample mid{a.t, Phase::Trace, a.primitive, s, *q};
        samples.insert(samples.begin() + i + 1, mid);
    }
    return true;
}

void assign_times(std::vector<Sample>& samples, const MotionOptions& options) {
    if (samples.empty()) return;
    samples[0].t = 0.0;
    for (std::size_t i = 1; i < samples.size(); ++i) {
        const Sample& a = samples[i - 1];
        Sample& b = samples[i];
        const double path = (a.phase == Phase::Trace && b.phase == Phase::Trace &&
                             a.primitive == b.primitive)
                                ? std::abs(b.s - a.s)
                                : 0.0;
        const double dt = std::max(path / options.ee_speed,
                                   largest_change(a.q, b.q) / options.joint_speed);
        // Microsecond resolution keeps the files readable; rounding is
        // monotone, so t stays non-decreasing.
        b.t = std::round((a.t + dt) * 1e6) / 1e6;
    }
}

}  // namespace modsynth::control
