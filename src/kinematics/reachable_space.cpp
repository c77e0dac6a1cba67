#include <modsynth/kinematics/reachable_space.h>

#include <algorithm>
#include <cmath>

#include <modsynth/kinematics/clearance_rule.h>
#include <modsynth/kinematics/kinematics.h>

namespace modsynth::kinematics {
namespace {

bool link_clear(const std::vector<geometry::Disc>& obstacles, double diameter, const Vec2& a,
                const Vec2& b) {
    const ClearanceRule rule{diameter};
    for (const auto& o : obstacles) {
        if (rule.link_margin(o, a, b) < 0.0) return false;
    }
    return true;
}

bool branch_clear(const DistalPair& arm, const std::vector<geometry::Disc>& obstacles,
                  double diameter, const Vec2& p, int elbow) {
    const auto ik = inverse_two_link(arm.origin, arm.r1, arm.r2, p, elbow);
    if (!ik) return false;
    const Vec2 knee = arm.origin + arm.r1 * geometry::unit(ik->phi1);
    if (!link_clear(obstacles, diameter, arm.origin, knee)) return false;
    if (!link_clear(obstacles, diameter, knee, p)) return false;
    const ClearanceRule rule{diameter};
    if (rule.self_margin(p, arm.origin, knee) < 0.0) return false;
    for (const auto& [a, b] : arm.fixed_links) {
        if (!link_clear(obstacles, diameter, a, b)) return false;
        if (rule.self_margin(p, a, b) < 0.0) return false;
    }
    return true;
}

}  // namespace

DistalPair distal_pair(const Robot& robot, std::span<const double> q) {
    const int n = robot.dof();
    const std::vector<double> lengths(robot.link_lengths.begin(), robot.link_lengths.end() - 2);
    const std::vector<double> lead(q.begin(), q.begin() + (n - 2));
    const std::vector<Vec2> joints = forward(robot.base, lengths, lead);
    DistalPair arm;
    arm.origin = joints.back();
    arm.r1 = robot.link_lengths[n - 2];
    arm.r2 = robot.link_lengths[n - 1];
    for (std::size_t k = 0; k + 1 < joints.size(); ++k)
        arm.fixed_links.emplace_back(joints[k], joints[k + 1]);
    return arm;
}

bool reaches_clear(const DistalPair& arm, const std::vector<geometry::Disc>& obstacles,
                   double diameter, const Vec2& p) {
    return branch_clear(arm, obstacles, diameter, p, 1) ||
           branch_clear(arm, obstacles, diameter, p, -1);
}

double ReachGrid::fraction() const {
    if (reachable.empty()) return 0.0;
    std::size_t count = 0;
    for (unsigned char r : reachable) count += r;
    return static_cast<double>(count) / static_cast<double>(reachable.size());
}

ReachGrid reachable_space(const DistalPair& arm, const std::vector<geometry::Disc>& obstacles,
                          double diameter, const Vec2& min, const Vec2& max, double cell) {
    ReachGrid g;
    g.min = min;
    g.cell = cell;
    g.nx = std::max(1, static_cast<int>(std::ceil((max.x() - min.x()) / cell)));
    g.ny = std::max(1, static_cast<int>(std::ceil((max.y() - min.y()) / cell)));
    g.reachable.assign(static_cast<std::size_t>(g.nx * g.ny), 0);
    for (int j = 0; j < g.ny; ++j) {
        for (int i = 0; i < g.nx; ++i) {
            g.reachable[static_cast<std::size_t>(j * g.nx + i)] =
                reaches_clear(arm, obstacles, diameter, g.center(i, j)) ? 1 : 0;
        }
    }
    return g;
}

}  // namespace modsynth::kinematics
