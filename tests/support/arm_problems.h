#pragma once
// Refinement problems on the shipped tasks, shared by the nlp tests.
#include <modsynth/io/task_io.h>
#include <modsynth/nlp/formulation.h>

#include "fixtures.h"

namespace modsynth::testing {

/// The rose (tasks/rose.json) for a 2-joint arm, elbow -1, base region 0,
/// from a start that reaches the path, with three points per primitive and
/// every obstacle at every point (all constraint kinds present).
inline nlp::ArmProblem rose_arm_problem(nlp::SweptVolume swept) {
    static const task::Task rose = io::load_task(source_path("tasks/rose.json"));
    nlp::ArmProblem p;
    p.task = &rose;
    p.skeleton.dof = 2;
    p.skeleton.elbow = -1;
    p.skeleton.base_region = 0;
    p.start.base = {0.0, 0.05};
    p.start.link_lengths = {0.5, 0.45};
    p.start.link_diameter = rose.robot.link_diameter;
    p.start.elbow = -1;
    p.swept = swept;
    p.horizon = 1.0;
    for (int j = 0; j < static_cast<int>(rose.trajectory.size()); ++j)
        for (double s : {0.0, 0.03, 0.07}) p.points.push_back({j, s});
    return p;
}

}  // namespace modsynth::testing
