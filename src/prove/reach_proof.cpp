#include <modsynth/prove/reach_proof.h>

#include <algorithm>
#include <limits>

#include <modsynth/geometry/farthest_reach.h>

namespace modsynth::prove {

std::optional<std::vector<task::TaskPart>> out_of_reach_core(const task::Task& task) {
    if (task.base_regions.empty() || task.robot.dof.empty()) return std::nullopt;
    const double longest_arm = task.robot.longest_arm();
    geometry::FarthestReachOptions options;
    options.tolerance = 1e-6;
    // Of the primitives out of reach, the one farthest out: the part a
    // user has to move most, and where a path runs out and back, the far
    // end rather than the way there.
    int farthest_out = -1;
    double most_excess = 1e-9;  // a primitive at full stretch is left to the front stage
    for (std::size_t j = 0; j < task.trajectory.size(); ++j) {
        const std::vector<geometry::Primitive> one{task.trajectory[j]};
        double excess = std::numeric_limits<double>::infinity();
        for (const task::BaseRegion& r : task.base_regions) {
            excess =
                std::min(excess, geometry::least_farthest_reach(one, r.min, r.max, options).lower -
                                     longest_arm);
            if (excess <= most_excess) break;
        }
        if (excess > most_excess) {
            most_excess = excess;
            farthest_out = static_cast<int>(j);
        }
    }
    if (farthest_out >= 0)
        return std::vector<task::TaskPart>{task::TaskPart::robot(task::RobotKey::MaxLinkLength),
                                           task::TaskPart::base_regions(),
                                           task::TaskPart::primitive(task, farthest_out)};
    return std::nullopt;
}

}  // namespace modsynth::prove
