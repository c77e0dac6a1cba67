#pragma once
// The pipeline: Z3 front stage (skeleton, proof of infeasibility), Ipopt
// refinement with counterexamples from the certified verification, control.
#include <string>
#include <vector>

#include <modsynth/control/motion.h>
#include <modsynth/control/retime.h>
#include <modsynth/prove/branch_and_bound.h>
#include <modsynth/run/cancel.h>
#include <modsynth/run/progress.h>
#include <modsynth/smt/front_stage.h>
#include <modsynth/synth/initial_guess.h>
#include <modsynth/synth/proximal_plan.h>
#include <modsynth/synth/solution.h>
#include <modsynth/synth/swept_choice.h>
#include <modsynth/task/task.h>
#include <modsynth/verify/verifier.h>

namespace modsynth::synth {

struct SynthesisOptions {
    double time_limit = 60.0;  ///< seconds, wall clock, for the whole run
    unsigned seed = 0;         ///< varies the initial guesses deterministically
    /// Ends the run early when cancelled (from another thread): it then
    /// answers as at its time limit.
    run::CancelToken cancel;
    control::MotionOptions motion;
    /// How a certified motion is timed: with the task's joint limits (or
    /// the modules' defaults, control::joint_limits_for()) and these caps.
    control::RetimeOptions retime;
    /// The front stage's options. Its time_limit caps each check, which
    /// the run shortens to what is left of its own time; its deadline is
    /// set by the run.
    smt::FrontStageOptions front;
    /// What a motion must meet to be certified. The run checks each motion
    /// against verify::options_for(motion, verify): the motion's own joint
    /// step, and the EE progress limit widened to the planning step on long
    /// paths.
    verify::VerifyOptions verify;
    /// How the initial guesses of the refinement are searched for.
    InitialGuessOptions guesses;
    /// Three joints: how the proximal angles of each initial guess are
    /// planned along the path before its refinement (proximal_plan.h).
    ProximalPlanOptions proximal;
    /// The branch and bound tried on tasks that allow 2 joints only, when
    /// neither a wall nor a detour proves them infeasible. Its time_limit
    /// is further capped at branch_and_bound_share of the run's, and so is
    /// its core_time_limit: the core of a proof is shrunk within what the
    /// proof leaves of that share, and at most until 1.5 s after the proof
    /// started, so that a walled-in task is answered within 2 s in all (the
    /// shrinking took every second it was given). `explain` shrinks a core
    /// with its own, longer budget.
    prove::BranchAndBoundOptions branch_and_bound = [] {
        prove::BranchAndBoundOptions o;
        o.core_time_limit = 0.75 * o.time_limit;
        return o;
    }();
    double branch_and_bound_share = 0.05;
    /// Design boxes, at most, for the branch and bound that drops 2 joints
    /// from the retries where more are allowed (0: it does not run). The
    /// proofs of scripts/keyhole-tasks take 300-1000.
    long branch_and_bound_boxes_beside = 2000;

