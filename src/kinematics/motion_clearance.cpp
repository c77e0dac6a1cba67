#include <modsynth/kinematics/motion_clearance.h>

#include <algorithm>
#include <limits>
#include <vector>

#include <modsynth/geometry/distance.h>
#include <modsynth/geometry/polygon.h>
#include <modsynth/kinematics/clearance_rule.h>
#include <modsynth/kinematics/kinematics.h>

namespace modsynth::kinematics {
using geometry::Vec2;

std::vector<double> sweep_bounds(const Robot& robot, std::span<const double> phi_a,
                                 std::span<const double> phi_b) {
    std::vector<double> e(phi_a.size());
    double acc = 0.0;
    for (std::size_t k = 0; k < e.size(); ++k) {
        const double d = phi_b[k] - phi_a[k];
        acc += robot.link_lengths[k] * d * d;
        e[k] = acc;
    }
    return e;
}

PoseClearance linear_motion_clearance(std::span<const geometry::Disc> obstacles, const Robot& robot,
                                      std::span<const double> qa, std::span<const double> qb) {
    const int n = robot.dof();
    const std::vector<Vec2> a = forward(robot.base, robot.link_lengths, qa);
    const std::vector<Vec2> b = forward(robot.base, robot.link_lengths, qb);
    const std::vector<double> pa = absolute_angles(qa), pb = absolute_angles(qb);
    const ClearanceRule rule{robot.link_diameter};
    const std::vector<double> e = sweep_bounds(robot, pa, pb);
    PoseClearance c;
    for (int k = 0; k < n; ++k) {
        const std::vector<Vec2> hull = geometry::convex_hull({a[k], a[k + 1], b[k], b[k + 1]});
        for (const geometry::Disc& ob : obstacles)
            c.obstacles = std::min(c.obstacles, geometry::point_convex_polygon(ob.center, hull) -
                                                    e[k] / 8.0 - rule.obstacle_distance(ob));
        if (k < n - 1)
            c.self = std::min(c.self, geometry::segment_convex_polygon(a[n], b[n], hull) -
                                          (e[n - 1] + e[k]) / 8.0 - rule.self_distance());
    }
    return c;
}

}  // namespace modsynth::kinematics
