#pragma once
// A closed loop of the path round an obstacle, which no arm of two joints
// can trace.
//
// Along a stroke an arm of two joints has one pose for each position of its
// tool on its elbow branch, and it keeps one branch for the whole motion
// (paper eq. 5; formats.md, "Robot branch"). So where the path comes back
// to a point it passed (a circle, or a run of primitives that closes), the
// arm is back in the pose it had there, and its chains from the base to
// the tool, moment by moment, contract that loop to the base. Were no link
// ever over a point, the loop could not wind round that point; but no link
// may pass over an obstacle's centre. Base, link lengths and branch do not
// matter: the proof is exact and takes milliseconds.
//
// A third joint can turn the first link aside at a transition between
// primitives, so with more joints the proof holds only for a loop that is
// one primitive, and only for modsynth's motions, which keep the proximal
// links still along a primitive: a limit of the search, not a proof.
#include <optional>

#include <modsynth/prove/proof.h>
#include <modsynth/task/task.h>

namespace modsynth::prove {

struct LoopAroundObstacle {
    int first = 0;     ///< the loop: primitives first..last of one stroke
    int last = 0;      ///< (task.trajectory's numbering)
    int obstacle = 0;  ///< whose centre it winds round
    int turns = 0;     ///< how often, counter-clockwise positive (never 0)
};

/// The first run of at most `longest` primitives of one stroke whose end is
/// its start (within 1e-6 m, as the format joins primitives) and which winds
/// round the centre of an obstacle that a link must keep off (radius +
/// link_diameter / 2 > 0); shortest runs first. None when there is no such
/// run, or when looking for one would take more than a few million steps.
std::optional<LoopAroundObstacle> loop_around_obstacle(const task::Task& task, int longest = -1);

/// The loop as a proof for arms of two joints. Its core is minimal: every
/// primitive of the loop (without one it is open), the obstacle, robot.dof,
/// and robot.link_diameter where the obstacle has radius 0 (with neither, a
/// link may pass over its centre).
Proof two_joint_loop_proof(const task::Task& task, const LoopAroundObstacle& loop);

/// The first such loop's proof, if there is one.
std::optional<Proof> prove_two_joint_loop(const task::Task& task);

/// "trajectory[3] to trajectory[9] is a closed loop that winds once
/// counter-clockwise round the centre of obstacles[0]".
std::string describe_loop(const task::Task& task, const LoopAroundObstacle& loop);

}  // namespace modsynth::prove
