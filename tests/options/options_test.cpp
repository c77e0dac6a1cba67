// Every stage's options: the defaults are valid, and each bad value is
// refused with a message that names the struct and the field.
#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <modsynth/baseline/baseline.h>
#include <modsynth/control/motion.h>
#include <modsynth/explanation/explanation.h>
#include <modsynth/nlp/solver.h>
#include <modsynth/smt/front_stage.h>
#include <modsynth/synth/initial_guess.h>
#include <modsynth/synth/synthesizer.h>
#include <modsynth/text/option_check.h>
#include <modsynth/verify/verifier.h>

#include "../support/fixtures.h"

using namespace modsynth;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

template <typename Options>
using Breakage = std::pair<std::string, std::function<void(Options&)>>;

// Each breakage: the name the message must contain and a change that makes
// one field (alone) invalid.
template <typename Options>
void check_options(const std::vector<Breakage<Options>>& breakages) {
    const Options defaults;
    std::string error = "untouched";
    CHECK(defaults.IsValid(&error));
    CHECK(error == "untouched");
    CHECK(defaults.IsValid(nullptr));
    for (const auto& [name, breaks] : breakages) {
        Options o;
        breaks(o);
        std::string message;
        INFO(name);
        CHECK_FALSE(o.IsValid(nullptr));
        REQUIRE_FALSE(o.IsValid(&message));
        CHECK(message.find(name) != std::string::npos);
        CHECK_THROWS_WITH(text::require_valid(o), message);
    }
}

}  // namespace

TEST_CASE("option checks name the first broken rule and skip the rest", "[options]") {
    std::string error;
    CHECK(text::OptionCheck("X", &error).greater("a", 1.0, 0.0).at_least("b", 0.0, 0.0).ok());
    CHECK_FALSE(
        text::OptionCheck("X", &error).greater("a", 0.0, 0.0).within("b", 9.0, 0.0, 1.0).ok());
    CHECK(error == "X::a = 0: must be greater than 0");
    CHECK_FALSE(text::OptionCheck("X", &error).at_least("a", kNaN, 0.0).ok());
    CHECK(error == "X::a = nan: must be a finite number");
    CHECK_FALSE(text::OptionCheck("X", &error)
                    .greater("a", std::numeric_limits<double>::infinity(), 0.0)
                    .ok());
    CHECK(error == "X::a = inf: must be a finite number");
    CHECK_FALSE(text::OptionCheck("X", &error).within("b", 9.0, 0.0, 1.0).ok());
    CHECK(error == "X::b = 9: must be a number from 0 to 1");
    CHECK_FALSE(text::OptionCheck("X", &error).holds("c", false, "must be odd").ok());
    CHECK(error == "X::c: must be odd");
}

TEST_CASE("front stage options: defaults valid, each bad field named", "[options][smt]") {
    using O = smt::FrontStageOptions;
    check_options<O>({
        {"FrontStageOptions::time_limit", [](O& o) { o.time_limit = 0.0; }},
        {"FrontStageOptions::time_limit", [](O& o) { o.time_limit = kNaN; }},
        {"FrontStageOptions::refined_time_limit", [](O& o) { o.refined_time_limit = -1.0; }},
        {"FrontStageOptions::refined_max_primitives", [](O& o) { o.refined_max_primitives = -1; }},
        {"FrontStageOptions::samples_per_primitive", [](O& o) { o.samples_per_primitive = 0; }},
        {"FrontStageOptions::encoded_points", [](O& o) { o.encoded_points = 0; }},
        {"FrontStageOptions::core_trial_seconds", [](O& o) { o.core_trial_seconds = 0.0; }},
        {"FrontStageOptions::core_trial_factor", [](O& o) { o.core_trial_factor = 0.5; }},
        {"FrontStageOptions::all_span_pairs", [](O& o) { o.all_span_pairs = -1; }},
        {"FrontStageOptions::hull_probe", [](O& o) { o.hull_probe = 0; }},
        {"FrontStageOptions::slack", [](O& o) { o.slack = -1e-7; }},
        {"FrontStageOptions::slack", [](O& o) { o.slack = 0.1; }},
    });
    O bad;
    bad.samples_per_primitive = 0;
    CHECK_THROWS_WITH(smt::FrontStage(testing::line_task(), 2, bad),
                      Catch::Contains("FrontStageOptions::samples_per_primitive"));
}

