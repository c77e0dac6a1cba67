#pragma once
// Circles cut into arcs, so that the proximal links may turn inside them.
//
// modsynth's motions keep the proximal links still along a primitive and
// move them only at transitions between primitives (motion.h). A circle
// that winds round an obstacle is then out of reach of every arm
// (loop_proof.h), though a third joint can trace it by turning the first
// link while the tool rests at a point of the circle. Cut into arcs, the
// circle has such points: the task of arcs is solved as any other, and its
// motion is read back as one of the circle, the transitions between its
// arcs becoming rests of the tool inside the circle's trace (the contract
// asks progress along a primitive not to go back, not to go on). Every
// motion of the circle is one of the arcs too (with rests of no motion),
// so the cut loses no robot.
#include <vector>

#include <modsynth/control/motion.h>
#include <modsynth/task/task.h>

namespace modsynth::synth {

/// A task whose circles are cut into arcs, and where each arc came from.
struct SplitTask {
    /// Where a primitive of `task` lies in the task it was cut from.
    struct Piece {
        int original = 0;     ///< the primitive's index there
        double offset = 0.0;  ///< arc length of the original before this piece
        bool last = true;     ///< the original's last piece (what follows it follows the original)
    };
    task::Task task;
    std::vector<Piece> pieces;  ///< one per primitive of task.trajectory
};

/// The task with each circle cut into `arcs` arcs of equal sweep (arcs >= 2),
/// in strokes as the circles were.
SplitTask split_circles(const task::Task& task, int arcs);

/// A motion of split.task read as one of `original` (the task split_circles
/// was given): the pieces' traces joined into their circle's, a transition
/// after a piece that is not its circle's last a rest of the tool at that
/// point of the circle's trace.
std::vector<control::Sample> join_arcs(const task::Task& original, const SplitTask& split,
                                       std::vector<control::Sample> samples);

}  // namespace modsynth::synth
