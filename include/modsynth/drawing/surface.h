#pragma once
// A drawing placed on a surface in space: on a plane (a wall, a tilted
// easel) or wrapped round a cylinder (a label on a bottle, a seam round a
// pipe). The drawing is imported in its own plane first (import.h), its
// centre at the origin; these maps carry its strokes onto the surface as
// the primitives of a spatial task (formats.md "Spatial tasks").
#include <cstddef>
#include <vector>

#include <modsynth/drawing/deadline.h>
#include <modsynth/drawing/stroke_order.h>
#include <modsynth/geometry/primitive3.h>
#include <modsynth/geometry/vec3.h>

namespace modsynth::drawing {

using geometry::Vec2;
using geometry::Vec3;
using Chain3 = std::vector<geometry::Primitive3>;

/// How far from unit length and from perpendicular the directions of
/// --plane may be (|1 - |u|| and |u . v|): enough for directions typed with
/// four digits (0.7071 for sqrt(1/2)); they are then made exactly
/// orthonormal, so the drawing is placed without distortion.
constexpr double kDirectionTolerance = 1e-3;

/// The drawing's point (x, y) goes to origin + x u + y v; u and v are
/// orthonormal, and the drawing reads unmirrored seen from the side
/// u x v points to.
struct PlaneSurface {
    Vec3 origin = Vec3::Zero();
    Vec3 u = Vec3::UnitX();
    Vec3 v = Vec3::UnitY();
};

/// The drawing's x runs round the axis, its y along it: (x, y) goes to
/// center + y axis + radius (cos(x / radius) facing + sin(x / radius)
/// axis x facing). The drawing's centre lies on the side `facing` points
/// to and reads unmirrored seen from outside.
struct CylinderSurface {
    Vec3 center = Vec3::Zero();  ///< the point of the axis level with the drawing's centre
    Vec3 axis = Vec3::UnitZ();   ///< unit
    double radius = 0.0;
    Vec3 facing = Vec3::UnitX();  ///< unit, perpendicular to axis
};

/// From --plane's nine numbers (origin, u, v); throws task::InputError
/// naming `option` when u or v is not unit or they are not perpendicular
/// within kDirectionTolerance, or a number is not finite.
PlaneSurface plane_surface(const std::vector<double>& numbers, const char* option = "--plane");

/// From --cylinder's seven numbers (center, axis of any non-zero length,
/// radius > 0). The drawing faces `towards` (the base): `facing` is the
/// direction from the axis to it; when the axis runs through it, the
/// direction perpendicular to the axis nearest world x (y for an axis
/// along x). Throws task::InputError naming `option`.
CylinderSurface cylinder_surface(const std::vector<double>& numbers, const Vec3& towards,
                                 const char* option = "--cylinder");

Vec3 surface_point(const PlaneSurface& s, const Vec2& p);
Vec3 surface_point(const CylinderSurface& s, const Vec2& p);
/// The image on the cylinder of the drawing's direction t at p (unit when
/// t is: the wrapping keeps lengths along the surface).
Vec3 surface_direction(const CylinderSurface& s, const Vec2& p, const Vec2& t);

struct PlacedStrokes {
    std::vector<Chain3> strokes;
    /// The largest distance found between the placed primitives and the
    /// drawing's strokes carried onto the surface exactly, metres.
    double deviation = 0.0;
};

/// Exact: lines stay lines, arcs and circles turn about u x v.
PlacedStrokes place_on_plane(const std::vector<Chain>& strokes, const PlaneSurface& s);

/// A line along the axis stays a line, one round it becomes an arc (a
/// circle) about the axis, any other a helix; arcs, circles and lines
/// whose helix would climb less than formats.md's 0.005 m per turn are
/// fitted with 3-D biarcs (tangent-continuous where the drawing is) within
/// `tolerance`. Throws task::InputError naming `option` for a drawing wider
/// than the circumference or one that needs more than `max_primitives`,
/// ImportTimeout past `deadline`.
PlacedStrokes place_on_cylinder(const std::vector<Chain>& strokes, const CylinderSurface& s,
                                double tolerance, std::size_t max_primitives,
                                Clock::time_point deadline = kNoDeadline,
                                const char* option = "--cylinder");

/// The extent in x of the strokes (exact for lines, arcs and circles).
double drawing_width(const std::vector<Chain>& strokes);

}  // namespace modsynth::drawing
