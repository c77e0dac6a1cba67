#pragma once
// How short an arm can be: whatever its joints, an arm whose base stands at b
// reaches no farther than its total link length, so that length is at least
// F(b) = max over the path of |p - b|. The least F over a box bounds the
// total length of every arm with its base in the box, from below.
#include <vector>

#include <modsynth/geometry/primitive.h>

namespace modsynth::geometry {

struct FarthestReachOptions {
    /// m: the search stops once its bound is within this of the least F it
    /// has seen at a point of the box.
    double tolerance = 1e-4;
    /// Evaluations of F, at most; past them the bound is looser, never wrong.
    int max_evaluations = 4000;
    /// Primitives visited over all evaluations (each visits every one), at
    /// most: on the longest paths fewer evaluations keep the bound to
    /// milliseconds. At least 16 evaluations are made whatever the path.
    double max_visits = 4e6;
};

struct FarthestReach {
    /// min over the box of F, from below (proved: F is convex, so each
    /// evaluation's subgradient bounds F over its whole cell).
    double lower = 0.0;
    /// F at `at`, a point of the box: the least value seen.
    double upper = 0.0;
    Vec2 at = Vec2::Zero();
};

/// The least farthest-point distance F from a point of the box [lo, hi] to
/// the path. `path` must not be empty; lo <= hi.
FarthestReach least_farthest_reach(const std::vector<Primitive>& path, const Vec2& lo,
                                   const Vec2& hi, const FarthestReachOptions& options = {});
/// The same over the whole plane: the radius of the least circle enclosing
/// the path, from below.
FarthestReach least_farthest_reach(const std::vector<Primitive>& path,
                                   const FarthestReachOptions& options = {});

}  // namespace modsynth::geometry
