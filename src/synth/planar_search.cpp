// The planar kind of the search (search_flow.h): the paper's arms of 2 and
// 3 joints in the task plane. Its proofs are the plane's (prove/provers.h),
// its front stage smt::FrontStage, its initial guesses initial_guess.h
// (with proximal plans for 3 joints), its refinement the bilinear program
// of nlp/formulation.h under the swept-volume models of swept_choice.h, its
// motion control::plan_motion and its certificate verify::certify.
#include <modsynth/synth/synthesizer.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <map>
#include <optional>
#include <set>

#include <modsynth/control/joint_limits.h>
#include <modsynth/control/motion.h>
#include <modsynth/geometry/farthest_reach.h>
#include <modsynth/geometry/primitive.h>
#include <modsynth/kinematics/chain_layout.h>
#include <modsynth/nlp/formulation.h>
#include <modsynth/nlp/solver.h>
#include <modsynth/nlp/warm_start.h>
#include <modsynth/prove/conflict_text.h>
#include <modsynth/prove/loop_proof.h>
#include <modsynth/prove/obstacle_proof.h>
#include <modsynth/prove/provers.h>
#include <modsynth/run/stopwatch.h>
#include <modsynth/smt/common_core.h>
#include <modsynth/smt/front_stage.h>
#include <modsynth/synth/initial_guess.h>
#include <modsynth/synth/proximal_plan.h>
#include <modsynth/synth/split_circles.h>
#include <modsynth/synth/swept_choice.h>
#include <modsynth/task/strokes.h>
#include <modsynth/text/format.h>
#include <modsynth/text/option_check.h>
#include <modsynth/verify/verifier.h>

#include "search_flow.h"

namespace modsynth::synth {

using prove::BranchAndBoundOptions;
using prove::describe_conflict;
using prove::Proof;
using prove::Prover;
using prove::provers;

namespace {

// Points where the refinement constrains the arm: evenly spaced along each
// primitive (critical points are added for the robot at hand).
// The count per primitive is capped, and the spacing widened when the
// whole path would need more than options.max_points, so that the program
// stays small on long paths (the counterexamples add points where they are
// needed).
std::vector<nlp::PathPoint> spaced_points(const task::Task& task, const SynthesisOptions& options) {
    double total = 0.0;
    for (const auto& p : task.trajectory) total += geometry::length(p);
    const double spacing =
        std::max(options.point_spacing, total / static_cast<double>(options.max_points));
    std::vector<nlp::PathPoint> pts;
    for (int j = 0; j < static_cast<int>(task.trajectory.size()); ++j) {
        const double len = geometry::length(task.trajectory[j]);
        const int n = static_cast<int>(std::clamp(
            std::ceil(len / spacing), static_cast<double>(options.min_points_per_primitive),
            static_cast<double>(options.max_points_per_primitive)));
        for (int i = 0; i <= n; ++i) pts.push_back({j, len * i / n});
    }
    return pts;
}

// The paper's points (eq. 1): the ends of every primitive; the critical
// points are added for the robot at hand.
std::vector<nlp::PathPoint> end_points(const task::Task& task) {
    std::vector<nlp::PathPoint> pts;
    for (int j = 0; j < static_cast<int>(task.trajectory.size()); ++j) {
        pts.push_back({j, 0.0});
        pts.push_back({j, geometry::length(task.trajectory[j])});
    }
    return pts;
}

void add_point(std::vector<nlp::PathPoint>& pts, int j, double s) {
    for (const auto& p : pts)
        if (p.primitive == j && std::abs(p.s - s) < 1e-4) return;
    pts.push_back({j, s});
}

// The critical points of every primitive relative to the point the distal
// pair turns about while tracing it: the base, or with three joints the end
// of the proximal link.
void add_critical_points(const task::Task& task, const kinematics::Robot& robot,
                         std::vector<nlp::PathPoint>& points) {
    for (int j = 0; j < static_cast<int>(task.trajectory.size()); ++j) {
        const bool known =
            !robot.has_proximal_link() || j < static_cast<int>(robot.proximal_angles.size());
        const auto cp = geometry::critical_points(task.trajectory[j],
                                                  known ? robot.tracing_origin(j) : robot.base);
        add_point(points, j, cp.closest.s);
        add_point(points, j, cp.farthest.s);
    }
}

/// How the statistics name a robot certified with its planned proximal
/// angles, unrefined.
constexpr const char* kPlanned = "proximal plan";

// The design a proximal plan is a function of.
std::vector<double> design_key(const kinematics::Robot& robot) {
    std::vector<double> key{static_cast<double>(robot.elbow), robot.base.x(), robot.base.y()};
    key.insert(key.end(), robot.link_lengths.begin(), robot.link_lengths.end());
    return key;
}

/// The plane's front stage: skeletons one at a time, each blocked before
/// the next is looked for.
class PlanarFront : public FrontStageRun<smt::Skeleton> {
public:
    PlanarFront(const task::Task& task, int dof, const smt::FrontStageOptions& options,
                SearchRun& run)
        : front_(task, dof, options), run_(run) {}

