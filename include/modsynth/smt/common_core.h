#pragma once
// One explanation for several joint counts: when the front stage proves
// each allowed joint count infeasible on its own, the core to report is one
// that conflicts for all of them.
#include <vector>

#include <modsynth/task/part.h>
#include <modsynth/task/task.h>

namespace modsynth::smt {

/// Among per-joint-count cores, the smallest that the front stage proves
/// to conflict for every allowed joint count, when there is one, else their
/// union; checks end within `time_limit` seconds.
std::vector<task::TaskPart> common_core(const task::Task& task,
                                        const std::vector<std::vector<task::TaskPart>>& cores,
                                        double time_limit);

}  // namespace modsynth::smt
