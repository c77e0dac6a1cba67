#pragma once
// The spatial pipeline (formats.md "Spatial tasks"), the same shape as the
// plane's: the reach proof, then per joint count, fewest first, the spatial
// front stage (Z3: proofs of infeasibility with cores, and the skeletons
// the pattern allows), initial guesses by random search, the reduced
// Ipopt refinement with counterexamples from the certified verifier, the
// exact motion, and the timing for a controller.
#include <string>

#include <modsynth/control/retime.h>
#include <modsynth/control/spatial_motion.h>
#include <modsynth/nlp/spatial_formulation.h>
#include <modsynth/run/cancel.h>
#include <modsynth/run/progress.h>
#include <modsynth/smt/spatial_front_stage.h>
#include <modsynth/synth/solution.h>
#include <modsynth/synth/spatial_initial_guess.h>
#include <modsynth/synth/synthesizer.h>
#include <modsynth/task/spatial_task.h>
#include <modsynth/verify/verifier.h>

namespace modsynth::synth {

struct SpatialSynthesisOptions {
    double time_limit = 60.0;  ///< seconds, wall clock, for the whole run
    unsigned seed = 0;         ///< varies the initial guesses deterministically
    /// Ends the run early when cancelled (from another thread): it then
    /// answers as at its time limit.
    run::CancelToken cancel;
    control::SpatialMotionOptions motion;
    /// How a certified motion is timed: the task's joint limits (or the
    /// modules' defaults) and these caps.
    control::RetimeOptions retime;
    /// What a motion must meet to be certified (the plane's limits; the
    /// spatial verifier adds its own bound on the deviation).
    verify::VerifyOptions verify;
    smt::SpatialFrontStageOptions front;
    SpatialGuessOptions guesses;
    nlp::SpatialMargins margins;
    /// m between the points where the refinement constrains the arm along
    /// each primitive, and at most this many points over the whole path
    /// (past it the spacing widens; counterexamples add points where
    /// needed).
    double point_spacing = 0.02;
    int max_points = 500;
    /// Initial guesses per skeleton in the first pass (breadth first, as in
    /// the plane), and in each later pass over the skeletons.
    int first_guesses = 1;
    int later_guesses = 3;
    /// Refinement rounds (solve, plan, verify, add counterexamples) per
    /// initial guess.
    int refinement_rounds = 8;
    /// Ipopt's budget and iterations per solve.
    double solve_seconds = 2.0;
    int solve_iterations = 300;
    /// Times the verifier's coarse sample pairs are split before a motion
    /// is given up.
    int motion_refinement_passes = 8;
    /// Counterexample points added per round, at most.
    int counterexamples_per_round = 24;
    /// After the first certified design: other skeletons of the same joint
    /// count refined for a shorter one, at most (each costs about what the
    /// first did).
    int shortening_variants = 3;
    /// m: as in the plane (SynthesisOptions::length_tie), a design at most
    /// this much longer than the shortest is returned when it passes
    /// farther from the obstacles by more than this.
    double length_tie = 5e-4;
    /// Told of every step (may be empty), as the plane's run tells it.
    run::ProgressSink progress;

    /// False (with `error` naming the field) when some value is out of range.
    bool IsValid(std::string* error) const;
};

/// Throws std::invalid_argument when the options are not valid.
Solution synthesize(const task::SpatialTask& task, const SpatialSynthesisOptions& options,
                    SynthesisStats* stats = nullptr);

/// The limits a run certifies a spatial motion against; a solution read
/// back from a file is checked with the same.
verify::VerifyOptions verify_options_for(const task::SpatialTask& task,
                                         const SpatialSynthesisOptions& options = {});

}  // namespace modsynth::synth
