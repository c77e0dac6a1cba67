#pragma once
// Obstacles of spatial tasks (formats.md "Spatial tasks"): spheres,
// capsules (every point within a radius of a segment: a post, a pipe, an
// edge) and axis-aligned boxes (a table, a wall, a fixture), as one
// std::variant, and the distances from the chain's segments to them.
#include <array>
#include <cstddef>
#include <span>
#include <variant>

#include <modsynth/geometry/vec3.h>

namespace modsynth::geometry {

struct Sphere {
    Vec3 center = Vec3::Zero();
    double radius = 0.0;
};

struct Capsule {
    Vec3 a = Vec3::Zero();
    Vec3 b = Vec3::Zero();
    double radius = 0.0;
};

using Obstacle3 = std::variant<Sphere, Capsule, Box3>;

/// "sphere", "capsule" or "box", as in the task document.
const char* type_name(const Obstacle3& o);

/// Distance from p to the obstacle's surface: negative inside a sphere or a
/// capsule (by how much), 0 inside a box.
double point_gap(const Vec3& p, const Obstacle3& o);
/// Distance from segment ab to the obstacle's surface, as formats.md
/// measures clearance: dist(segment, center) - r for a sphere,
/// dist(segment, axis) - r for a capsule (both negative inside), and
/// dist(segment, box) for a box (0 when they meet). Exact for parallel,
/// degenerate and point-like segments.
double segment_gap(const Vec3& a, const Vec3& b, const Obstacle3& o);

/// The obstacle as the points within `radius` of the convex hull of
/// `points`: a sphere's centre, a capsule's axis, a box's eight corners
/// (radius 0). Distances to moving links are bounded through it
/// (geometry::hull_distance).
struct ObstacleCore {
    std::array<Vec3, 8> points{};
    std::size_t count = 0;
    double radius = 0.0;
    std::span<const Vec3> span() const { return {points.data(), count}; }
};
ObstacleCore core_of(const Obstacle3& o);

/// A ball holding the obstacle, for quick rejections.
Sphere bounding_sphere(const Obstacle3& o);

}  // namespace modsynth::geometry
