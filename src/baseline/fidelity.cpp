#include <modsynth/baseline/fidelity.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <modsynth/geometry/distance.h>
#include <modsynth/geometry/primitive.h>
#include <modsynth/kinematics/chain_layout.h>
#include <modsynth/kinematics/kinematics.h>
#include <modsynth/kinematics/pose_clearance.h>
#include <modsynth/kinematics/reachable_space.h>
#include <modsynth/text/option_check.h>

namespace modsynth::baseline {
namespace {

using geometry::Vec2;

double distance_to_path(const task::Task& task, const Vec2& p) {
    double best = std::numeric_limits<double>::infinity();
    for (const auto& prim : task.trajectory)
        best = std::min(best, geometry::point_primitive(p, prim));
    return best;
}

double distance_to_trail(const std::vector<Vec2>& trail, const Vec2& p) {
    if (trail.size() == 1) return (trail.front() - p).norm();
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i + 1 < trail.size(); ++i)
        best = std::min(best, geometry::point_segment(p, trail[i], trail[i + 1]));
    return best;
}

bool reachable(const task::Task& task, const kinematics::Robot& robot, const Vec2& p,
               int proximal_steps) {
    const double d = robot.link_diameter;
    if (!robot.has_proximal_link())
        return kinematics::reaches_clear(kinematics::distal_pair(robot, {}), task.obstacles, d, p);
    std::vector<double> lead(robot.dof() - 2, 0.0);
    for (int i = 0; i < proximal_steps; ++i) {
        lead[0] = geometry::kTau * i / proximal_steps;
        if (kinematics::reaches_clear(kinematics::distal_pair(robot, lead), task.obstacles, d, p))
            return true;
    }
    return false;
}

}  // namespace

bool FidelityOptions::IsValid(std::string* error) const {
    return text::OptionCheck("FidelityOptions", error)
        .greater("max_joint_step", max_joint_step, 0.0)
        .greater("path_spacing", path_spacing, 0.0)
        .at_least("proximal_steps", proximal_steps, 1)
        .ok();
}

Fidelity measure_fidelity(const task::Task& task, const kinematics::Robot& robot,
                          const std::vector<std::vector<double>>& waypoints,
                          const FidelityOptions& options) {
    text::require_valid(options);
    Fidelity f;
    f.min_clearance = std::numeric_limits<double>::infinity();
    double deviation_sum = 0.0;
    auto visit = [&](const std::vector<double>& q) {
        const Vec2 ee = kinematics::forward(robot.base, robot.link_lengths, q).back();
        const double dev = distance_to_path(task, ee);
        deviation_sum += dev;
        if (dev > f.max_deviation || f.trail.empty()) {
            f.max_deviation = std::max(f.max_deviation, dev);
            f.worst_point = ee;
        }
        f.min_clearance =
            std::min(f.min_clearance, kinematics::pose_clearance(task.obstacles, robot, q).worst());
        f.trail.push_back(ee);
    };
    for (std::size_t w = 0; w < waypoints.size(); ++w) {
        if (w == 0) {
            visit(waypoints[0]);
            continue;
        }
        const std::vector<double>& a = waypoints[w - 1];
        const std::vector<double>& b = waypoints[w];
        double largest = 0.0;
        for (std::size_t j = 0; j < a.size(); ++j)
            largest = std::max(largest, std::abs(b[j] - a[j]));
        const int steps =
            std::max(1, static_cast<int>(std::ceil(largest / options.max_joint_step)));
        std::vector<double> q(a.size());
        for (int k = 1; k <= steps; ++k) {
            const double t = static_cast<double>(k) / steps;
            for (std::size_t j = 0; j < a.size(); ++j) q[j] = a[j] + t * (b[j] - a[j]);
            visit(q);
        }
    }
    if (!f.trail.empty()) f.mean_deviation = deviation_sum / static_cast<double>(f.trail.size());

    for (const auto& prim : task.trajectory) {
        const double len = geometry::length(prim);
        f.path_length += len;
        const int steps = std::max(1, static_cast<int>(std::ceil(len / options.path_spacing)));
        for (int k = 0; k <= steps; ++k) {
            const Vec2 p = geometry::point_at(prim, len * k / steps);
            if (!f.trail.empty())
                f.coverage_gap = std::max(f.coverage_gap, distance_to_trail(f.trail, p));
            if (!reachable(task, robot, p, options.proximal_steps)) {
                f.outside_points.push_back(p);
                if (k > 0) f.outside_length += len / steps;
            }
        }
    }
    return f;
}

}  // namespace modsynth::baseline