TEST_CASE("solver options: defaults valid, each bad field named", "[options][nlp]") {
    using O = nlp::SolverOptions;
    check_options<O>({
        {"SolverOptions::time_limit", [](O& o) { o.time_limit = 0.0; }},
        {"SolverOptions::max_iterations", [](O& o) { o.max_iterations = -1; }},
        {"SolverOptions::tolerance", [](O& o) { o.tolerance = 0.0; }},
        {"SolverOptions::constraint_tolerance", [](O& o) { o.constraint_tolerance = kNaN; }},
        {"SolverOptions::acceptable_tolerance", [](O& o) { o.acceptable_tolerance = 1e-9; }},
        {"SolverOptions::acceptable_constraint_tolerance",
         [](O& o) { o.acceptable_constraint_tolerance = 1e-10; }},
        {"SolverOptions::acceptable_iterations", [](O& o) { o.acceptable_iterations = -1; }},
        {"SolverOptions::warm_push", [](O& o) { o.warm_push = 0.0; }},
        {"SolverOptions::warm_mu", [](O& o) { o.warm_mu = kNaN; }},
        {"SolverOptions::print_level", [](O& o) { o.print_level = 13; }},
        {"SolverOptions::reported_violations", [](O& o) { o.reported_violations = -1; }},
        {"ProgressWatchOptions::stall_window", [](O& o) { o.watch.stall_window = 0; }},
    });
    nlp::QuadraticProgram qp;
    qp.add_variable(-1.0, 1.0, 0.0, "x");
    qp.finalize();
    O bad;
    bad.max_iterations = -1;
    CHECK_THROWS_WITH(nlp::minimize(qp, bad), Catch::Contains("SolverOptions::max_iterations"));
}

TEST_CASE("motion options: defaults valid, each bad field named", "[options][control]") {
    using O = control::MotionOptions;
    check_options<O>({
        {"MotionOptions::max_joint_step", [](O& o) { o.max_joint_step = 0.0; }},
        {"MotionOptions::max_ee_step", [](O& o) { o.max_ee_step = -0.002; }},
        {"MotionOptions::ee_speed", [](O& o) { o.ee_speed = kNaN; }},
        {"MotionOptions::joint_speed", [](O& o) { o.joint_speed = 0.0; }},
        {"MotionOptions::max_samples", [](O& o) { o.max_samples = 0; }},
        {"MotionOptions::step_attempts", [](O& o) { o.step_attempts = 0; }},
        {"MotionOptions::ticks_per_second", [](O& o) { o.ticks_per_second = 0.0; }},
    });
    O bad;
    bad.ee_speed = 0.0;
    std::vector<control::Sample> samples(2);
    CHECK_THROWS_WITH(control::assign_times(samples, bad),
                      Catch::Contains("MotionOptions::ee_speed"));
    CHECK_THROWS_WITH(control::plan_motion(testing::line_task(), {}, bad),
                      Catch::Contains("MotionOptions::ee_speed"));
}

TEST_CASE("verify options: defaults valid, each bad field named", "[options][verify]") {
    using O = verify::VerifyOptions;
    check_options<O>({
        {"VerifyOptions::deviation_tolerance", [](O& o) { o.deviation_tolerance = 0.0; }},
        {"VerifyOptions::max_joint_step", [](O& o) { o.max_joint_step = kNaN; }},
        {"VerifyOptions::max_ee_step", [](O& o) { o.max_ee_step = -1.0; }},
    });
    O bad;
    bad.max_ee_step = 0.0;
    CHECK_THROWS_WITH(verify::certify(testing::line_task(), {}, {}, bad),
                      Catch::Contains("VerifyOptions::max_ee_step"));
}

