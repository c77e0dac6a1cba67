// Solution import on arbitrary bytes, as `export` does it: every input is
// either a solution or an InputError naming the offending part. One that
// parses is checked against a fixed task (tasks/rose.json, embedded),
// verified again, and rendered to every output; nothing else may escape,
// and the verdict must be consistent with the reason given for it.
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include <nlohmann/json.hpp>

#include <modsynth/io/solution_io.h>
#include <modsynth/io/task_io.h>
#include <modsynth/output/build_sheet.h>
#include <modsynth/output/csv.h>
#include <modsynth/output/recertify.h>
#include <modsynth/output/report.h>
#include <modsynth/output/urdf.h>
#include <modsynth/task/input_error.h>

namespace {

constexpr std::string_view kRose = R"json({
  "format": "modsynth-task/1",
  "name": "rose",
  "description": "Paint a rose (after the paper's Fig. 1): a stem, a leaf drawn as two arcs, a bloom circle and a spiral of two arcs, between three obstacles, with the base on a small plate near the origin.",
  "trajectory": [
    {"type": "line", "start": [0.50, 0.05], "end": [0.50, 0.22]},
    {"type": "arc", "start": [0.50, 0.22], "end": [0.60, 0.22], "center": [0.55, 0.22], "direction": "cw"},
    {"type": "arc", "start": [0.60, 0.22], "end": [0.50, 0.22], "center": [0.55, 0.22], "direction": "cw"},
    {"type": "line", "start": [0.50, 0.22], "end": [0.50, 0.32]},
    {"type": "circle", "start": [0.50, 0.32], "center": [0.50, 0.37], "direction": "ccw", "radius": 0.05},
    {"type": "arc", "start": [0.50, 0.32], "end": [0.50, 0.40], "center": [0.50, 0.36], "direction": "ccw"},
    {"type": "arc", "start": [0.50, 0.40], "end": [0.50, 0.34], "center": [0.50, 0.37], "direction": "ccw"}
  ],
  "obstacles": [
    {"center": [0.36, 0.33], "radius": 0.04},
    {"center": [0.66, 0.40], "radius": 0.04},
    {"center": [0.64, 0.07], "radius": 0.03}
  ],
  "base_regions": [{"min": [-0.05, -0.05], "max": [0.10, 0.10]}],
  "robot": {"dof": [2, 3], "link_diameter": 0.03175, "min_link_length": 0.05, "max_link_length": 1.0}
}
)json";

const modsynth::task::Task& rose() {
    static const modsynth::task::Task task = modsynth::io::parse_task_text(kRose);
    return task;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace modsynth;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const task::Task& task = rose();
    io::ParsedSolution parsed;
    output::ReportFigures figures;
    try {
        parsed = io::parse_solution_text(text);
        figures.certificate_note = output::recertify(task, parsed);
    } catch (const task::InputError&) {
        return 0;
    }
    const synth::Solution& s = parsed.solution;
    if (s.status == synth::Status::Solved &&
        s.certificate.ok != output::uncertified_reason(s.certificate).empty())
        std::abort();
    // What parsed must write back to a document that parses again.
    io::parse_solution(io::to_json(s));
    if (s.status == synth::Status::Solved) {
        output::build_sheet(task, s);
        output::trajectory_csv(s);
        output::robot_urdf(task, s);
    }
    output::html_report(task, s, figures);
    return 0;
}
