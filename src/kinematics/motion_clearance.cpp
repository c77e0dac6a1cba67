#include <modsynth/kinematics/motion_clearance.h>

#include <algorithm>
#include <limits>
#include <vector>

#include <modsynth/geometry/distance.h>
#include <modsynth/geometry/polygon.h>
#include <modsynth/kinematics/clearance_rule.h>
#include <modsynth/kinematics/kinematics.h>

namespace modsynth::kinematics {
namespace {

using geometry::Vec2;

double segment_polygon(const Vec2& a, const Vec2& b, const std::vector<Vec2>& poly) {
    if (geometry::point_in_convex_polygon(a, poly) || geometry::point_in_convex_polygon(b, poly))
        return 0.0;
    if (poly.size() == 1) return geometry::point_segment(poly[0], a, b);
    double d = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < poly.size(); ++i)
        d = std::min(d, geometry::segment_segment(a, b, poly[i], poly[(i + 1) % poly.size()]));
    return d;
}

}  // namespace

PoseClearance linear_motion_clearance(std::span<const geometry::Disc> obstacles, const Robot& robot,
                                      std::span<const double> qa, std::span<const double> qb) {
    const int n = robot.dof();
    const std::vector<Vec2> a = forward(robot.base, robot.link_lengths, qa);
    const std::vector<Vec2> b = forward(robot.base, robot.link_lengths, qb);
    const std::vector<double> pa = absolute_angles(qa), pb = absolute_angles(qb);
    const ClearanceRule rule{robot.link_diameter};
    std::vector<double> e(n);
    double acc = 0.0;
    for (int k = 0; k < n; ++k) {
        const double d = pb[k] - pa[k];
        acc += robot.link_lengths[k] * d * d;
        e[k] = acc;
    }
    PoseClearance c;
    for (int k = 0; k < n; ++k) {
        const std::vector<Vec2> hull = geometry::convex_hull({a[k], a[k + 1], b[k], b[k + 1]});
        for (const geometry::Disc& ob : obstacles)
            c.obstacles = std::min(c.obstacles, geometry::point_convex_polygon(ob.center, hull) -
                                                    e[k] / 8.0 - rule.obstacle_distance(ob));
        if (k < n - 1)
            c.self = std::min(c.self, segment_polygon(a[n], b[n], hull) - (e[n - 1] + e[k]) / 8.0 -
                                          rule.self_distance());
    }
    return c;
}

}  // namespace modsynth::kinematics
