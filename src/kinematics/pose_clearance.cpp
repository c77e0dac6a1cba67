#include <modsynth/kinematics/pose_clearance.h>

#include <modsynth/kinematics/clearance_rule.h>
#include <modsynth/kinematics/kinematics.h>

namespace modsynth::kinematics {

PoseClearance pose_clearance(std::span<const geometry::Disc> obstacles, const Robot& robot,
                             std::span<const double> q) {
    const std::vector<Vec2> s = forward(robot.base, robot.link_lengths, q);
    const ClearanceRule rule{robot.link_diameter};
    PoseClearance c;
    for (std::size_t k = 0; k + 1 < s.size(); ++k) {
        for (const geometry::Disc& o : obstacles)
            c.obstacles = std::min(c.obstacles, rule.link_margin(o, s[k], s[k + 1]));
        if (k + 2 < s.size()) c.self = std::min(c.self, rule.self_margin(s.back(), s[k], s[k + 1]));
    }
    return c;
}

}  // namespace modsynth::kinematics
