#pragma once
// Initial guesses for the refinement: a cheap, deterministic random search
// over 2-joint robots on one skeleton (elbow sign and base region) that
// scores each candidate by its worst margin at points along the path.
#include <chrono>
#include <vector>

#include <modsynth/kinematics/robot.h>
#include <modsynth/smt/skeleton.h>
#include <modsynth/task/task.h>

namespace modsynth::synth {

struct ScoredRobot {
    kinematics::Robot robot;
    /// Worst margin (m) over reach, self-collision and obstacle clearance at
    /// the scoring points; >= 0 means clear at all of them.
    double margin = 0.0;
};

/// The margin of a robot at points every `spacing` m of the path.
double path_margin(const task::Task& task, const kinematics::Robot& robot, double spacing);

/// Up to `count` distinct candidates, best first: clear ones by shorter
/// total length, the others by larger margin. Candidates stop at the
/// deadline (those scored by then are kept).
std::vector<ScoredRobot> initial_guesses(
    const task::Task& task, const smt::Skeleton& skeleton, int count, unsigned seed,
    std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max());

}  // namespace modsynth::synth
