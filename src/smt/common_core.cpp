#include <modsynth/smt/common_core.h>

#include <algorithm>

#include <modsynth/run/deadline.h>
#include <modsynth/smt/front_stage.h>

namespace modsynth::smt {

std::vector<task::TaskPart> common_core(const task::Task& task,
                                        const std::vector<std::vector<task::TaskPart>>& cores,
                                        double time_limit) {
    const run::Deadline deadline = run::Deadline::in(time_limit);
    std::vector<std::vector<task::TaskPart>> candidates = cores;
    std::sort(candidates.begin(), candidates.end(),
              [](const auto& a, const auto& b) { return a.size() < b.size(); });
    for (const auto& c : candidates) {
        bool everywhere = true;
        for (int dof : task.robot.dof) {
            FrontStageOptions o;
            o.time_limit = time_limit;
            o.deadline = deadline;
            FrontStage fs(task, dof, o);
            everywhere = everywhere && fs.conflicts(c);
        }
        if (everywhere) return c;
    }
    std::vector<task::TaskPart> all;
    for (const auto& c : cores)
        for (const auto& part : c)
            if (std::find(all.begin(), all.end(), part) == all.end()) all.push_back(part);
    return all;
}

}  // namespace modsynth::smt