    /// m between the points where the refinement constrains the arm along
    /// each primitive: 25 mm keeps a circle of the shipped tasks well
    /// sampled, and counterexamples add points where 25 mm is not enough.
    double point_spacing = 0.025;
    /// Points per primitive, at least (a short line still gets its ends
    /// and some interior) and at most (the program stays small).
    int min_points_per_primitive = 4;
    int max_points_per_primitive = 200;
    /// Points over the whole path: past this the spacing widens, so the
    /// program stays small on long paths.
    int max_points = 20000;
    /// Trace samples the motion gets over the whole path: past this the
    /// planning step widens beyond motion.max_ee_step (memory and time stay
    /// bounded on long paths; the verifier checks the wider steps).
    double trace_samples = 250000;
    /// Initial guesses tried per skeleton of the front stage, and per
    /// variant (other elbow sign or base region) when shortening the first
    /// certified robot: a fixed amount of work, so solutions stay repeatable.
    int guesses_per_skeleton = 4;
    int guesses_per_variant = 1;
    /// m: a variant is not refined when no robot with its base region can
    /// be shorter than the one found by more than this. Every arm is at
    /// least as long as its farthest reach from the best base of its region
    /// (geometry/farthest_reach.h). Such a variant could at best tie
    /// (length_tie) with more clearance; in the robot's own region the robot
    /// found with the other elbow is verified instead, which costs a
    /// verification. A gap wider than length_tie would leave out robots that
    /// are shorter by more than a tie.
    double shorten_gap = 5e-4;
    /// m: of the certified robots the search found, one at most this much
    /// longer than the shortest is returned when it passes farther from the
    /// obstacles by more than this (synth/design_choice.h): lengths that
    /// close are the same to a builder, and the refinement's local optima
    /// for either elbow of one base often differ by less.
    double length_tie = 5e-4;
    /// A variant is started only while the time left is at least this many
    /// times what the refinement of the robot found took.
    double shorten_reserve = 2.0;
    /// Refinement rounds (solve, plan, verify, add counterexamples) per
    /// initial guess before the next guess is tried.
    int refinement_rounds = 12;
    /// Ipopt's budget in the first round of a guess and in later rounds,
    /// which start close to a solution: a refinement that needs more is
    /// better restarted from another guess than waited for.
    double first_solve_seconds = 3.0;
    double later_solve_seconds = 1.5;
    /// Each budget grows by this per 1000 variables of the program: an
    /// iteration's cost grows with its size (about 80 ms at 13000 variables,
    /// a 640-primitive path), and a fixed budget stopped large refinements
    /// that were converging.
    double solve_seconds_per_kvariable = 0.25;
    /// Later rounds start Ipopt from the last round's solution and
    /// multipliers (nlp::carry_over) instead of from the refined robot alone.
    bool warm_start_rounds = true;
    int first_solve_iterations = 200;
    int later_solve_iterations = 100;
    /// Three joints: proximal poses per transition in the refinement are
    /// 2^depth - 1; a failed transition raises the depth from
    /// nlp::ArmProblem::transition_depth up to this.
    int max_transition_depth = 4;
    /// Times the verifier's coarse sample pairs are split before a motion
    /// is given up.
    int motion_refinement_passes = 8;
    /// Counterexample points added per round, at most (the program grows
    /// by a bounded amount per round).
    int counterexamples_per_round = 24;
    /// Seconds the front stage stops before the run's deadline, at most,
    /// and at most this share of the time limit: tearing down a large
    /// encoding takes time too.
    double front_reserve_seconds = 0.3;
    double front_reserve_share = 0.1;
    /// Seconds for finding the core common to every joint count once all
    /// are proved infeasible, at most.
    double explanation_seconds = 5.0;
    /// The model of the swept area the refinement starts each guess from,
    /// and so the order models are tried in (swept_choice.h).
    SweptChoice swept = SweptChoice::Auto;
    /// Told of every step (may be empty).
    run::ProgressSink progress;

    /// False (with `error` naming the field) when some value is out of range.
    bool IsValid(std::string* error) const;
};

/// Statistics of one run, kept out of the solution so that solutions stay
/// byte-identical across runs.
struct SynthesisStats {
    double front_seconds = 0.0;
    double refine_seconds = 0.0;
    double verify_seconds = 0.0;
    int skeletons = 0;
    int nlp_solves = 0;
    int counterexamples = 0;
    /// The model (swept_choice.h, name_of) of the refinement round whose
    /// robot was certified and returned; empty when none was.
    std::string certified_by;
    /// The model of the first certified robot (the one the search for a
    /// shorter robot starts from).
    std::string first_certified_by;
    /// Times a swept-volume model gave way to the next: its refinement did
    /// not converge, or its candidate failed verification and the rounds
    /// went on with lines.
    int fallbacks = 0;
    /// What the user should be told besides the answer (e.g. that no
    /// modules were chosen, and why).
    std::vector<std::string> notes;
    /// How the returned motion was timed (solved only): its duration, its
    /// stops, where the EE runs slower than options.retime.ee_speed.
    control::RetimeStats timing;
};

/// The motion options a run plans `task` with: options.motion, with its EE
/// step widened on long paths so that the trace has at most
/// options.trace_samples samples.
control::MotionOptions motion_options_for(const task::Task& task, const SynthesisOptions& options);

/// What a run certifies a motion of `task` against. A solution read back
/// from a file is checked with the same limits, so that what was certified
/// when it was made certifies again.
verify::VerifyOptions verify_options_for(const task::Task& task,
                                         const SynthesisOptions& options = {});

/// Throws std::invalid_argument when the options are not valid.
Solution synthesize(const task::Task& task, const SynthesisOptions& options,
                    SynthesisStats* stats = nullptr);

}  // namespace modsynth::synth
