#include <modsynth/synth/synthesizer.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <optional>
#include <set>

#include <modsynth/control/joint_limits.h>
#include <modsynth/control/motion.h>
#include <modsynth/control/path_corners.h>
#include <modsynth/control/retime.h>
#include <modsynth/geometry/distance.h>
#include <modsynth/geometry/farthest_reach.h>
#include <modsynth/geometry/polygon.h>
#include <modsynth/geometry/primitive.h>
#include <modsynth/kinematics/chain_layout.h>
#include <modsynth/kinematics/clearance_rule.h>
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
#include <modsynth/synth/blockers.h>
#include <modsynth/synth/design_choice.h>
#include <modsynth/synth/initial_guess.h>
#include <modsynth/synth/proximal_plan.h>
#include <modsynth/synth/split_circles.h>
#include <modsynth/task/strokes.h>
#include <modsynth/text/format.h>
#include <modsynth/text/option_check.h>
#include <modsynth/verify/verifier.h>

namespace modsynth::synth {

using prove::BranchAndBoundOptions;
using prove::describe_conflict;
using prove::Proof;
using prove::Prover;
using prove::provers;

namespace {

std::string join(const std::vector<std::string>& v, const char* sep) {
    std::string s;
    for (std::size_t i = 0; i < v.size(); ++i) s += (i ? sep : "") + v[i];
    return s;
}

std::string names(const std::vector<task::TaskPart>& parts) {
    std::vector<std::string> v;
    for (const task::TaskPart& p : parts) v.push_back(task::to_string(p));
    return join(v, ", ");
}

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

/// What planning and certifying one candidate robot came to: a certified
/// answer, or what the next refinement must take in (counterexample-guided).
struct Verdict {
    std::optional<Solution> solution;
    /// Motion planning gave up (a deadline, a cap): nothing was learnt.
    bool gave_up = false;
    /// Where along the path the robot failed: (primitive, arc length).
    std::vector<std::pair<int, double>> points;
    /// Failures in transitions: each asks for more proximal poses there.
    int deeper_transitions = 0;
};

class Search {
public:
    Search(const task::Task& task, const SynthesisOptions& options, SynthesisStats& stats)
        : task_(task),
          opt_(options),
          stats_(stats),
          deadline_(
              run::Deadline::in(std::max(0.0, options.time_limit)).cancelled_by(options.cancel)),
          motion_(motion_options_for(task, options)) {
        motion_.deadline = deadline_;
        // Where refinements of three joints fail or crawl: a stroke longer
        // than the guesses score whole, or a loop round an obstacle, round
        // which link 1 must be carried from one transition to the next.
        for (int s = 0; s < task::stroke_count(task) && !plan_first_; ++s)
            plan_first_ = task::stroke_last(task, s) - task::stroke_first(task, s) >=
                          options.guesses.coarse_primitives;
        plan_first_ = plan_first_ || prove::loop_around_obstacle(task).has_value();
    }

    Solution run();

private:
    /// What the front stage concluded for each joint count.
    struct FrontStageVerdicts {
        /// The cores of the joint counts proved infeasible.
        std::vector<std::vector<task::TaskPart>> cores;
        /// In words, the proofs of joint counts that the front stage cannot
        /// check (a loop round an obstacle, for 2 joints); their cores are
        /// in `cores` too.
        std::vector<std::string> own_proofs;
        std::vector<smt::Skeleton> searched;  ///< every skeleton tried, for the retries
        bool all_unsat = true;                ///< every joint count proved infeasible
    };
    std::optional<Proof> find_proof();
    bool ruled_out(int dof, FrontStageVerdicts& verdicts);
    bool two_joints_bounded(FrontStageVerdicts& verdicts);
    /// The branch and bound's options within its share of the run: its
    /// core shrunk only within what the proof leaves of that share.
    BranchAndBoundOptions branch_and_bound_budget() const {
        BranchAndBoundOptions bnb = opt_.branch_and_bound;
        bnb.time_limit = std::min(bnb.time_limit, opt_.branch_and_bound_share * opt_.time_limit);
        bnb.core_time_limit = std::min(bnb.core_time_limit, bnb.time_limit);
        return bnb;
    }
    std::optional<Solution> search_skeletons(FrontStageVerdicts& verdicts);
    Solution infeasible(Proof proof) const;
    Solution unknown(const std::vector<std::vector<task::TaskPart>>& cores) const;
    Solution timed(Solution solution);
    double motion_seconds(const Solution& solution) const;
    double remaining() const { return deadline_.remaining(); }
    void say(run::Stage stage, const std::string& message) {
        stage_ = message;
        if (opt_.progress) opt_.progress({stage, message, clock_.seconds()});
    }
    // Each step takes values and gives values: skeleton -> refined robot ->
    // verdict on its motion -> (certified solution | the next problem).
    std::optional<Solution> try_skeleton(const smt::Skeleton& skeleton, int guesses, unsigned seed,
                                         bool refine_too = true);
    std::optional<Solution> retry(const std::vector<smt::Skeleton>& skeletons);
    Solution shorten(const smt::Skeleton& found, Solution first);
    double shortest_possible(int base_region, int dof);
    std::optional<Solution> refine(const smt::Skeleton& skeleton, const kinematics::Robot& start,
                                   SweptAttempt attempt);
    std::optional<Solution> planned(kinematics::Robot& start);
    Verdict judge(const kinematics::Robot& robot);
    nlp::ArmProblem learn(nlp::ArmProblem problem, const Verdict& verdict,
                          const kinematics::Robot& robot) const;