    FrontAnswer check() override {
        result_ = front_.check();
        switch (result_) {
            case smt::FrontStage::Result::Sat:
                return FrontAnswer::Sat;
            case smt::FrontStage::Result::Unsat:
                return FrontAnswer::Unsat;
            case smt::FrontStage::Result::Unknown:
                return FrontAnswer::Unknown;
        }
        return FrontAnswer::Unknown;
    }
    std::vector<task::TaskPart> minimal_core() override { return front_.minimal_core(); }
    bool conflicts(const std::vector<task::TaskPart>& parts) override {
        return front_.conflicts(parts);
    }
    std::string reason_unknown() const override { return front_.reason_unknown(); }
    std::optional<smt::Skeleton> next() override {
        if (last_) {
            front_.block(*last_);
            const run::Stopwatch t1;
            result_ = front_.check();
            run_.stats.front_seconds += t1.seconds();
        }
        if (result_ != smt::FrontStage::Result::Sat || run_.remaining() <= 0.0) return std::nullopt;
        last_ = front_.skeleton();
        return last_;
    }
    bool exhausted() const override { return result_ != smt::FrontStage::Result::Sat; }

private:
    smt::FrontStage front_;
    SearchRun& run_;
    smt::FrontStage::Result result_ = smt::FrontStage::Result::Unknown;
    std::optional<smt::Skeleton> last_;
};

/// An initial guess, and the robot its refinements start from: the guess
/// with the proximal angles a plan found (3 joints).
struct PlanarGuess {
    ScoredRobot scored;
    kinematics::Robot start;
};

/// One refinement: the program's points, the swept-volume model, and the
/// last round's program and solution, which the next round warm-starts
/// from.
struct PlanarProblem {
    nlp::ArmProblem arm;
    const char* name = "";
    std::optional<nlp::Formulation> last;
    nlp::SolverResult last_result;
};

class PlanarKind {
public:
    using Task = task::Task;
    using Skeleton = smt::Skeleton;
    using Design = kinematics::Robot;
    using Guess = PlanarGuess;
    using Attempt = SweptAttempt;
    using Problem = PlanarProblem;

    PlanarKind(const task::Task& task, const SynthesisOptions& options, SearchRun& run)
        : task_(task), opt_(options), run_(run), motion_(motion_options_for(task, options)) {
        motion_.deadline = run.deadline;
        // Where refinements of three joints fail or crawl: a stroke longer
        // than the guesses score whole, or a loop round an obstacle, round
        // which link 1 must be carried from one transition to the next.
        for (int s = 0; s < task::stroke_count(task) && !plan_first_; ++s)
            plan_first_ = task::stroke_last(task, s) - task::stroke_first(task, s) >=
                          options.guesses.coarse_primitives;
        plan_first_ = plan_first_ || prove::loop_around_obstacle(task).has_value();
    }

    const task::Task& task() const { return task_; }
    const control::RetimeOptions& retime() const { return opt_.retime; }
    SearchSettings settings() const {
        return {opt_.seed,
                1,
                opt_.guesses_per_skeleton,
                opt_.guesses_per_variant,
                opt_.refinement_rounds,
                opt_.motion_refinement_passes,
                opt_.counterexamples_per_round,
                opt_.length_tie,
                opt_.shorten_reserve};
    }

