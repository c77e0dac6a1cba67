#pragma once
// Vectors and axis-aligned boxes in space, for spatial tasks (formats.md
// "Spatial tasks"): points are [x, y, z] in metres, z up.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace modsynth::geometry {

using Vec3 = Eigen::Vector3d;

/// v / |v| for any finite non-zero v: scaled by its largest component first,
/// so that neither a tiny nor a huge vector loses its direction to underflow
/// or overflow.
inline Vec3 unit_vector(const Vec3& v) { return (v / v.cwiseAbs().maxCoeff()).normalized(); }

/// A closed axis-aligned box, min <= max on every axis (a flat one is a
/// plate, a base region standing on a table).
struct Box3 {
    Vec3 min = Vec3::Zero();
    Vec3 max = Vec3::Zero();
    bool contains(const Vec3& p, double tolerance = 0.0) const {
        for (int i = 0; i < 3; ++i)
            if (!(p[i] >= min[i] - tolerance && p[i] <= max[i] + tolerance)) return false;
        return true;
    }
    Vec3 center() const { return 0.5 * (min + max); }
};

}  // namespace modsynth::geometry
