#include <modsynth/synth/solve.h>

#include <algorithm>
#include <string>
#include <utility>

#include <modsynth/hardware/select_dh_modules.h>
#include <modsynth/hardware/task_catalog.h>
#include <modsynth/synth/module_choice.h>
#include <modsynth/synth/spatial_module_choice.h>
#include <modsynth/task/limits.h>
#include <modsynth/text/format.h>
#include <modsynth/text/printable.h>

namespace modsynth::synth {
namespace {

/// A solved motion a solution file cannot hold (more samples than one may
/// have, or longer than a motion may last: task/limits.h) is no answer the
/// program could read back or a controller run: "unknown", saying why.
void keep_within_file_limits(Solution& solution, int dof) {
    if (solution.status != Status::Solved || solution.samples.empty()) return;
    const std::size_t most = task::max_motion_samples(dof);
    const double duration = solution.samples.back().t;
    std::string why;
    if (solution.samples.size() > most)
        why = text::format(
            "the certified motion has %zu samples, more than the %zu a solution "
            "of %d joints may hold",
            solution.samples.size(), most, dof);
    else if (!(duration <= task::kLongestMotion))
        why = text::format("the timed motion lasts %s s, more than the %s s a solution may hold",
                           text::compact(duration).c_str(),
                           text::compact(task::kLongestMotion).c_str());
    if (why.empty()) return;
    Solution unknown;
    unknown.task_name = solution.task_name;
    unknown.status = Status(Status::Unknown, "writing the motion", why);
    unknown.explanation.message = "No answer: " + why + ".";
    solution = std::move(unknown);
}

}  // namespace

Solution solve(const task::Task& task, SynthesisOptions options, SynthesisStats* stats) {
    SynthesisStats local;
    SynthesisStats& s = stats ? *stats : local;
    const hardware::TaskCatalog catalog = hardware::catalog_for(task);
    if (!catalog.note.empty()) s.notes.push_back(catalog.note);
    options.retime.joint_speed =
        std::min(options.retime.joint_speed, hardware::module_speed_cap(task, catalog.catalog));
    Solution solution = synthesize(task, options, &s);
    keep_within_file_limits(solution, solution.robot.dof());
    choose_modules(task, catalog.catalog, solution);
    return solution;
}

Solution solve(const task::SpatialTask& task, SpatialSynthesisOptions options,
               SynthesisStats* stats) {
    SynthesisStats local;
    SynthesisStats& s = stats ? *stats : local;
    std::string note;
    const std::optional<hardware::Catalog> catalog = hardware::spatial_catalog(task, &note);
    if (!note.empty()) s.notes.push_back(note);
    options.retime.joint_speed =
        std::min(options.retime.joint_speed, hardware::module_speed_cap(task, catalog));
    Solution solution = synthesize(task, options, &s);
    if (solution.dh_robot) keep_within_file_limits(solution, solution.dh_robot->dof());
    choose_modules(task, catalog, solution);
    return solution;
}

}  // namespace modsynth::synth