TEST_CASE("the verifier's limits follow the motion's: same joint step, wider EE step",
          "[options][verify]") {
    control::MotionOptions motion;
    const verify::VerifyOptions defaults;
    // The default planning step is finer than the progress limit it must meet.
    CHECK(motion.max_ee_step < defaults.max_ee_step);
    CHECK(motion.max_joint_step == defaults.max_joint_step);
    verify::VerifyOptions v = verify::options_for(motion);
    CHECK(v.max_ee_step == defaults.max_ee_step);
    CHECK(v.max_joint_step == motion.max_joint_step);
    motion.max_ee_step = 0.02;  // a long path, planned coarser
    motion.max_joint_step = 0.005;
    v = verify::options_for(motion);
    CHECK(v.max_ee_step == 0.02);
    CHECK(v.max_joint_step == 0.005);
    CHECK(v.deviation_tolerance == defaults.deviation_tolerance);
}

TEST_CASE("synthesis options: defaults valid, each bad field named", "[options][synth]") {
    using O = synth::SynthesisOptions;
    check_options<O>({
        {"SynthesisOptions::time_limit", [](O& o) { o.time_limit = -1.0; }},
        {"SynthesisOptions::motion: MotionOptions::max_joint_step",
         [](O& o) { o.motion.max_joint_step = 0.0; }},
        {"SynthesisOptions::front: FrontStageOptions::time_limit",
         [](O& o) { o.front.time_limit = 0.0; }},
        {"SynthesisOptions::verify: VerifyOptions::deviation_tolerance",
         [](O& o) { o.verify.deviation_tolerance = kNaN; }},
        {"SynthesisOptions::guesses: InitialGuessOptions::sweep_step",
         [](O& o) { o.guesses.sweep_step = 0.0; }},
        {"SynthesisOptions::point_spacing", [](O& o) { o.point_spacing = 0.0; }},
        {"SynthesisOptions::min_points_per_primitive",
         [](O& o) { o.min_points_per_primitive = 0; }},
        {"SynthesisOptions::max_points_per_primitive",
         [](O& o) { o.max_points_per_primitive = 3; }},
        {"SynthesisOptions::max_points", [](O& o) { o.max_points = 0; }},
        {"SynthesisOptions::trace_samples", [](O& o) { o.trace_samples = 0.0; }},
        {"SynthesisOptions::guesses_per_skeleton", [](O& o) { o.guesses_per_skeleton = 0; }},
        {"SynthesisOptions::guesses_per_variant", [](O& o) { o.guesses_per_variant = -1; }},
        {"SynthesisOptions::shorten_gap", [](O& o) { o.shorten_gap = -1e-3; }},
        {"SynthesisOptions::length_tie", [](O& o) { o.length_tie = -1e-4; }},
        {"SynthesisOptions::shorten_reserve", [](O& o) { o.shorten_reserve = -1.0; }},
        {"SynthesisOptions::refinement_rounds", [](O& o) { o.refinement_rounds = 0; }},
        {"SynthesisOptions::first_solve_seconds", [](O& o) { o.first_solve_seconds = 0.0; }},
        {"SynthesisOptions::later_solve_seconds", [](O& o) { o.later_solve_seconds = kNaN; }},
        {"SynthesisOptions::solve_seconds_per_kvariable",
         [](O& o) { o.solve_seconds_per_kvariable = -1.0; }},
        {"SynthesisOptions::first_solve_iterations", [](O& o) { o.first_solve_iterations = 0; }},
        {"SynthesisOptions::later_solve_iterations", [](O& o) { o.later_solve_iterations = 0; }},
        {"SynthesisOptions::max_transition_depth", [](O& o) { o.max_transition_depth = 11; }},
        {"SynthesisOptions::motion_refinement_passes",
         [](O& o) { o.motion_refinement_passes = -1; }},
        {"SynthesisOptions::counterexamples_per_round",
         [](O& o) { o.counterexamples_per_round = 0; }},
        {"SynthesisOptions::front_reserve_seconds", [](O& o) { o.front_reserve_seconds = -0.1; }},
        {"SynthesisOptions::front_reserve_share", [](O& o) { o.front_reserve_share = 1.5; }},
        {"SynthesisOptions::explanation_seconds", [](O& o) { o.explanation_seconds = 0.0; }},
    });
    O bad;
    bad.refinement_rounds = 0;
    CHECK_THROWS_WITH(synth::synthesize(testing::line_task(), bad),
                      Catch::Contains("SynthesisOptions::refinement_rounds"));
}