    // The provers first (provers.h): exact geometry in milliseconds, where
    // the front stage could only search.
    std::optional<Proof> prove() {
        const BranchAndBoundOptions bnb = branch_and_bound_budget();
        const run::Stopwatch proving;
        for (const Prover& prover : provers(bnb)) {
            std::optional<Proof> proof = prover.prove(task_, run_.deadline);
            if (!proof) continue;
            run_.stats.front_seconds += proving.seconds();
            run_.say(run::Stage::Proofs,
                     std::string(prover.name) + ": proved infeasible, " + proof->message);
            return proof;
        }
        run_.stats.front_seconds += proving.seconds();
        return std::nullopt;
    }

    std::vector<int> joint_counts() const { return task_.robot.dof; }

    // A loop of the path round an obstacle (loop_proof.h) rules 2 joints
    // out with a proof, in microseconds, where the front stage would offer
    // skeletons whose every refinement runs a link through the obstacle.
    // With more joints a loop that is one primitive rules out only
    // modsynth's motions, which keep the proximal links still along a
    // primitive: that is said, and is no proof.
    bool ruled_out(int dof, Verdicts<Skeleton>& verdicts) {
        const run::Stopwatch t0;
        if (dof == 2) {
            const auto loop = prove::loop_around_obstacle(task_);
            run_.stats.front_seconds += t0.seconds();
            if (!loop) return false;
            prove::Proof proof = prove::two_joint_loop_proof(task_, *loop);
            run_.say(run::Stage::Proofs, "2 joints: proved infeasible, " + proof.message);
            // Not the core's names: a loop may be thousands of primitives.
            run_.tried.push_back("2 joints proved infeasible (" +
                                 prove::describe_loop(task_, *loop) + ")");
            verdicts.own_proofs.push_back("with 2 joints, " + proof.message);
            verdicts.cores.push_back(std::move(proof.core));
            return true;
        }
        const auto loop = prove::loop_around_obstacle(task_, 1);
        run_.stats.front_seconds += t0.seconds();
        if (!loop) return false;
        const std::string why =
            prove::describe_loop(task_, *loop) + ", and modsynth's motions keep the first " +
            (dof == 3 ? std::string("link") : std::to_string(dof - 2) + " links") +
            " still along a primitive";
        run_.say(run::Stage::Search, std::to_string(dof) + " joints: not searched: " + why);
        run_.tried.push_back(std::to_string(dof) + " joints not searched (" + why + ")");
        verdicts.all_unsat = false;
        return true;
    }

    std::unique_ptr<FrontStageRun<Skeleton>> front_stage(int dof) {
        smt::FrontStageOptions fo = opt_.front;
        fo.time_limit = std::min(opt_.front.time_limit, std::max(0.1, run_.remaining()));
        // Tearing down a large encoding takes time too: the front stage
        // stops a little before the run must end.
        fo.deadline = run_.deadline.reserve(
            std::min(opt_.front_reserve_seconds, opt_.front_reserve_share * opt_.time_limit));
        return std::make_unique<PlanarFront>(task_, dof, fo, run_);
    }

    // Where more joints are allowed, the branch and bound that proves a
    // task of 2 joints only infeasible (provers.h) drops 2 joints from the
    // retries: a proof, said as the loop's is. Not before the first pass,
    // which certifies most tasks that 2 joints can do at less than its cost.
    void prune_retries(Verdicts<Skeleton>& verdicts) {
        auto& searched = verdicts.searched;
        const auto two = [](const smt::Skeleton& sk) { return sk.dof == 2; };
        if (std::none_of(searched.begin(), searched.end(), two) || task_.robot.dof.size() < 2)
            return;  // dof [2]: the provers ran it
        BranchAndBoundOptions bnb = branch_and_bound_budget();
        // A search that finds no proof here only delays the joint counts
        // that can do the task: it gets a count of boxes (the same on every
        // machine) rather than all of its share.
        bnb.max_boxes = std::min(bnb.max_boxes, opt_.branch_and_bound_boxes_beside);
        // Its core is not shrunk: it only drops a joint count, and an
        // answer of "infeasible" has its core shrunk with the other joint
        // counts'.
        bnb.core_time_limit = 0.0;
        if (!(bnb.time_limit > 0.0) || bnb.max_boxes < 1) return;
        task::Task two_only = task_;
        two_only.robot.dof = {2};
        const run::Stopwatch t0;
        std::optional<Proof> proof =
            prove::prove_two_joint_infeasible(two_only, bnb, run_.deadline);
        run_.stats.front_seconds += t0.seconds();
        if (!proof) return;
        run_.say(run::Stage::Proofs, "2 joints: proved infeasible, " + proof->message);
        run_.tried.push_back("2 joints proved infeasible (by branch and bound)");
        verdicts.own_proofs.push_back("with 2 joints, " + proof->message);
        verdicts.cores.push_back(std::move(proof->core));
        searched.erase(std::remove_if(searched.begin(), searched.end(), two), searched.end());
    }

