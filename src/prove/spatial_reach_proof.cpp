#include <modsynth/prove/spatial_reach_proof.h>

#include <algorithm>
#include <limits>

#include <modsynth/geometry/curve_distance.h>
#include <modsynth/task/spatial_strokes.h>
#include <modsynth/text/format.h>

namespace modsynth::prove {
namespace {

/// m: the least, over the base boxes, of the primitive's largest distance
/// from a box: every base of every box has a point of the primitive at
/// least this far.
double least_far_distance(const task::SpatialTask& task, int j) {
    double least = std::numeric_limits<double>::infinity();
    for (const geometry::Box3& box : task.base_regions)
        least = std::min(least, geometry::largest_distance_to_box(
                                    task.trajectory[static_cast<std::size_t>(j)], box)
                                    .distance);
    return least;
}

double longest_chain(int dof, double max_link_length) { return dof * 2.0 * max_link_length; }

}  // namespace

std::optional<std::vector<task::TaskPart>> spatial_out_of_reach_core(
    const task::SpatialTask& task) {
    if (task.base_regions.empty() || task.robot.dof.empty()) return std::nullopt;
    const double reach = task.robot.longest_chain();
    // Of the primitives out of reach, the one farthest out: the part a user
    // has to move most.
    int farthest_out = -1;
    double most = reach + 1e-9;
    for (int j = 0; j < static_cast<int>(task.trajectory.size()); ++j) {
        const double d = least_far_distance(task, j);
        if (d > most) most = d, farthest_out = j;
    }
    if (farthest_out < 0) return std::nullopt;
    std::vector<task::TaskPart> core{task::TaskPart::robot(task::RobotKey::MaxLinkLength),
                                     task::TaskPart::base_regions(),
                                     task::primitive_part(task, farthest_out)};
    // robot.dof belongs when more joints than it allows would reach.
    if (!(most > longest_chain(task::kMaxSpatialDof, task.robot.max_link_length) + 1e-9))
        core.push_back(task::TaskPart::robot(task::RobotKey::Dof));
    return core;
}

std::string describe_spatial_reach(const task::SpatialTask& task,
                                   const std::vector<task::TaskPart>& core) {
    int j = -1;
    for (int k = 0; k < static_cast<int>(task.trajectory.size()); ++k)
        if (std::find(core.begin(), core.end(), task::primitive_part(task, k)) != core.end()) j = k;
    if (j < 0) return "a primitive is out of reach from every base region";
    const int dof = *std::max_element(task.robot.dof.begin(), task.robot.dof.end());
    return text::format(
        "%s is out of reach from every base region: wherever the base stands, some point of it "
        "lies at least %.3f m away, and no chain of %d joints with links of at most %.3f m "
        "reaches farther than %.3f m from its base (each link moves the EE by at most |a| + "
        "|d|).",
        task::part_name(task, j).c_str(), least_far_distance(task, j), dof,
        task.robot.max_link_length, longest_chain(dof, task.robot.max_link_length));
}

}  // namespace modsynth::prove
