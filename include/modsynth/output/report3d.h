#pragma once
// The visual report of a spatial task (formats.md "Spatial tasks"): one
// self-contained HTML file with a 3-D view of the task (path, sphere,
// capsule and box obstacles, base boxes), the DH arm as capsules with its
// module housings, its animated motion (play / pause / scrub, `#t=` opens
// at a time), orbit / pan / zoom and a floor grid; the figures table and
// the timing charts. The view is three.js, bundled into the file
// (web/report3d/): nothing is fetched when it is viewed. For an unsolved
// task it shows the task and the explanation, the parts of its core in red.
#include <string>

#include <modsynth/output/report.h>
#include <modsynth/synth/solution.h>
#include <modsynth/task/spatial_task.h>

namespace modsynth::output {

std::string html_report(const task::SpatialTask& task, const synth::Solution& solution,
                        const ReportFigures& figures);

}  // namespace modsynth::output