    Proof common_proof(const Verdicts<Skeleton>& verdicts) {
        Proof proof;
        proof.core =
            smt::common_core(task_, verdicts.cores,
                             std::max(0.1, std::min(opt_.explanation_seconds, run_.remaining())));
        proof.message = describe_conflict(task_, proof.core);
        // A core the front stage checked for every joint count speaks for
        // itself; otherwise each joint count's own proof is said first.
        if (!verdicts.own_proofs.empty() &&
            std::none_of(verdicts.cores.begin(), verdicts.cores.end(),
                         [&](const auto& c) { return c == proof.core; })) {
            std::string own;
            for (std::size_t i = 0; i < verdicts.own_proofs.size(); ++i)
                own += (i ? " " : "") + verdicts.own_proofs[i];
            proof.message = own + " With more joints, " + proof.message;
        }
        return proof;
    }

    // Three joints: the plans of several guesses come before any
    // refinement, which costs far more than a plan on a long path. Without
    // refinements (a variant of a robot its plan found) the guesses get
    // what the robot found took, times shorten_reserve: scored whole where
    // few are clear, they took seconds on a 100-segment loop.
    std::vector<Guess> guesses(const Skeleton& skeleton, int count, unsigned seed,
                               bool refine_too) {
        const bool plan = planning(skeleton);
        const run::Deadline guessing =
            refine_too ? run_.deadline
                       : run_.deadline.within(opt_.shorten_reserve *
                                              std::max(run_.certified_seconds, 0.1));
        std::vector<Guess> out;
        for (ScoredRobot& g :
             initial_guesses(task_, skeleton,
                             plan && refine_too ? std::max(count, opt_.proximal.guesses) : count,
                             seed, guessing, opt_.guesses))
            out.push_back({g, g.robot});
        return out;
    }

    // Three joints: with the start's design fixed, where the proximal link
    // stands along the path is a shortest path over (primitive, angle)
    // (proximal_plan.h), linear in the primitives. A plan the verifier
    // certifies is the answer; otherwise its angles start the refinement,
    // which then moves the design too.
    template <class Flow>
    std::optional<Solution> before_refinement(const Skeleton& skeleton, std::vector<Guess>& guesses,
                                              bool, Flow& flow) {
        if (!planning(skeleton)) return std::nullopt;
        for (Guess& g : guesses) {
            if (run_.remaining() <= 0.0) return std::nullopt;
            // A plan is a function of the design: one planned before is not again.
            if (!planned_.insert(design_key(g.scored.robot)).second) continue;
            const kinematics::Robot& r = g.scored.robot;
            run_.say(run::Stage::Search,
                     text::format("  design: base (%.3f, %.3f), total length %.3f m", r.base.x(),
                                  r.base.y(), r.total_length()) +
                         text::format(", margin %.4f m", g.scored.margin));
            const run::Stopwatch t0;
            const ProximalPlan plan =
                plan_proximal_angles(task_, g.start, opt_.proximal, run_.deadline);
            run_.stats.refine_seconds += t0.seconds();
            if (!plan.found) {
                run_.say(run::Stage::Search, text::format("    proximal plan: none (%s), %.3f s",
                                                          plan.message.c_str(), t0.seconds()));
                continue;
            }
            run_.say(run::Stage::Search,
                     text::format("    proximal plan: %d move(s), margin %.4f m, %.3f s",
                                  plan.moves, plan.margin, t0.seconds()));
            g.start.proximal_angles = plan.angles;
            Verdict verdict = flow.judge(g.start);
            if (!verdict.solution) continue;
            run_.stats.certified_by = kPlanned;
            if (run_.stats.first_certified_by.empty())
                run_.stats.first_certified_by = run_.stats.certified_by;
            return std::move(verdict.solution);
        }
        return std::nullopt;
    }

