#include "surface_import.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>

#include <modsynth/drawing/surface.h>
#include <modsynth/geometry/vec.h>
#include <modsynth/task/input_error.h>
#include <modsynth/task/limits.h>
#include <modsynth/task/spatial_strokes.h>
#include <modsynth/text/format.h>

#include "imported_task.h"

namespace modsynth::app {

namespace {

geometry::Vec3 facing_point(const task::SpatialTask& base) {
    if (base.base_regions.empty()) return geometry::Vec3::Zero();
    const geometry::Box3& b = base.base_regions.front();
    return (b.min + b.max) / 2.0;
}

/// The tool square into a plane: along -(u x v), into the side the drawing
/// is seen from.
void hold_square(task::SpatialTask& t, const drawing::PlaneSurface& plane, double tolerance) {
    task::ToolAxis axis;
    axis.direction = -plane.u.cross(plane.v).normalized();
    axis.tolerance = tolerance;
    axis.tolerance_given = true;
    t.tool_axis = axis;
}

/// The tool square into a cylinder: at its axis on the turns about it (and
/// on the lines along it, whose direction to the axis is fixed); a curve
/// fitted to the wrapped drawing points where the surface faces at its
/// middle, when the surface turns by at most half the tolerance along it.
void hold_square(task::SpatialTask& t, const drawing::CylinderSurface& c, double tolerance,
                 const std::string& option) {
    const auto inward = [&](const geometry::Vec3& p) {
        const geometry::Vec3 r = p - c.center;
        return geometry::Vec3(-(r - r.dot(c.axis) * c.axis).normalized());
    };
    t.tool_axes.assign(t.trajectory.size(), std::nullopt);
    for (std::size_t j = 0; j < t.trajectory.size(); ++j) {
        const geometry::Primitive3& p = t.trajectory[j];
        task::ToolAxis axis;
        axis.tolerance = tolerance;
        axis.tolerance_given = true;
        const auto turn = task::turn_axis(p);
        const bool about_axis = turn && turn->second.cross(c.axis).norm() <= 1e-9 &&
                                (turn->first - c.center).cross(c.axis).norm() <= 1e-9;
        if (about_axis) {
            axis.kind = task::ToolAxis::Kind::TowardAxis;
        } else {
            const double length = geometry::length(p);
            axis.direction = inward(geometry::point_at(p, length / 2.0));
            for (const geometry::Vec3& e : {geometry::start_point(p), geometry::end_point(p)}) {
                const double off = std::acos(std::clamp(inward(e).dot(axis.direction), -1.0, 1.0));
                if (off > tolerance / 2.0)
                    throw task::InputError(
                        option,
                        text::format(
                            "%s: the surface turns by %.2f degrees along it, "
                            "more than half the tool's tolerance; import "
                            "with a smaller --tolerance",
                            task::to_string(task::primitive_part(t, static_cast<int>(j))).c_str(),
                            off * 180.0 / geometry::kPi));
            }
        }
        t.tool_axes[j] = axis;
    }
}

}  // namespace

void SurfaceImport::check() const {
    if (!plane.empty()) drawing::plane_surface(plane, plane_option.c_str());
    if (!cylinder.empty())
        drawing::cylinder_surface(cylinder, geometry::Vec3::Zero(), cylinder_option.c_str());
}

double prepare_surface_import(drawing::ImportOptions& options, const SurfaceImport& surface) {
    if (!surface.placed()) return 0.0;
    options.placement.at = geometry::Vec2::Zero();
    if (surface.cylinder.empty()) return 0.0;
    options.tolerance /= 2.0;
    return options.tolerance;
}

nlohmann::json surface_task_json(drawing::ImportResult& r, const SurfaceImport& surface,
                                 const task::SpatialTask& base, double wrap_tolerance,
                                 drawing::Clock::time_point deadline) {
    drawing::PlacedStrokes placed;
    std::function<geometry::Vec3(const geometry::Vec2&)> to_space;
    if (!surface.plane.empty()) {
        const drawing::PlaneSurface plane =
            drawing::plane_surface(surface.plane, surface.plane_option.c_str());
        placed = drawing::place_on_plane(r.strokes, plane);
        to_space = [plane](const geometry::Vec2& p) { return drawing::surface_point(plane, p); };
    } else {
        const drawing::CylinderSurface cylinder = drawing::cylinder_surface(
            surface.cylinder, facing_point(base), surface.cylinder_option.c_str());
        placed =
            drawing::place_on_cylinder(r.strokes, cylinder, wrap_tolerance, task::kMaxPrimitives,
                                       deadline, surface.cylinder_option.c_str());
        to_space = [cylinder](const geometry::Vec2& p) {
            return drawing::surface_point(cylinder, p);
        };
    }
    // A circle of the obstacle layer keeps the pen off that much of the
    // surface: a sphere of its radius where its centre lands.
    std::vector<geometry::Obstacle3> obstacles;
    for (const geometry::Disc& d : r.obstacles)
        obstacles.push_back(geometry::Sphere{to_space(d.center), d.radius});
    r.deviation += placed.deviation;
    if (surface.tool.empty()) return imported_spatial_task_json(placed, obstacles, base);
    return imported_spatial_task_json(placed, obstacles, base, [&](task::SpatialTask& t) {
        if (!surface.plane.empty())
            hold_square(t, drawing::plane_surface(surface.plane, surface.plane_option.c_str()),
                        surface.tool_tolerance);
        else
            hold_square(t,
                        drawing::cylinder_surface(surface.cylinder, facing_point(base),
                                                  surface.cylinder_option.c_str()),
                        surface.tool_tolerance, "--tool");
    });
}

}  // namespace modsynth::app
