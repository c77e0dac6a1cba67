#include <modsynth/baseline/baseline.h>

#include <algorithm>
#include <stdexcept>

#include <modsynth/run/stopwatch.h>
#include <modsynth/text/option_check.h>

namespace modsynth::baseline {

const char* to_string(BaselineResult::Status status) {
    switch (status) {
        case BaselineResult::Status::Executed:
            return "executed";
        case BaselineResult::Status::NoDesign:
            return "no design";
        case BaselineResult::Status::NoMotion:
            return "no motion";
    }
    return "?";
}

bool BaselineOptions::IsValid(std::string* error) const {
    return text::OptionCheck("BaselineOptions", error)
        .at_least("points", points, 2)
        .greater("time_limit", time_limit, 0.0)
        .within("design_share", design_share, 0.0, 1.0)
        .nested("design", design)
        .nested("planner", planner)
        .nested("fidelity", fidelity)
        .ok();
}

BaselineResult run_baseline(const task::Task& task, const BaselineOptions& options) {
    text::require_valid(options);
    const run::Stopwatch t0;
    auto say = [&](const std::string& line) {
        if (options.progress) options.progress({run::Stage::Baseline, line, t0.seconds()});
    };
    BaselineResult result;
    result.points = equidistant_points(task, options.points);
    DesignOptions design = options.design;
    design.time_limit = std::min(design.time_limit, options.design_share * options.time_limit);
    say("discretized design: " + std::to_string(options.points) + " points");
    result.design = design_for_points(task, result.points, design);
    result.design_seconds = t0.seconds();
    if (!result.design.found) {
        result.status = BaselineResult::Status::NoDesign;
        result.message = result.design.message;
        result.seconds = result.design_seconds;
        return result;
    }
    say("discretized design: " + std::to_string(result.design.robot.dof()) + " joints after " +
        std::to_string(result.design.nlp_solves) + " solves; RRT between the poses");
    const run::Stopwatch t1;
    PlannerOptions planner = options.planner;
    planner.time_limit =
        std::max(0.0, std::min(planner.time_limit, options.time_limit - result.design_seconds));
    result.motion = plan_rrt(task, result.design.robot, result.design.poses, planner);
    result.planning_seconds = t1.seconds();
    result.seconds = result.design_seconds + result.planning_seconds;
    result.status = result.motion.complete ? BaselineResult::Status::Executed
                                           : BaselineResult::Status::NoMotion;
    result.message = result.motion.message;
    say("measuring the executed path");
    result.fidelity =
        measure_fidelity(task, result.design.robot, result.motion.waypoints, options.fidelity);
    return result;
}

}  // namespace modsynth::baseline