    std::vector<Attempt> attempts(const Skeleton& skeleton, const Guess& g) const {
        return swept_attempts(opt_.swept, task_, skeleton, g.scored.robot);
    }

    // What a refinement is a function of (the time left aside): the
    // skeleton's discrete choices, the swept-volume model and the start
    // robot.
    std::vector<double> key(const Skeleton& skeleton, const Guess& g, const Attempt& a) const {
        const kinematics::Robot& start = g.scored.robot;
        std::vector<double> key{static_cast<double>(skeleton.dof),
                                static_cast<double>(skeleton.elbow),
                                static_cast<double>(skeleton.base_region),
                                static_cast<double>(a.swept),
                                a.paper ? 1.0 : 0.0,
                                start.base.x(),
                                start.base.y()};
        key.insert(key.end(), start.link_lengths.begin(), start.link_lengths.end());
        key.insert(key.end(), start.proximal_angles.begin(), start.proximal_angles.end());
        return key;
    }

    Problem problem(const Skeleton& skeleton, const Guess& g, const Attempt& attempt) const {
        Problem p;
        p.name = name_of(attempt);
        p.arm.task = &task_;
        p.arm.skeleton = skeleton;
        p.arm.start = g.start;
        p.arm.swept = attempt.swept;
        p.arm.swept_only = attempt.paper;
        p.arm.points = attempt.paper ? end_points(task_) : spaced_points(task_, opt_);
        add_critical_points(task_, g.start, p.arm.points);
        return p;
    }

    // One round: the program as it stands, solved by Ipopt from the last
    // round's solution and multipliers (nlp::carry_over) when there was
    // one. A refinement that needs more than its budget is better
    // restarted from another initial guess than waited for.
    std::optional<Design> solve(Problem& p, int round, const Guess&) {
        const run::Stopwatch t0;
        nlp::Formulation f = nlp::formulate(p.arm);
        nlp::SolverOptions so;
        const double budget =
            std::max(round == 0 ? opt_.first_solve_seconds : opt_.later_solve_seconds,
                     opt_.solve_seconds_per_kvariable * 1e-3 * f.program.num_variables());
        so.time_limit = std::min(budget, std::max(0.05, run_.remaining()));
        so.max_iterations = round == 0 ? opt_.first_solve_iterations : opt_.later_solve_iterations;
        so.deadline = run_.deadline.at_least(0.05);
        std::optional<nlp::WarmStart> warm;
        if (p.last && opt_.warm_start_rounds)
            warm = nlp::carry_over(p.last->program, p.last_result, f.program);
        const nlp::SolverResult res = nlp::minimize(f.program, so, warm ? &*warm : nullptr);
        if (!res.usable()) {
            run_.say(run::Stage::Refinement,
                     std::string("    ") + p.name +
                         text::format(": refinement did not converge in %d iterations, %.3f s (",
                                      res.iterations, t0.seconds()) +
                         res.message + ")");
            return std::nullopt;
        }
        kinematics::Robot robot = nlp::robot_from(f, res.x);
        const int variables = f.program.num_variables();
        p.last = std::move(f);
        p.last_result = res;
        std::string links;
        for (double r : robot.link_lengths)
            links += text::format(links.empty() ? "%.4f" : " + %.4f", r);
        run_.say(run::Stage::Refinement,
                 std::string("    ") + p.name + ": candidate links " + links +
                     text::format(" m with %zu points, %d variables, in %d iterations, %.3f s",
                                  p.arm.points.size(), variables, res.iterations, t0.seconds()));
        return robot;
    }

    // The next round's program: the failed robot's counterexamples, its
    // critical points, and (three joints) more proximal poses in
    // transitions, up to the cap. After a swept-volume model's round the
    // sampled model (lines) takes over, at the sampled points too.
    int learn(Problem& p, const Verdict& verdict, const Design& robot) {
        nlp::ArmProblem next = p.arm;
        int deeper = 0;
        for (const PathPlace& place : verdict.places)
            if (place.transition) ++deeper;
        if (deeper > 0 && next.transition_depth < opt_.max_transition_depth)
            next.transition_depth =
                std::min(opt_.max_transition_depth, next.transition_depth + deeper);
        for (const PathPlace& place : verdict.places)
            if (!place.transition) add_point(next.points, place.primitive, place.s);
        add_critical_points(task_, robot, next.points);
        if (next.points.size() == p.arm.points.size() &&
            next.transition_depth == p.arm.transition_depth)
            return -1;
        const int added = static_cast<int>(next.points.size() - p.arm.points.size());
        next.start = robot;
        if (next.swept != nlp::SweptVolume::Sampled) ++run_.stats.fallbacks;
        if (next.swept_only)
            for (const auto& q : spaced_points(task_, opt_))
                add_point(next.points, q.primitive, q.s);
        next.swept = nlp::SweptVolume::Sampled;
        next.swept_only = false;
        p.name = "sampled";
        p.arm = std::move(next);
        return added;
    }

