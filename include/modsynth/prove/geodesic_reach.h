#pragma once
// Proof by geodesic reach: an arm's links form a polygonal way through the
// free space (the plane minus the no-go discs) from its base to the
// end-effector, no longer than max(dof) * max_link_length. When the shortest
// such way from every point of a base region to a point of the path is
// longer, no arm reaches. Shortest ways among discs are made of tangent
// segments and arcs of the discs' circles (a visibility graph, exact
// geometry); the graph keeps every edge that rounding leaves in doubt, so
// its distances never exceed the true ones.
#include <modsynth/prove/no_go.h>
#include <modsynth/prove/wall_witness.h>
#include <modsynth/task/task.h>

#include <memory>
#include <optional>
#include <vector>

namespace modsynth::prove {

/// For every base region, a path point whose distance through the free
/// space (of the listed obstacles) from the region exceeds the reach;
/// nullopt when some region has none, when a region touches a no-go disc
/// (the proof needs the region free), or the task has no base regions.
/// Without `with_route`, a search stops as soon as its bound exceeds the
/// reach: the detours then carry that bound and no route.
std::optional<GeodesicWitness> prove_geodesic_reach(const task::Task& task,
                                                    const std::vector<int>& obstacles,
                                                    bool with_route = true);

/// The visibility graph of a set of obstacles, kept to try the proof among
/// subsets of them (what minimising a core does) without building it again.
class GeodesicProver {
public:
    GeodesicProver(const task::Task& task, const std::vector<int>& obstacles);
    ~GeodesicProver();
    GeodesicProver(const GeodesicProver&) = delete;
    GeodesicProver& operator=(const GeodesicProver&) = delete;

    /// prove_geodesic_reach among `among` (a subset of the constructor's
    /// obstacles), trying only the path points in `only` when it is not empty.
    std::optional<GeodesicWitness> prove(const std::vector<int>& among, bool with_route = true,
                                         const std::vector<PathPoint>& only = {}) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

/// Lower bound on the length of every way through the free space of `discs`
/// from a point of the box [lo, hi] to p, and the way that attains it.
double geodesic_distance(const std::vector<NoGoDisc>& discs, const geometry::Vec2& lo,
                         const geometry::Vec2& hi, const geometry::Vec2& p,
                         std::vector<RouteStep>* route = nullptr);

}  // namespace modsynth::prove
