#pragma once
// `solve` on a spatial task (formats.md "Spatial tasks"): the spatial
// synthesis, its progress on stderr, its summary on stdout and the
// solution file, with the exit codes of the plane.
#include <chrono>
#include <limits>
#include <string>

#include <modsynth/output/exports.h>
#include <modsynth/task/spatial_task.h>

namespace modsynth::app {

/// What both solve paths take from the command line (the planar one adds
/// its own options, cmd_solve.cpp).
struct SolveRequest {
    std::string output;
    double time_limit = 60.0;
    unsigned seed = 0;
    /// Caps on top of the joint limits; infinity: none.
    double ee_speed = std::numeric_limits<double>::infinity();
    double joint_speed = std::numeric_limits<double>::infinity();
    bool quiet = false;
    std::string events;  ///< where progress events go as JSON lines, if anywhere
    /// The files asked for beside the solution (--report, --urdf, ...).
    output::ExportPaths exports;
};

/// The run's exit code; `started` is when the command began (its time
/// limit counts from there).
int run_spatial_solve(const task::SpatialTask& task, const SolveRequest& request,
                      std::chrono::steady_clock::time_point started);

}  // namespace modsynth::app