    std::string model_name(const Problem& p) const { return p.name; }

    std::optional<std::vector<control::Sample>> plan(const Design& robot,
                                                     control::MotionFailure* failure) const {
        return control::plan_motion(task_, robot, motion_, failure);
    }
    verify::Certificate certify(const Design& robot,
                                const std::vector<control::Sample>& samples) const {
        return verify::certify(task_, robot, samples, verify::options_for(motion_, opt_.verify));
    }
    bool refine_motion(const Design& robot, std::vector<control::Sample>& samples,
                       const std::vector<int>& pairs) const {
        return control::refine_motion(task_, robot, samples, pairs);
    }
    Solution solution(const Design& robot, std::vector<control::Sample> samples,
                      verify::Certificate cert) const {
        Solution out;
        out.task_name = task_.name;
        out.status = Status::Solved;
        out.robot = robot;
        out.samples = std::move(samples);
        out.certificate = std::move(cert);
        return out;
    }

    // The first certified robot is often not the shortest: the refinement
    // only sees its own elbow sign and base region, and the other branch
    // can need much shorter links (on tasks/rose.json, 0.54 m against
    // 0.97 m). Each other elbow sign and base region gets one initial
    // guess, unless the region cannot hold a robot shorter by more than
    // shorten_gap (a proved bound).
    template <class Flow>
    void shorten(const Skeleton& found, typename Flow::Shortlist& list, Flow& flow) {
        for (int region : task::base_region_choices(task_)) {
            const double bound = shortest_possible(region, found.dof);
            if (bound >= list.shortest() - opt_.shorten_gap) {
                run_.say(run::Stage::Shortening,
                         text::format("%d joints: no robot with base region %d is shorter than "
                                      "%.4f m",
                                      found.dof, region, bound));
                // The other elbow could then give a robot about as long that
                // passes farther from the obstacles. The robot found, with
                // the other elbow, is one such: it reaches the same points,
                // and costs a verification, not a refinement.
                if (region == found.base_region && list.size() == 1) {
                    if (!flow.time_for_variant(found.dof)) return;
                    kinematics::Robot other = list.first().robot;
                    other.elbow = -other.elbow;
                    run_.say(run::Stage::Shortening,
                             text::format("%d joints: the same robot with elbow %+d?", found.dof,
                                          other.elbow));
                    if (auto twin = flow.judge(other).solution) list.add_twin(std::move(*twin));
                }
                continue;
            }
            for (int elbow : {1, -1}) {
                if (region == found.base_region && elbow == found.elbow) continue;
                if (!flow.time_for_variant(found.dof)) return;
                smt::Skeleton variant = found;
                variant.base_region = region;
                variant.elbow = elbow;
                run_.say(run::Stage::Shortening,
                         text::format("%d joints: shorter robot with elbow %+d, base region %d?",
                                      found.dof, elbow, region));
                // A robot the plan found alone is compared with the plans of
                // the variants: a refinement of a long path costs many plans.
                auto candidate = flow.try_skeleton(variant, opt_.guesses_per_variant, opt_.seed,
                                                   run_.stats.first_certified_by != kPlanned);
                if (candidate) list.offer(std::move(*candidate), run_.stats.certified_by);
            }
        }
    }

