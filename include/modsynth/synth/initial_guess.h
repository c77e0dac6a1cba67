#pragma once
// Initial guesses for the refinement: a cheap, deterministic random search
// over 2-joint robots on one skeleton (elbow sign and base region) that
// scores each candidate by its worst margin at points along the path.
#include <string>
#include <vector>

#include <modsynth/kinematics/robot.h>
#include <modsynth/run/deadline.h>
#include <modsynth/smt/skeleton.h>
#include <modsynth/task/task.h>

namespace modsynth::synth {

struct ScoredRobot {
    kinematics::Robot robot;
    /// Worst margin (m) over reach, self-collision and obstacle clearance at
    /// the scoring points; >= 0 means clear at all of them.
    double margin = 0.0;
};

struct InitialGuessOptions {
    /// m between the path points every candidate is scored at: finer than
    /// the refinement's 25 mm, so a guess clear at these points is seldom
    /// far from clear between the refinement's.
    double scoring_spacing = 0.02;
    /// Scoring points per primitive, at most, and over the whole path
    /// (past this the spacing widens): the guesses need the path's shape,
    /// and their work must not grow with its absolute size.
    int max_points_per_primitive = 200;
    int max_points = 20000;
    /// Random candidates per skeleton. Two joints are scored pose by pose
    /// (600 take milliseconds on the shipped tasks); three joints also
    /// choose a proximal angle per primitive, which costs far more each.
    int candidates_two = 600;
    int candidates_three = 120;
    /// Three joints: further candidates whose links are drawn long, each up
    /// to about twice the distance to the path. They let the arm go round
    /// obstacles: a base ringed by posts with one opening (scripts/
    /// keyhole-tasks) needs link 1 through the opening and a distal pair
    /// that wraps round the ring, several times longer than the straight
    /// reach the compact candidates are drawn from. Clear candidates rank
    /// shortest first, so these are chosen only where no compact one is
    /// clear.
    int candidates_three_detour = 120;
    /// Three joints: first-joint angles tried per primitive (16: every
    /// 22.5 degrees), and the rad between poses checked in a sweep from one
    /// to the next.
    int proximal_angles = 16;
    double sweep_step = 0.2;
    /// Three joints: m between the points of a primitive each proximal
    /// angle is scored at, and at most this many points a primitive (the
    /// span computed from them is quadratic in the count).
    double proximal_spacing = 0.03;
    int max_proximal_points = 64;
    /// m: a proximal angle whose margin falls below minus this at some
    /// point is hopeless, and its scoring stops there.
    double hopeless_margin = 0.05;
    /// m: candidates whose bases and every link length differ by less than
    /// this count as one start (a second start near the first adds little).
    double distinct_distance = 0.02;
    /// Three joints: a stroke of more primitives than this is scored as the
    /// chords through every k-th primitive end, at most this many: the
    /// guesses need the path's shape, and scoring every transition of a
    /// 512-segment loop took seconds a candidate. The proximal angles of
    /// each chord go to the primitives it spans.
    int coarse_primitives = 48;

    /// False (with `error` naming the field) when some value is out of range.
    bool IsValid(std::string* error) const;
};

/// The margin of a robot at points every `spacing` m of the path (at most
/// as many as `options` allow).
double path_margin(const task::Task& task, const kinematics::Robot& robot, double spacing,
                   const InitialGuessOptions& options = {});

/// Up to `count` distinct candidates, best first: clear ones by shorter
/// total length, the others by larger margin. Candidates are scored
/// shortest first, and no further than the `count`-th distinct clear one;
/// scoring stops at the deadline (those scored by then are kept). Throws std::invalid_argument
/// when the options are not valid.
std::vector<ScoredRobot> initial_guesses(const task::Task& task, const smt::Skeleton& skeleton,
                                         int count, unsigned seed, run::Deadline deadline = {},
                                         const InitialGuessOptions& options = {});

}  // namespace modsynth::synth