TEST_CASE("initial guess options: defaults valid, each bad field named", "[options][synth]") {
    using O = synth::InitialGuessOptions;
    check_options<O>({
        {"InitialGuessOptions::scoring_spacing", [](O& o) { o.scoring_spacing = 0.0; }},
        {"InitialGuessOptions::max_points_per_primitive",
         [](O& o) { o.max_points_per_primitive = 3; }},
        {"InitialGuessOptions::max_points", [](O& o) { o.max_points = 0; }},
        {"InitialGuessOptions::candidates_two", [](O& o) { o.candidates_two = -1; }},
        {"InitialGuessOptions::candidates_three", [](O& o) { o.candidates_three = -1; }},
        {"InitialGuessOptions::candidates_three_detour",
         [](O& o) { o.candidates_three_detour = -1; }},
        {"InitialGuessOptions::proximal_angles", [](O& o) { o.proximal_angles = 0; }},
        {"InitialGuessOptions::sweep_step", [](O& o) { o.sweep_step = kNaN; }},
        {"InitialGuessOptions::proximal_spacing", [](O& o) { o.proximal_spacing = -0.03; }},
        {"InitialGuessOptions::max_proximal_points", [](O& o) { o.max_proximal_points = 2; }},
        {"InitialGuessOptions::hopeless_margin", [](O& o) { o.hopeless_margin = -0.05; }},
        {"InitialGuessOptions::distinct_distance", [](O& o) { o.distinct_distance = kNaN; }},
    });
    O bad;
    bad.proximal_angles = 0;
    smt::Skeleton skeleton;
    CHECK_THROWS_WITH(synth::initial_guesses(testing::line_task(), skeleton, 1, 0, {}, bad),
                      Catch::Contains("InitialGuessOptions::proximal_angles"));
}

TEST_CASE("relaxation options: defaults valid, each bad field named", "[options][explain]") {
    using O = explanation::RelaxationOptions;
    check_options<O>({
        {"RelaxationOptions::check_seconds", [](O& o) { o.check_seconds = 0.0; }},
        {"RelaxationOptions::longest_link", [](O& o) { o.longest_link = kNaN; }},
        {"RelaxationOptions::farthest_move", [](O& o) { o.farthest_move = -1.0; }},
        {"RelaxationOptions::length_tolerance", [](O& o) { o.length_tolerance = 0.0; }},
        {"RelaxationOptions::min_length_tolerance", [](O& o) { o.min_length_tolerance = kNaN; }},
        {"RelaxationOptions::diameter_tolerance", [](O& o) { o.diameter_tolerance = -1e-3; }},
        {"RelaxationOptions::radius_tolerance", [](O& o) { o.radius_tolerance = 0.0; }},
        {"RelaxationOptions::thinnest_tube", [](O& o) { o.thinnest_tube = 0.0; }},
        {"RelaxationOptions::smallest_radius", [](O& o) { o.smallest_radius = -1.0; }},
    });
    O bad;
    bad.check_seconds = -1.0;
    CHECK_THROWS_WITH(explanation::suggest_relaxations(
                          testing::line_task(),
                          {task::TaskPart::robot(task::RobotKey::MaxLinkLength)}, 1.0, 1.0, bad),
                      Catch::Contains("RelaxationOptions::check_seconds"));
}