    std::string describe(const Skeleton& sk) const {
        return text::format("elbow %+d, base region %d", sk.elbow, sk.base_region);
    }
    std::string describe(const Guess& g) const {
        const kinematics::Robot& r = g.scored.robot;
        return text::format("base (%.3f, %.3f), total length %.3f m", r.base.x(), r.base.y(),
                            r.total_length()) +
               text::format(", margin %.4f m", g.scored.margin);
    }
    std::string describe_choice(const Solution& s) const {
        return text::format("elbow %+d", s.robot.elbow);
    }
    int dof_of(const Skeleton& sk) const { return sk.dof; }
    int dof_of(const Design& robot) const { return robot.dof(); }
    int dof_of(const Solution& s) const { return s.robot.dof(); }
    double length_of(const Solution& s) const { return s.robot.total_length(); }

private:
    bool planning(const Skeleton& skeleton) const {
        return plan_first_ && kinematics::has_proximal_link(skeleton.dof);
    }

    /// The branch and bound's options within its share of the run: its
    /// core shrunk only within what the proof leaves of that share.
    BranchAndBoundOptions branch_and_bound_budget() const {
        BranchAndBoundOptions bnb = opt_.branch_and_bound;
        bnb.time_limit = std::min(bnb.time_limit, opt_.branch_and_bound_share * opt_.time_limit);
        bnb.core_time_limit = std::min(bnb.core_time_limit, bnb.time_limit);
        return bnb;
    }

    // A lower bound on the total link length of any robot of `dof` joints
    // with its base in the region: every link is at least the task's
    // shortest, and the arm reaches the path point farthest from its base.
    double shortest_possible(int base_region, int dof) {
        auto it = least_reach_.find(base_region);
        if (it == least_reach_.end()) {
            geometry::FarthestReachOptions o;
            o.tolerance = std::max(1e-6, 0.25 * opt_.shorten_gap);
            const geometry::FarthestReach reach =
                base_region < 0 ? geometry::least_farthest_reach(task_.trajectory, o)
                                : geometry::least_farthest_reach(
                                      task_.trajectory, task_.base_regions[base_region].min,
                                      task_.base_regions[base_region].max, o);
            it = least_reach_.emplace(base_region, reach.lower).first;
        }
        return std::max(it->second, dof * task_.robot.min_link_length);
    }