    const task::Task& task_;
    const SynthesisOptions& opt_;
    SynthesisStats& stats_;
    const run::Stopwatch clock_;
    const run::Deadline deadline_;
    control::MotionOptions motion_;
    std::vector<std::string> tried_;
    /// Refinements that failed, by skeleton, swept-volume model and start
    /// robot: a refinement is a function of these, so it is never repeated
    /// (the shortening pass and the retries would otherwise redo them).
    std::set<std::vector<double>> failed_;
    /// Designs whose proximal angles were planned (three joints).
    std::set<std::vector<double>> planned_;
    /// Three joints: each guess's proximal angles are planned along the
    /// path, and certified as they are, before any refinement
    /// (proximal_plan.h). Elsewhere the refinement alone, as it finds
    /// shorter links.
    bool plan_first_ = false;
    std::string stage_ = "before the front stage";  ///< the last stage said, for an unknown answer
    /// Seconds the refinement of the last certified robot took, all rounds.
    double certified_seconds_ = 0.0;
    /// By base region (-1: anywhere): the least farthest reach of the path.
    std::map<int, double> least_reach_;
    Blockers blocked_;  ///< what stopped the candidates, for an unknown answer
};

Solution Search::run() {
    if (auto proof = find_proof()) return infeasible(std::move(*proof));
    FrontStageVerdicts verdicts;
    if (auto found = search_skeletons(verdicts)) return timed(std::move(*found));
    // Blocking skeletons proves nothing: while time is left, their other
    // initial guesses are tried.
    // Before 2 joints' skeletons are retried, the branch and bound may
    // prove that none can be certified: they are dropped.
    auto& searched = verdicts.searched;
    const auto two = [](const smt::Skeleton& sk) { return sk.dof == 2; };
    if (std::any_of(searched.begin(), searched.end(), two) && two_joints_bounded(verdicts))
        searched.erase(std::remove_if(searched.begin(), searched.end(), two), searched.end());
    if (!searched.empty())
        if (auto found = retry(searched)) return timed(std::move(*found));
    if (verdicts.all_unsat && !verdicts.cores.empty()) {
        const run::Stopwatch t0;
        Proof proof;
        proof.core = smt::common_core(
            task_, verdicts.cores, std::max(0.1, std::min(opt_.explanation_seconds, remaining())));
        proof.message = describe_conflict(task_, proof.core);
        // A core the front stage checked for every joint count speaks for
        // itself; otherwise each joint count's own proof is said first.
        if (!verdicts.own_proofs.empty() &&
            std::none_of(verdicts.cores.begin(), verdicts.cores.end(),
                         [&](const auto& c) { return c == proof.core; }))
            proof.message = join(verdicts.own_proofs, " ") + " With more joints, " + proof.message;
        stats_.front_seconds += t0.seconds();
        return infeasible(std::move(proof));
    }
    return unknown(verdicts.cores);
}

// The provers first (provers.h): exact geometry in milliseconds, where the
// front stage could only search.
std::optional<Proof> Search::find_proof() {
    // Two joints only: the branch and bound gets a small share of the run,
    // and its core is shrunk only within what the proof leaves of it.
    BranchAndBoundOptions bnb = branch_and_bound_budget();
    const run::Stopwatch proving;
    for (const Prover& prover : provers(bnb)) {
        std::optional<Proof> proof = prover.prove(task_, deadline_);
        if (!proof) continue;
        stats_.front_seconds += proving.seconds();
        say(run::Stage::Proofs,
            std::string(prover.name) + ": proved infeasible, " + proof->message);
        return proof;
    }
    stats_.front_seconds += proving.seconds();
    return std::nullopt;
}

// For each allowed joint count, fewest first, the front stage and every
// skeleton it offers, until one is certified. Breadth first: every
// skeleton, of every joint count, gets its best initial guess before any
// gets its others (retry). A wrong elbow sign fails on each of its guesses,
// and each failure costs a full refinement; where every first guess of
// fewer joints fails, more joints are usually needed (a base ringed by
// posts, scripts/keyhole-tasks).
std::optional<Solution> Search::search_skeletons(FrontStageVerdicts& verdicts) {
    for (int dof : task_.robot.dof) {
        if (remaining() <= 0.0) {
            verdicts.all_unsat = false;
            break;
        }
        if (ruled_out(dof, verdicts)) continue;
        const run::Stopwatch t0;
        smt::FrontStageOptions fo = opt_.front;
        fo.time_limit = std::min(opt_.front.time_limit, std::max(0.1, remaining()));
        // Tearing down a large encoding takes time too: the front stage
        // stops a little before the run must end.
        fo.deadline = deadline_.reserve(
            std::min(opt_.front_reserve_seconds, opt_.front_reserve_share * opt_.time_limit));
        say(run::Stage::FrontStage, std::to_string(dof) + " joints: front stage");
        smt::FrontStage front(task_, dof, fo);
        auto result = front.check();
        stats_.front_seconds += t0.seconds();
        if (result == smt::FrontStage::Result::Unsat) {
            // A core found for fewer joints often holds here too: checking
            // it is cheaper than minimising afresh.
            auto& cores = verdicts.cores;
            const auto known = std::find_if(cores.begin(), cores.end(),
                                            [&](const auto& c) { return front.conflicts(c); });
            cores.push_back(known != cores.end() ? *known : front.minimal_core());
            say(run::Stage::FrontStage, std::to_string(dof) +
                                            " joints: proved infeasible, conflict between " +
                                            names(cores.back()));
            tried_.push_back(std::to_string(dof) + " joints proved infeasible (" +
                             names(cores.back()) + ")");
            continue;
        }
        verdicts.all_unsat = false;
        if (result == smt::FrontStage::Result::Unknown) {
            say(run::Stage::FrontStage, std::to_string(dof) + " joints: front stage gave up (" +
                                            front.reason_unknown() + ")");
            tried_.push_back(std::to_string(dof) + " joints: front stage undecided");
            continue;
        }
        int skeletons = 0;
        while (result == smt::FrontStage::Result::Sat && remaining() > 0.0) {
            const smt::Skeleton sk = front.skeleton();
            assert(sk.dof == dof && sk.link_lengths.size() == static_cast<std::size_t>(dof));
            ++skeletons;
            ++stats_.skeletons;
            say(run::Stage::Search,
                text::format("%d joints: skeleton %d (elbow %+d, base region %d)", dof, skeletons,
                             sk.elbow, sk.base_region));
            verdicts.searched.push_back(sk);
            if (auto found = try_skeleton(sk, 1, opt_.seed)) return shorten(sk, std::move(*found));
            front.block(sk);
            const run::Stopwatch t1;
            result = front.check();
            stats_.front_seconds += t1.seconds();
        }
        const bool exhausted = result != smt::FrontStage::Result::Sat;
        tried_.push_back(text::format("%d joints: %d skeleton(s) searched", dof, skeletons) +
                         (exhausted ? " (all of them) without a certified motion" : ""));
        if (exhausted) say(run::Stage::Search, std::to_string(dof) + " joints: search exhausted");
    }
    return std::nullopt;
}

// A loop of the path round an obstacle (loop_proof.h) rules 2 joints out
// with a proof, in microseconds, where the front stage would offer skeletons
// whose every refinement runs a link through the obstacle. With more joints a
// loop that is one primitive rules out only modsynth's motions, which keep
// the proximal links still along a primitive: that is said, and is no proof.
bool Search::ruled_out(int dof, FrontStageVerdicts& verdicts) {
    const run::Stopwatch t0;
    if (dof == 2) {
        const auto loop = prove::loop_around_obstacle(task_);
        stats_.front_seconds += t0.seconds();
        if (!loop) return false;
        prove::Proof proof = prove::two_joint_loop_proof(task_, *loop);
        say(run::Stage::Proofs, "2 joints: proved infeasible, " + proof.message);
        // Not the core's names: a loop may be thousands of primitives.
        tried_.push_back("2 joints proved infeasible (" + prove::describe_loop(task_, *loop) + ")");
        verdicts.own_proofs.push_back("with 2 joints, " + proof.message);
        verdicts.cores.push_back(std::move(proof.core));
        return true;
    }
    const auto loop = prove::loop_around_obstacle(task_, 1);
    stats_.front_seconds += t0.seconds();
    if (!loop) return false;
    const std::string why = prove::describe_loop(task_, *loop) +
                            ", and modsynth's motions keep the first " +
                            (dof == 3 ? std::string("link") : std::to_string(dof - 2) + " links") +
                            " still along a primitive";
    say(run::Stage::Search, std::to_string(dof) + " joints: not searched: " + why);
    tried_.push_back(std::to_string(dof) + " joints not searched (" + why + ")");
    verdicts.all_unsat = false;
    return true;
}

// Where more joints are allowed, the branch and bound that proves a task of
// 2 joints only infeasible (find_proof) drops 2 joints from the retries:
// a proof, said as the loop's is. Not before the first pass, which
// certifies most tasks that 2 joints can do at less than its cost.
bool Search::two_joints_bounded(FrontStageVerdicts& verdicts) {
    if (task_.robot.dof.size() < 2) return false;  // dof [2]: find_proof ran it
    BranchAndBoundOptions bnb = branch_and_bound_budget();
    // A search that finds no proof here only delays the joint counts that
    // can do the task: it gets a count of boxes (the same on every
    // machine) rather than all of its share.
    bnb.max_boxes = std::min(bnb.max_boxes, opt_.branch_and_bound_boxes_beside);
    // Its core is not shrunk: it only drops a joint count, and an answer of
    // "infeasible" has its core shrunk with the other joint counts'.
    bnb.core_time_limit = 0.0;
    if (!(bnb.time_limit > 0.0) || bnb.max_boxes < 1) return false;
    task::Task two = task_;
    two.robot.dof = {2};
    const run::Stopwatch t0;
    std::optional<Proof> proof = prove::prove_two_joint_infeasible(two, bnb, deadline_);
    stats_.front_seconds += t0.seconds();
    if (!proof) return false;
    say(run::Stage::Proofs, "2 joints: proved infeasible, " + proof->message);
    tried_.push_back("2 joints proved infeasible (by branch and bound)");
    verdicts.own_proofs.push_back("with 2 joints, " + proof->message);
    verdicts.cores.push_back(std::move(proof->core));
    return true;
}

Solution Search::infeasible(Proof proof) const {
    assert(!proof.core.empty() && !proof.message.empty());  // a proof names what conflicts
    Solution out;
    out.task_name = task_.name;
    out.status = Status::Infeasible;
    out.explanation.message = "Proved infeasible: " + proof.message;
    out.explanation.core = std::move(proof.core);
    out.explanation.separation = std::move(proof.separation);
    out.explanation.geodesic = std::move(proof.geodesic);
    return out;
}

// No robot and no proof: what was tried, and the cores of the joint counts
// the front stage proved infeasible.
Solution Search::unknown(const std::vector<std::vector<task::TaskPart>>& cores) const {
    Solution out;
    out.task_name = task_.name;
    const bool out_of_time = remaining() <= 0.0;
    out.status =
        Status(Status::Unknown, stage_,
               out_of_time ? "time limit" : "every joint count tried without a certified robot");
    out.explanation.message =
        "No certified robot found" + std::string(out_of_time ? " within the time limit" : "") +
        (tried_.empty() ? std::string(": the time ran out before any robot was tried.")
                        : ": " + join(tried_, "; ") + ".") +
        (blocked_.empty() ? std::string()
                          : " What stopped the candidates: " + blocked_.describe(task_) + ".");
    for (const auto& c : cores)
        for (const auto& part : c)
            if (std::find(out.explanation.core.begin(), out.explanation.core.end(), part) ==
                out.explanation.core.end())
                out.explanation.core.push_back(part);
    return out;
}

// The chosen robot's certified motion, timed for a controller (retime.h):
// its q stay as certified, so the certificate holds for the result.
Solution Search::timed(Solution solution) {
    assert(solution.status == Status::Solved && !solution.samples.empty() &&
           solution.certificate.ok);
    const run::Stopwatch t0;
    control::RetimeStats timing;
    solution.samples = control::retime_for(task_, std::move(solution.samples),
                                           control::joint_limits_for(task_, solution.robot.dof()),
                                           opt_.retime, &timing);
    say(run::Stage::Timing,
        text::format("timed: %.3f s of motion, %d rests, %d passes, in %.1f ms", timing.duration,
                     timing.rests, timing.passes, 1e3 * t0.seconds()));
    stats_.timing = std::move(timing);
    return solution;
}

// s the certified motion of a candidate takes, timed as the one returned
// will be.
double Search::motion_seconds(const Solution& solution) const {
    control::RetimeStats timing;
    control::retime_for(task_, solution.samples,
                        control::joint_limits_for(task_, solution.robot.dof()), opt_.retime,
                        &timing);
    return timing.duration;
}

// Every skeleton the front stage offered, again and again with initial
// guesses of other seeds, until one is certified or the time runs out: a
// skeleton exhausted by blocking is no proof that the task is infeasible.
// Pass 0 gives each skeleton the other guesses of the search's own seed
// (its best one was tried already); later passes, further seeds. The seeds
// follow from the pass, so solutions stay repeatable.
std::optional<Solution> Search::retry(const std::vector<smt::Skeleton>& skeletons) {
    // However many passes the time allows, the explanation says it once.
    unsigned retries = 0;
    auto note_retries = [&] {
        if (retries > 0)
            tried_.push_back(
                text::format("every skeleton retried %u time(s) with other seeds", retries));
    };
    for (unsigned pass = 0; remaining() > 0.0; ++pass) {
        const unsigned seed = opt_.seed + 1000003u * pass;
        for (const smt::Skeleton& sk : skeletons) {
            if (remaining() <= 0.0) break;
            say(run::Stage::Search,
                pass == 0 ? text::format("%d joints: more initial guesses for elbow %+d, base "
                                         "region %d",
                                         sk.dof, sk.elbow, sk.base_region)
                          : text::format("%d joints: retry %u, elbow %+d, base region %d", sk.dof,
                                         pass, sk.elbow, sk.base_region));
            if (auto found = try_skeleton(sk, opt_.guesses_per_skeleton, seed)) {
                note_retries();
                return shorten(sk, std::move(*found));
            }
        }
        if (pass > 0) ++retries;
    }
    note_retries();
    return std::nullopt;
}

// The first certified robot ends the search, but it is often not the
// shortest: the refinement only sees its own elbow sign and base region, and
// the other branch can need much shorter links (on tasks/rose.json, 0.54 m
// against 0.97 m). Each other elbow sign and base region gets one initial
// guess; a fixed amount of work, so that solutions stay repeatable, unless
// the region cannot hold a robot shorter by more than shorten_gap (a proved
// bound) or the time left would not cover the attempt. Of the certified
// robots, the shortest is returned, or one as short to within length_tie
// that passes farther from the obstacles.
Solution Search::shorten(const smt::Skeleton& found, Solution first) {
    struct Certified {
        Solution solution;
        std::string by;
    };
    std::vector<Certified> certified;
    certified.push_back({std::move(first), stats_.certified_by});
    double shortest = certified.front().solution.robot.total_length();
    const auto chosen = [&] {
        std::vector<DesignMerit> merits;
        // Every candidate's motion is timed (a few milliseconds each) when
        // there is a choice: among robots tied in length and clearance, the
        // quicker motion wins.
        for (const Certified& c : certified) {
            merits.push_back({c.solution.robot.total_length(), c.solution.certificate.min_clearance,
                              certified.size() > 1 ? motion_seconds(c.solution)
                                                   : std::numeric_limits<double>::infinity()});
            if (certified.size() > 1)
                say(run::Stage::Shortening,
                    text::format("%d joints: elbow %+d, total length %.4f m: %.3f s of motion",
                                 found.dof, c.solution.robot.elbow, merits.back().total_length,
                                 merits.back().motion_time));
        }
        Certified& c = certified[choose_design(merits, opt_.length_tie)];
        stats_.certified_by = c.by;
        return std::move(c.solution);
    };
    // A variant costs about what the robot found did, and a single Ipopt
    // iteration on a long path can outlast what is left: one started too
    // late would leave no time to time and write the robot already
    // certified. A verification alone (the twin below) is held to the same
    // reserve: on a 3000-primitive path it takes a third of a second.
    const auto out_of_time = [&] {
        if (remaining() >= opt_.shorten_reserve * certified_seconds_ && remaining() > 0.0)
            return false;
        say(run::Stage::Shortening,
            text::format("%d joints: no time left to look for a shorter robot", found.dof));
        return true;
    };
    for (int region : task::base_region_choices(task_)) {
        const double bound = shortest_possible(region, found.dof);
        if (bound >= shortest - opt_.shorten_gap) {
            say(run::Stage::Shortening,
                text::format("%d joints: no robot with base region %d is shorter than %.4f m",
                             found.dof, region, bound));
            // The other elbow could then give a robot about as long that
            // passes farther from the obstacles. The robot found, with the
            // other elbow, is one such: it reaches the same points, and
            // costs a verification, not a refinement.
            if (region == found.base_region && certified.size() == 1) {
                if (out_of_time()) return chosen();
                kinematics::Robot other = certified.front().solution.robot;
                other.elbow = -other.elbow;
                say(run::Stage::Shortening,
                    text::format("%d joints: the same robot with elbow %+d?", found.dof,
                                 other.elbow));
                if (auto twin = judge(other).solution)
                    certified.push_back({std::move(*twin), certified.front().by});
            }
            continue;
        }
        for (int elbow : {1, -1}) {
            if (region == found.base_region && elbow == found.elbow) continue;
            if (out_of_time()) return chosen();
            smt::Skeleton variant = found;
            variant.base_region = region;
            variant.elbow = elbow;
            say(run::Stage::Shortening,
                text::format("%d joints: shorter robot with elbow %+d, base region %d?", found.dof,
                             elbow, region));
            // A robot the plan found alone is compared with the plans of the
            // variants: a refinement of a long path costs many plans.
            auto candidate = try_skeleton(variant, opt_.guesses_per_variant, opt_.seed,
                                          stats_.first_certified_by != kPlanned);
            if (!candidate) continue;
            const double length = candidate->robot.total_length();
            if (length < shortest - 1e-6)
                say(run::Stage::Shortening,
                    text::format("    shorter: total length %.4f m", length));
            else if (length <= shortest + opt_.length_tie)
                say(run::Stage::Shortening,
                    text::format("    as short, to within %.4f m: total length %.4f m",
                                 opt_.length_tie, length));
            else
                continue;
            shortest = std::min(shortest, length);
            certified.push_back({std::move(*candidate), stats_.certified_by});
        }
    }
    return chosen();
}

// A lower bound on the total link length of any robot of `dof` joints with
// its base in the region: every link is at least the task's shortest, and
// the arm reaches the path point farthest from its base.
double Search::shortest_possible(int base_region, int dof) {
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

// The design a proximal plan is a function of.
std::vector<double> design_key(const kinematics::Robot& robot) {
    std::vector<double> key{static_cast<double>(robot.elbow), robot.base.x(), robot.base.y()};
    key.insert(key.end(), robot.link_lengths.begin(), robot.link_lengths.end());
    return key;
}

// What a refinement is a function of (the time left aside): the skeleton's
// discrete choices, the swept-volume model and the start robot.
std::vector<double> refinement_key(const smt::Skeleton& skeleton, const kinematics::Robot& start,
                                   const SweptAttempt& attempt) {
    std::vector<double> key{static_cast<double>(skeleton.dof),
                            static_cast<double>(skeleton.elbow),
                            static_cast<double>(skeleton.base_region),
                            static_cast<double>(attempt.swept),
                            attempt.paper ? 1.0 : 0.0,
                            start.base.x(),
                            start.base.y()};
    key.insert(key.end(), start.link_lengths.begin(), start.link_lengths.end());
    key.insert(key.end(), start.proximal_angles.begin(), start.proximal_angles.end());
    return key;
}

std::optional<Solution> Search::try_skeleton(const smt::Skeleton& skeleton, int count,
                                             unsigned seed, bool refine_too) {
    const run::Stopwatch started;
    // Three joints: the plans of several guesses come before any refinement,
    // which costs far more than a plan on a long path. Without refinements
    // (a variant of a robot its plan found) the guesses get what the robot
    // found took, times shorten_reserve: scored whole where few are clear,
    // they took seconds on a 100-segment loop.
    const bool plan = plan_first_ && kinematics::has_proximal_link(skeleton.dof);
    const run::Deadline guessing =
        refine_too ? deadline_
                   : deadline_.within(opt_.shorten_reserve * std::max(certified_seconds_, 0.1));
    const auto guesses = initial_guesses(
        task_, skeleton, plan && refine_too ? std::max(count, opt_.proximal.guesses) : count, seed,
        guessing, opt_.guesses);
    std::vector<kinematics::Robot> starts;
    for (const auto& g : guesses) starts.push_back(g.robot);
    for (std::size_t i = 0; plan && i < guesses.size(); ++i) {
        if (remaining() <= 0.0) return std::nullopt;
        // A plan is a function of the design: one planned before is not again.
        if (!planned_.insert(design_key(guesses[i].robot)).second) continue;
        say(run::Stage::Search, text::format("  design: base (%.3f, %.3f), total length %.3f m",
                                             guesses[i].robot.base.x(), guesses[i].robot.base.y(),
                                             guesses[i].robot.total_length()) +
                                    text::format(", margin %.4f m", guesses[i].margin));
        if (auto s = planned(starts[i])) {
            certified_seconds_ = started.seconds();
            return s;
        }
    }
    if (!refine_too) return std::nullopt;
    for (std::size_t n = 0; n < guesses.size() && static_cast<int>(n) < count; ++n) {
        const ScoredRobot& g = guesses[n];
        if (remaining() <= 0.0) return std::nullopt;
        auto attempts = swept_attempts(opt_.swept, task_, skeleton, g.robot);
        std::erase_if(attempts, [&](const SweptAttempt& a) {
            return failed_.count(refinement_key(skeleton, g.robot, a)) > 0;
        });
        if (attempts.empty()) continue;  // failed before from this very start
        say(run::Stage::Search,
            text::format("  start: base (%.3f, %.3f), total length %.3f m", g.robot.base.x(),
                         g.robot.base.y(), g.robot.total_length()) +
                text::format(", margin %.4f m", g.margin));
        for (std::size_t i = 0; i < attempts.size(); ++i) {
            if (auto s = refine(skeleton, starts[n], attempts[i])) return s;
            failed_.insert(refinement_key(skeleton, g.robot, attempts[i]));
            if (i + 1 < attempts.size()) ++stats_.fallbacks;
        }
    }
    return std::nullopt;
}

// Three joints: with the start's design fixed, where the proximal link
// stands along the path is a shortest path over (primitive, angle)
// (proximal_plan.h), linear in the primitives. A plan the verifier
// certifies is the answer; otherwise its angles start the refinement, which
// then moves the design too.
std::optional<Solution> Search::planned(kinematics::Robot& start) {
    const run::Stopwatch t0;
    const ProximalPlan plan = plan_proximal_angles(task_, start, opt_.proximal, deadline_);
    stats_.refine_seconds += t0.seconds();
    if (!plan.found) {
        say(run::Stage::Search, text::format("    proximal plan: none (%s), %.3f s",
                                             plan.message.c_str(), t0.seconds()));
        return std::nullopt;
    }
    say(run::Stage::Search, text::format("    proximal plan: %d move(s), margin %.4f m, %.3f s",
                                         plan.moves, plan.margin, t0.seconds()));
    start.proximal_angles = plan.angles;
    Verdict verdict = judge(start);
    if (!verdict.solution) return std::nullopt;
    stats_.certified_by = kPlanned;
    if (stats_.first_certified_by.empty()) stats_.first_certified_by = stats_.certified_by;
    certified_seconds_ = t0.seconds();
    return std::move(verdict.solution);
}

std::optional<Solution> Search::refine(const smt::Skeleton& skeleton,
                                       const kinematics::Robot& start, SweptAttempt attempt) {
    const run::Stopwatch started;
    const char* name = name_of(attempt);
    const nlp::SweptVolume swept = attempt.swept;
    nlp::ArmProblem problem;
    problem.task = &task_;
    problem.skeleton = skeleton;
    problem.start = start;
    problem.swept = swept;
    problem.swept_only = attempt.paper;
    problem.points = attempt.paper ? end_points(task_) : spaced_points(task_, opt_);
    add_critical_points(task_, start, problem.points);
    // The last round's program and solution: the next round's program is
    // the same plus counterexample points, and starts where it ended.
    std::optional<nlp::Formulation> last;
    nlp::SolverResult last_result;
    for (int round = 0; round < opt_.refinement_rounds && remaining() > 0.0; ++round) {
        const run::Stopwatch t0;
        nlp::Formulation f = nlp::formulate(problem);
        nlp::SolverOptions so;
        // A refinement that needs more than this is better restarted from
        // another initial guess than waited for.
        const double budget =
            std::max(round == 0 ? opt_.first_solve_seconds : opt_.later_solve_seconds,
                     opt_.solve_seconds_per_kvariable * 1e-3 * f.program.num_variables());
        so.time_limit = std::min(budget, std::max(0.05, remaining()));
        so.max_iterations = round == 0 ? opt_.first_solve_iterations : opt_.later_solve_iterations;
        so.deadline = deadline_.at_least(0.05);
        std::optional<nlp::WarmStart> warm;
        if (last && opt_.warm_start_rounds)
            warm = nlp::carry_over(last->program, last_result, f.program);
        const nlp::SolverResult res = nlp::minimize(f.program, so, warm ? &*warm : nullptr);
        stats_.refine_seconds += t0.seconds();
        ++stats_.nlp_solves;
        if (!res.usable()) {
            blocked_.not_converged(skeleton.dof);
            say(run::Stage::Refinement,
                std::string("    ") + name +
                    text::format(": refinement did not converge in %d iterations, %.3f s (",
                                 res.iterations, t0.seconds()) +
                    res.message + ")");
            return std::nullopt;
        }
        const kinematics::Robot robot = nlp::robot_from(f, res.x);
        const int variables = f.program.num_variables();
        last = std::move(f);
        last_result = res;
        std::string links;
        for (double r : robot.link_lengths)
            links += text::format(links.empty() ? "%.4f" : " + %.4f", r);
        say(run::Stage::Refinement,
            std::string("    ") + name + ": candidate links " + links +
                text::format(" m with %zu points, %d variables, in %d iterations, %.3f s",
                             problem.points.size(), variables, res.iterations, t0.seconds()));
        Verdict verdict = judge(robot);
        if (verdict.solution) {
            stats_.certified_by = name;
            certified_seconds_ = started.seconds();
            if (stats_.first_certified_by.empty()) stats_.first_certified_by = name;
            return std::move(verdict.solution);
        }
        if (verdict.gave_up) return std::nullopt;
        nlp::ArmProblem next = learn(problem, verdict, robot);
        if (next.points.size() == problem.points.size() &&
            next.transition_depth == problem.transition_depth)
            return std::nullopt;  // nothing left to learn
        stats_.counterexamples += static_cast<int>(next.points.size() - problem.points.size());
        next.start = robot;
        if (next.swept != nlp::SweptVolume::Sampled) ++stats_.fallbacks;
        if (next.swept_only)  // lines take over, at the sampled points too
            for (const auto& p : spaced_points(task_, opt_))
                add_point(next.points, p.primitive, p.s);
        next.swept = nlp::SweptVolume::Sampled;
        next.swept_only = false;
        name = "sampled";
        problem = std::move(next);
    }
    return std::nullopt;
}

// Plans and certifies the motion of one candidate robot.
Verdict Search::judge(const kinematics::Robot& robot) {
    Verdict verdict;
    const run::Stopwatch t0;
    control::MotionFailure failure;
    auto motion = control::plan_motion(task_, robot, motion_, &failure);
    if (!motion && failure.gave_up) {
        say(run::Stage::Verification, "    motion planning stopped: " + failure.message);
        stats_.verify_seconds += t0.seconds();
        verdict.gave_up = true;  // the refinement of this guess ends
        return verdict;
    }
    if (!motion && failure.travel) {
        blocked_.no_travel(robot.dof(), failure.primitive);
        // Nothing along the path to learn from: the next guess may do.
        say(run::Stage::Verification, "    no clear travel: " + failure.message);
        stats_.verify_seconds += t0.seconds();
        return verdict;
    }
    if (!motion) {
        blocked_.out_of_reach(robot.dof(), failure.primitive, failure.transition);
        say(run::Stage::Verification, "    out of reach at " + failure.message);
        if (failure.transition) {
            verdict.deeper_transitions = 1;
        } else {
            verdict.points.emplace_back(failure.primitive, failure.s);
        }
        stats_.verify_seconds += t0.seconds();
        return verdict;
    }
    const verify::VerifyOptions vo = verify::options_for(motion_, opt_.verify);
    verify::Certificate cert = verify::certify(task_, robot, *motion, vo);
    for (int pass = 0; pass < opt_.motion_refinement_passes && cert.violations.empty() &&
                       !cert.coarse_pairs.empty() && remaining() > 0.0;
         ++pass) {
        if (!control::refine_motion(task_, robot, *motion, cert.coarse_pairs)) break;
        cert = verify::certify(task_, robot, *motion, vo);
    }
    stats_.verify_seconds += t0.seconds();
    if (cert.ok) {
        Solution& out = verdict.solution.emplace();
        out.task_name = task_.name;
        out.status = Status::Solved;
        out.robot = robot;
        out.samples = std::move(*motion);
        out.certificate = std::move(cert);
        say(run::Stage::Verification,
            text::format("    certified: %s, self margin %.4f m, deviation %.2g m",
                         text::clearance_text(out.certificate.min_clearance).c_str(),
                         out.certificate.min_self_clearance, out.certificate.max_deviation));
        return verdict;
    }
    // Each obstacle (and the tool against the links) once per candidate.
    std::set<int> blamed;
    for (const auto& v : cert.violations) {
        if (v.kind == verify::Violation::Kind::Clearance && blamed.insert(v.obstacle).second)
            blocked_.obstacle(robot.dof(), v.obstacle, v.link, v.primitive);
        if (v.kind == verify::Violation::Kind::SelfCollision && blamed.insert(-1).second)
            blocked_.self_collision(robot.dof(), v.primitive);
    }
    std::set<std::pair<int, long>> seen;
    for (const auto& v : cert.violations) {
        if (v.primitive < 0 || v.travel) continue;
        if (v.transition) {
            ++verdict.deeper_transitions;
            continue;
        }
        if (!seen.insert({v.primitive, std::lround(v.s * 1e3)}).second) continue;
        verdict.points.emplace_back(v.primitive, v.s);
        if (static_cast<int>(verdict.points.size()) >= opt_.counterexamples_per_round) break;
    }
    if (!cert.violations.empty())
        say(run::Stage::Verification,
            "    verification: " + std::to_string(cert.violations.size()) +
                " violation(s), first: " + cert.violations.front().message);
    return verdict;
}

// The next refinement's problem: the failed robot's counterexamples, its
// critical points, and (three joints) more proximal poses in transitions,
// up to the cap.
nlp::ArmProblem Search::learn(nlp::ArmProblem problem, const Verdict& verdict,
                              const kinematics::Robot& robot) const {
    if (verdict.deeper_transitions > 0 && problem.transition_depth < opt_.max_transition_depth)
        problem.transition_depth = std::min(opt_.max_transition_depth,
                                            problem.transition_depth + verdict.deeper_transitions);
    for (const auto& [primitive, s] : verdict.points) add_point(problem.points, primitive, s);
    add_critical_points(task_, robot, problem.points);
    return problem;
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

namespace {

// A circle that winds round an obstacle is out of reach of modsynth's
// motions as it stands (Search::ruled_out): cut into arcs, it is searched
// again with what is left of the time, fewer arcs first (each cut is one
// more place where the first link may turn, and one more transition to
// plan). The motion found is read back as one of the circle and certified
// against the task as written.
Solution through_arcs(const task::Task& task, const SynthesisOptions& options,
                      SynthesisStats& stats, Solution unknown, const run::Stopwatch& clock) {
    const auto loop = prove::loop_around_obstacle(task, 1);
    if (!loop || *std::max_element(task.robot.dof.begin(), task.robot.dof.end()) < 3)
        return unknown;
    std::vector<std::string> tried;
    for (const int arcs : {8, 16, 32}) {
        const double left = options.time_limit - clock.seconds();
        if (left < 0.1) break;
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
        Solution found = Search(split.task, o, stats).run();
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
    if (!tried.empty()) unknown.explanation.message += " Then " + join(tried, "; ") + ".";
    return unknown;
}

}  // namespace

Solution synthesize(const task::Task& task, const SynthesisOptions& options,
                    SynthesisStats* stats) {
    text::require_valid(options);
    SynthesisStats local;
    SynthesisStats& s = stats ? *stats : local;
    const run::Stopwatch clock;
    Solution out = Search(task, options, s).run();
    if (out.status != Status::Unknown) return out;
    return through_arcs(task, options, s, std::move(out), clock);
}

}  // namespace modsynth::synth