TEST_CASE("baseline options: defaults valid, each bad field named", "[options][baseline]") {
    using B = baseline::BaselineOptions;
    check_options<B>({
        {"BaselineOptions::points", [](B& o) { o.points = 1; }},
        {"BaselineOptions::time_limit", [](B& o) { o.time_limit = 0.0; }},
        {"BaselineOptions::design_share", [](B& o) { o.design_share = 1.1; }},
        {"BaselineOptions::design: DesignOptions::smoothness_weight",
         [](B& o) { o.design.smoothness_weight = -1.0; }},
        {"BaselineOptions::planner: PlannerOptions::goal_bias",
         [](B& o) { o.planner.goal_bias = 2.0; }},
        {"BaselineOptions::fidelity: FidelityOptions::proximal_steps",
         [](B& o) { o.fidelity.proximal_steps = 0; }},
    });
    using D = baseline::DesignOptions;
    check_options<D>({
        {"DesignOptions::time_limit", [](D& o) { o.time_limit = kNaN; }},
        {"DesignOptions::smoothness_weight", [](D& o) { o.smoothness_weight = -0.5; }},
        {"DesignOptions::clearance_margin", [](D& o) { o.clearance_margin = -0.001; }},
        {"DesignOptions::self_margin", [](D& o) { o.self_margin = -0.001; }},
        {"DesignOptions::start_reach_share_two", [](D& o) { o.start_reach_share_two = 0.0; }},
        {"DesignOptions::start_reach_share_three", [](D& o) { o.start_reach_share_three = 0.0; }},
        {"DesignOptions::start_turn", [](D& o) { o.start_turn = 4.0; }},
        {"DesignOptions::feasibility_tolerance", [](D& o) { o.feasibility_tolerance = 0.0; }},
        {"DesignOptions::solver: SolverOptions::tolerance",
         [](D& o) { o.solver.tolerance = -1.0; }},
    });
    using P = baseline::PlannerOptions;
    check_options<P>({
        {"PlannerOptions::goal_bias", [](P& o) { o.goal_bias = -0.1; }},
        {"PlannerOptions::range", [](P& o) { o.range = -1.0; }},
        {"PlannerOptions::resolution", [](P& o) { o.resolution = 0.0; }},
        {"PlannerOptions::max_iterations", [](P& o) { o.max_iterations = 0; }},
        {"PlannerOptions::time_limit", [](P& o) { o.time_limit = kNaN; }},
    });
    using F = baseline::FidelityOptions;
    check_options<F>({
        {"FidelityOptions::max_joint_step", [](F& o) { o.max_joint_step = 0.0; }},
        {"FidelityOptions::path_spacing", [](F& o) { o.path_spacing = -0.002; }},
        {"FidelityOptions::proximal_steps", [](F& o) { o.proximal_steps = 0; }},
    });
    B bad;
    bad.design.self_margin = kNaN;
    CHECK_THROWS_WITH(baseline::run_baseline(testing::line_task(), bad),
                      Catch::Contains("DesignOptions::self_margin"));
    F bad_fidelity;
    bad_fidelity.path_spacing = 0.0;
    CHECK_THROWS_WITH(baseline::measure_fidelity(testing::line_task(), {}, {}, bad_fidelity),
                      Catch::Contains("FidelityOptions::path_spacing"));
    P bad_planner;
    bad_planner.resolution = 0.0;
    CHECK_THROWS_WITH(baseline::plan_rrt(testing::line_task(), {}, {}, bad_planner),
                      Catch::Contains("PlannerOptions::resolution"));
}
