#include <modsynth/kinematics/clearance_rule.h>

#include <modsynth/geometry/distance.h>

namespace modsynth::kinematics {

double ClearanceRule::link_margin(const geometry::Disc& obstacle, const geometry::Vec2& a,
                                  const geometry::Vec2& b) const {
    return geometry::point_segment(obstacle.center, a, b) - obstacle_distance(obstacle);
}

double ClearanceRule::self_margin(const geometry::Vec2& ee, const geometry::Vec2& a,
                                  const geometry::Vec2& b) const {
    return geometry::point_segment(ee, a, b) - self_distance();
}

}  // namespace modsynth::kinematics
