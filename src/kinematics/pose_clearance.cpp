#include <modsynth/kinematics/pose_clearance.h>

#include <modsynth/geometry/distance.h>
#include <modsynth/kinematics/kinematics.h>

namespace modsynth::kinematics {

PoseClearance pose_clearance(const task::Task& task, const Robot& robot, std::span<const double> q) {
    const std::vector<Vec2> s = forward(robot.base, robot.link_lengths, q);
    const double d = robot.link_diameter;
    PoseClearance c;
    for (std::size_t k = 0; k + 1 < s.size(); ++k) {
        for (const task::Obstacle& o : task.obstacles)
            c.obstacles = std::min(c.obstacles, geometry::point_segment(o.center, s[k], s[k + 1]) -
                                                    (o.radius + d / 2.0));
        if (k + 2 < s.size()) c.self = std::min(c.self, geometry::point_segment(s.back(), s[k], s[k + 1]) - d);
    }
    return c;
}

}  // namespace modsynth::kinematics
