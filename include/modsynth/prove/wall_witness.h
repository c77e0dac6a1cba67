#pragma once
// The data of an obstacle-infeasibility proof (formats.md, "explanation.
// separation" and "explanation.geodesic"): enough for a reader to re-check
// the claim with nothing but the task.
#include <modsynth/geometry/vec.h>

#include <vector>

namespace modsynth::prove {

/// A closed wall: obstacles whose tubes' no-go discs (radius + link_diameter
/// / 2) overlap in a cycle, so that the polygon through their centres lies
/// inside the discs. It separates `point` (on trajectory[primitive]) from
/// every free position in base_regions[base_region].
struct Wall {
    int base_region = 0;
    int primitive = 0;
    geometry::Vec2 point = geometry::Vec2::Zero();
    std::vector<int> cycle;  ///< obstacle indices in order around the wall
    std::vector<double>
        overlaps;  ///< depth of overlap of cycle[k] and cycle[k+1] (last: with cycle[0]), m
};

struct SeparationWitness {
    std::vector<Wall> walls;  ///< one per base region
};

/// One step of a route: reached `point` by a straight segment (around < 0)
/// or along the shorter arc of obstacle `around`'s no-go circle.
struct RouteStep {
    geometry::Vec2 point = geometry::Vec2::Zero();
    int around = -1;
};

/// The shortest way through the free space from a base region to a point of
/// the path; `lower_bound` is below the length of every way from any point of
/// the region, and above `reach`.
struct Detour {
    int base_region = 0;
    int primitive = 0;
    geometry::Vec2 point = geometry::Vec2::Zero();
    double lower_bound = 0.0;  ///< m
    std::vector<RouteStep> route;
};

struct GeodesicWitness {
    double reach = 0.0;  ///< max(robot.dof) * robot.max_link_length, m
    /// The obstacles the ways are measured among (the core's): the bound
    /// holds for the plane without just these, hence with all of them.
    std::vector<int> obstacles;
    std::vector<Detour> detours;  ///< one per base region
};

}  // namespace modsynth::prove
