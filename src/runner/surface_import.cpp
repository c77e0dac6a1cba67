#include "surface_import.h"

#include <functional>

#include <modsynth/drawing/surface.h>
#include <modsynth/task/limits.h>

#include "imported_task.h"

namespace modsynth::app {

namespace {

geometry::Vec3 facing_point(const task::SpatialTask& base) {
    if (base.base_regions.empty()) return geometry::Vec3::Zero();
    const geometry::Box3& b = base.base_regions.front();
    return (b.min + b.max) / 2.0;
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
    return imported_spatial_task_json(placed, obstacles, base);
}

}  // namespace modsynth::app
