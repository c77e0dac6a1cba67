// A spatial solution on arbitrary bytes, as `certify` and `export` read it:
// every input is a solution or an InputError naming the offending part. One
// that parses is checked against a fixed spatial task (a line and an arc
// with an obstacle, jerk limits), verified again over the continuum, its
// timing judged against the task's limits, and rendered to every output;
// nothing else may escape, and the verdict must be consistent with the
// reason given for it.
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include <nlohmann/json.hpp>

#include <modsynth/control/joint_limits.h>
#include <modsynth/control/retime.h>
#include <modsynth/io/solution_io.h>
#include <modsynth/io/spatial_task_io.h>
#include <modsynth/output/csv.h>
#include <modsynth/output/dh_build_sheet.h>
#include <modsynth/output/dh_urdf.h>
#include <modsynth/output/joint_trajectory.h>
#include <modsynth/output/recertify.h>
#include <modsynth/output/report3d.h>
#include <modsynth/task/input_error.h>

namespace {

constexpr std::string_view kTask = R"json({
  "format": "modsynth-task/1", "name": "tiny3", "space": "3d",
  "trajectory": [
    {"type": "line", "start": [0.4, -0.02, 0.1], "end": [0.4, 0.02, 0.1]},
    {"type": "arc", "start": [0.4, 0.02, 0.1], "end": [0.42, 0.04, 0.1], "center": [0.42, 0.02, 0.1],
     "normal": [0, 0, 1], "direction": "cw"}
  ],
  "obstacles": [{"type": "sphere", "center": [0.2, 0.3, 0.2], "radius": 0.05}],
  "base_regions": [{"min": [-0.05, -0.05, 0.0], "max": [0.05, 0.05, 0.0]}],
  "robot": {"dof": [3], "joint_limits": {"velocity": 2, "acceleration": 5, "jerk": 50}}
}
)json";

const modsynth::task::SpatialTask& tiny3() {
    static const modsynth::task::SpatialTask t = modsynth::io::parse_spatial_task_text(kTask);
    return t;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace modsynth;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const task::SpatialTask& t = tiny3();
    io::ParsedSolution parsed;
    output::ReportFigures figures;
    try {
        parsed = io::parse_solution_text(text);
        figures.certificate_note = output::recertify(t, parsed);
    } catch (const task::InputError&) {
        return 0;
    }
    const synth::Solution& s = parsed.solution;
    const bool solved = s.status == synth::Status::Solved;
    if (solved && s.certificate.ok != output::uncertified_reason(s.certificate).empty())
        std::abort();
    if (solved) {
        // The timing a controller would be handed is judged, never trusted.
        (void)control::timing_fault(s.samples, control::joint_limits_for(t, s.dh_robot->dof()));
    }
    // What parsed must write back to a document that parses again.
    io::parse_solution(io::to_json(s));
    if (solved) {
        output::trajectory_csv(s);
        output::joint_trajectory_yaml(s);
        output::robot_urdf(t, s);
    }
    output::build_sheet(t, s);
    output::html_report(t, s, figures);
    return 0;
}
