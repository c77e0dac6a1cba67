#pragma once
// A triangle mesh read from STL (ASCII or binary, as OpenSCAD writes it),
// and what the checks of a printed part ask of it: whether it is closed,
// its volume, centre and moments, and its section by a horizontal plane.
#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include <modsynth/geometry/vec.h>
#include <modsynth/geometry/vec3.h>

namespace modsynth::parts {

struct Mesh {
    std::vector<std::array<geometry::Vec3, 3>> triangles;  ///< in the file's units
};

/// Throws std::runtime_error naming `path` when it cannot be read or is not
/// an STL file.
Mesh read_stl(const std::string& path);
/// The same from the file's text (ASCII STL); `name` names it in errors.
Mesh parse_stl(const std::string& bytes, const std::string& name);

/// The edges of the mesh that are not shared by exactly two triangles
/// running along them in opposite directions (vertices compared exactly):
/// 0 for a closed, consistently oriented surface.
int bad_edges(const Mesh& mesh);

/// Of the solid the mesh bounds (divergence theorem over its triangles).
struct MassProperties {
    double volume = 0.0;  ///< units^3
    geometry::Vec3 centroid = geometry::Vec3::Zero();
    /// Second moments about the centroid, per unit density: the inertia
    /// tensor of the solid with density 1.
    Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
};

MassProperties mass_properties(const Mesh& mesh);

/// The closed loops where the plane z = `z` cuts the mesh, as polygons in
/// (x, y); where the surface is open, the cut is no loop and is left out.
/// `z` should pass through no vertex.
std::vector<std::vector<geometry::Vec2>> section(const Mesh& mesh, double z);

}  // namespace modsynth::parts