    const task::Task& task_;
    const SynthesisOptions& opt_;
    SearchRun& run_;
    control::MotionOptions motion_;
    /// Designs whose proximal angles were planned (three joints).
    std::set<std::vector<double>> planned_;
    /// Three joints: each guess's proximal angles are planned along the
    /// path, and certified as they are, before any refinement
    /// (proximal_plan.h). Elsewhere the refinement alone, as it finds
    /// shorter links.
    bool plan_first_ = false;
    /// By base region (-1: anywhere): the least farthest reach of the path.
    std::map<int, double> least_reach_;
};

static_assert(SearchKind<PlanarKind>);

Solution search(const task::Task& task, const SynthesisOptions& options, SynthesisStats& stats) {
    SearchRun run(run::Deadline::in(std::max(0.0, options.time_limit)).cancelled_by(options.cancel),
                  options.progress, stats);
    PlanarKind kind(task, options, run);
    return SearchFlow<PlanarKind>(kind, run).run();
}

// A circle that winds round an obstacle is out of reach of modsynth's
// motions as it stands (PlanarKind::ruled_out): cut into arcs, it is
// searched again with what is left of the time, fewer arcs first (each cut
// is one more place where the first link may turn, and one more transition
// to plan). The motion found is read back as one of the circle and
// certified against the task as written.
Solution through_arcs(const task::Task& task, const SynthesisOptions& options,
                      SynthesisStats& stats, Solution unknown, const run::Stopwatch& clock) {
    const auto loop = prove::loop_around_obstacle(task, 1);
    if (!loop || *std::max_element(task.robot.dof.begin(), task.robot.dof.end()) < 3)
        return unknown;
    std::vector<std::string> tried;
    for (const int arcs : {8, 16, 32}) {
        const double left = options.time_limit - clock.seconds();
        if (left < 0.1 || options.cancel.cancelled()) break;
        const SplitTask split = split_circles(task, arcs);
        SynthesisOptions o = options;
        o.time_limit = left;
        const double before = clock.seconds();
        if (options.progress)
            o.progress = [&](const run::ProgressEvent& e) {
                options.progress({e.stage, e.message, before + e.elapsed});
            };
        const std::string cut =
            text::format("%s cut into %d arcs", task::part_name(task, loop->first).c_str(), arcs);
        if (o.progress)
            o.progress({run::Stage::Search,
                        cut + ", so that the first link may turn inside it (the lines that follow "
                              "number the primitives of that task of arcs)",
                        0.0});
        Solution found = search(split.task, o, stats);
        if (found.status != Status::Solved) {
            tried.push_back(cut + ": " + to_string(found.status.kind));
            continue;
        }
        found.samples = join_arcs(task, split, std::move(found.samples));
        found.certificate =
            verify::certify(task, found.robot, found.samples, verify_options_for(task, options));
        if (found.certificate.ok) return found;
        tried.push_back(cut + ": its motion read back as one of the circle failed verification (" +
                        (found.certificate.violations.empty()
                             ? std::string("no reason given")
                             : found.certificate.violations.front().message) +
                        ")");
    }
    if (!tried.empty()) {
        std::string said;
        for (std::size_t i = 0; i < tried.size(); ++i) said += (i ? "; " : "") + tried[i];
        unknown.explanation.message += " Then " + said + ".";
    }
    return unknown;
}

}  // namespace

bool SynthesisOptions::IsValid(std::string* error) const {
    return text::OptionCheck("SynthesisOptions", error)
        .at_least("time_limit", time_limit, 0.0)
        .nested("motion", motion)
        .nested("retime", retime)
        .nested("front", front)
        .nested("verify", verify)
        .nested("guesses", guesses)
        .nested("proximal", proximal)
        .nested("branch_and_bound", branch_and_bound)
        .within("branch_and_bound_share", branch_and_bound_share, 0.0, 1.0)
        .at_least("branch_and_bound_boxes_beside",
                  static_cast<double>(branch_and_bound_boxes_beside), 0.0)
        .greater("point_spacing", point_spacing, 0.0)
        .at_least("min_points_per_primitive", min_points_per_primitive, 1)
        .at_least("max_points_per_primitive", max_points_per_primitive, min_points_per_primitive)
        .at_least("max_points", max_points, 1)
        .greater("trace_samples", trace_samples, 0.0)
        .at_least("guesses_per_skeleton", guesses_per_skeleton, 1)
        .at_least("guesses_per_variant", guesses_per_variant, 0)
        .at_least("shorten_gap", shorten_gap, 0.0)
        .at_least("length_tie", length_tie, 0.0)
        .at_least("shorten_reserve", shorten_reserve, 0.0)
        .at_least("refinement_rounds", refinement_rounds, 1)
        .greater("first_solve_seconds", first_solve_seconds, 0.0)
        .greater("later_solve_seconds", later_solve_seconds, 0.0)
        .at_least("solve_seconds_per_kvariable", solve_seconds_per_kvariable, 0.0)
        .at_least("first_solve_iterations", first_solve_iterations, 1)
        .at_least("later_solve_iterations", later_solve_iterations, 1)
        .within("max_transition_depth", max_transition_depth, 0, 10)
        .at_least("motion_refinement_passes", motion_refinement_passes, 0)
        .at_least("counterexamples_per_round", counterexamples_per_round, 1)
        .at_least("front_reserve_seconds", front_reserve_seconds, 0.0)
        .within("front_reserve_share", front_reserve_share, 0.0, 1.0)
        .greater("explanation_seconds", explanation_seconds, 0.0)
        .ok();
}

control::MotionOptions motion_options_for(const task::Task& task, const SynthesisOptions& options) {
    control::MotionOptions motion = options.motion;
    // A long path is sampled more coarsely rather than without bound; the
    // verifier certifies whatever steps the motion takes.
    double total = 0.0;
    for (const auto& p : task.trajectory) total += geometry::length(p);
    motion.max_ee_step = std::max(motion.max_ee_step, total / options.trace_samples);
    return motion;
}

verify::VerifyOptions verify_options_for(const task::Task& task, const SynthesisOptions& options) {
    return verify::options_for(motion_options_for(task, options), options.verify);
}

Solution synthesize(const task::Task& task, const SynthesisOptions& options,
                    SynthesisStats* stats) {
    text::require_valid(options);
    SynthesisStats local;
    SynthesisStats& s = stats ? *stats : local;
    const run::Stopwatch clock;
    Solution out = search(task, options, s);
    if (out.status != Status::Unknown) return out;
    return through_arcs(task, options, s, std::move(out), clock);
}

}  // namespace modsynth::synth
