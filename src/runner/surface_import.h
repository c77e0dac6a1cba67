#pragma once
// A drawing placed on a surface in space, as `modsynth import --plane` /
// `--cylinder` and POST /api/import with `plane` / `cylinder` make it: the
// drawing is imported in its own plane about its centre, then carried onto
// the plane or wrapped round the cylinder as a spatial task.
#include <string>

#include <modsynth/task/tool_axis.h>
#include <vector>

#include <nlohmann/json.hpp>

#include <modsynth/drawing/import.h>
#include <modsynth/task/spatial_task.h>

namespace modsynth::app {

struct SurfaceImport {
    std::vector<double> plane;     ///< --plane's nine numbers (origin, u, v), or none
    std::vector<double> cylinder;  ///< --cylinder's seven (centre, axis, radius), or none
    /// How errors name the two (`--plane` on the command line, `plane` in a
    /// query string).
    std::string plane_option = "--plane", cylinder_option = "--cylinder";
    /// "square": the task holds the tool square into the surface while it
    /// traces (formats.md "Tool orientation"), within `tool_tolerance` rad;
    /// empty: the tool is free.
    std::string tool;
    double tool_tolerance = task::kDefaultToolTolerance;

    bool placed() const { return !plane.empty() || !cylinder.empty(); }
    /// "plane" or "cylinder", as the reply says.
    const char* kind() const { return plane.empty() ? "cylinder" : "plane"; }
    /// Throws task::InputError naming the option when the numbers are not a
    /// surface (wrong count, directions not unit or not perpendicular, a
    /// radius that is not positive), before any drawing is read.
    void check() const;
};

/// The options to import the drawing with in its own plane: centred at the
/// origin, and round a cylinder with half the tolerance (the other half is
/// the wrapping's: it keeps lengths along the surface, so the two add at
/// most). Returns the tolerance left for the wrapping (0 on a plane).
double prepare_surface_import(drawing::ImportOptions& options, const SurfaceImport& surface);

/// The spatial task of the drawing `r` (imported with the prepared options)
/// on the surface; its strokes' obstacle circles become spheres where their
/// centres land. The name, base boxes and robot come from `base`; round a
/// cylinder the drawing faces the first base box's centre (else the
/// origin). Adds the placement's deviation to r.deviation. Throws
/// task::InputError naming the option (a drawing wider than the
/// circumference) or a part, drawing::ImportTimeout past `deadline`.
nlohmann::json surface_task_json(drawing::ImportResult& r, const SurfaceImport& surface,
                                 const task::SpatialTask& base, double wrap_tolerance,
                                 drawing::Clock::time_point deadline);

}  // namespace modsynth::app
