#pragma once
// Where no part of any arm can be: each obstacle grown by the tube's radius.
// Every link (and so the base and the end-effector) keeps out of these open
// discs (formats.md, guarantee 3), whatever the joint count and lengths.
#include <modsynth/geometry/vec.h>
#include <modsynth/task/task.h>

#include <cstddef>
#include <vector>

namespace modsynth::prove {

struct NoGoDisc {
    geometry::Vec2 center = geometry::Vec2::Zero();
    double radius = 0.0;  ///< obstacle radius + link_diameter / 2
    int obstacle = 0;     ///< index into task.obstacles
};

/// Lengths (m) below which the obstacle proofs treat two discs as apart and a
/// point as free: rounding must never close a gap a tube could thread.
constexpr double kNoGoSlack = 1e-9;

/// Sizes beyond which the obstacle proofs are not tried, so that they stay
/// a matter of milliseconds before the front stage (src/prove/obstacle_proof.cpp).
constexpr std::size_t kMaxPathPoints = 24;
constexpr std::size_t kMaxWallObstacles = 400;
constexpr std::size_t kMaxDetourObstacles = 120;
constexpr std::size_t kMaxProofRegions = 10;
/// The 2-joint branch and bound only looks at the discs near each design
/// box, so it copes with more (src/prove/branch_and_bound.cpp).
constexpr std::size_t kMaxBranchObstacles = 200;

/// The no-go discs of the listed obstacles.
std::vector<NoGoDisc> no_go_discs(const task::Task& task, const std::vector<int>& obstacles);

/// Every obstacle index of the task.
std::vector<int> all_obstacles(const task::Task& task);

/// How deep two no-go discs overlap (m); > kNoGoSlack: no tube passes between.
double overlap(const NoGoDisc& a, const NoGoDisc& b);

/// Points of the path the end-effector must visit, as (primitive, point):
/// the start, middle and end of every primitive; on long paths at most
/// kMaxPathPoints of them, evenly spread (any point the arm must visit
/// serves a proof: fewer only make proofs rarer).
struct PathPoint {
    int primitive = 0;
    geometry::Vec2 point = geometry::Vec2::Zero();
};
std::vector<PathPoint> path_points(const task::Task& task);

/// Whether p is outside every disc by more than kNoGoSlack.
bool free_point(const std::vector<NoGoDisc>& discs, const geometry::Vec2& p);

}  // namespace modsynth::prove
