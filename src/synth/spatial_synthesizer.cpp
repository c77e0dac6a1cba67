#include <modsynth/synth/spatial_synthesizer.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <set>
#include <stdexcept>

#include <modsynth/control/joint_limits.h>
#include <modsynth/control/path_corners.h>
#include <modsynth/geometry/primitive3.h>
#include <modsynth/nlp/solver.h>
#include <modsynth/prove/spatial_enclosure.h>
#include <modsynth/run/deadline.h>
#include <modsynth/run/stopwatch.h>
#include <modsynth/synth/design_choice.h>
#include <modsynth/synth/spatial_reach_proof.h>
#include <modsynth/task/part.h>
#include <modsynth/task/spatial_strokes.h>
#include <modsynth/text/format.h>
#include <modsynth/text/option_check.h>
#include <modsynth/verify/spatial_verifier.h>

namespace modsynth::synth {
namespace {

using Clock = std::chrono::steady_clock;
using geometry::Vec3;
using run::Stage;

/// s: the most the proof of a wall in space may take of a run.
constexpr double kEnclosureSeconds = 1.0;

double seconds_since(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

std::string join(const std::vector<task::TaskPart>& parts, const char* sep) {
    std::string s;
    for (std::size_t i = 0; i < parts.size(); ++i) s += (i ? sep : "") + task::to_string(parts[i]);
    return s;
}

std::string join(const std::vector<std::string>& v, const char* sep) {
    std::string s;
    for (std::size_t i = 0; i < v.size(); ++i) s += (i ? sep : "") + v[i];
    return s;
}

double chain_length(const kinematics::YawPitchArm& arm) {
    double l = std::abs(arm.column);
    for (double a : arm.links) l += a;
    return l;
}

std::string describe(const smt::SpatialSkeleton& sk) {
    return text::format("%d joints, column %s, base region %d", sk.dof,
                        sk.column > 0   ? "up"
                        : sk.column < 0 ? "hanging"
                                        : "none",
                        sk.base_region);
}

std::string describe(const kinematics::YawPitchDesign& d) {
    std::string links;
    for (double a : d.arm.links) links += text::format(links.empty() ? "%.4f" : " + %.4f", a);
    return text::format("base (%.3f, %.3f, %.3f), d1 %.4f, links ", d.arm.base.x(), d.arm.base.y(),
                        d.arm.base.z(), d.arm.column) +
           links + text::format(" m (chain %.4f m)", chain_length(d.arm));
}

void add_point(std::vector<nlp::SpatialPoint>& pts, const nlp::SpatialPoint& p) {
    for (const auto& q : pts)
        if (q.primitive == p.primitive && q.transition == p.transition &&
            std::abs(q.s - p.s) < 1e-4 && std::abs(q.t - p.t) < 1e-4)
            return;
    pts.push_back(p);
}

/// What planning and certifying one candidate design came to.
struct Verdict {
    std::optional<Solution> solution;
    bool gave_up = false;
    std::vector<nlp::SpatialPoint> points;  ///< where it failed
};

class Search {
public:
    Search(const task::SpatialTask& task, const SpatialSynthesisOptions& options,
           SynthesisStats& stats)
        : task_(task),
          opt_(options),
          stats_(stats),
          deadline_(
              run::Deadline::in(std::max(0.0, options.time_limit)).cancelled_by(options.cancel)) {
        motion_ = opt_.motion;
        motion_.deadline = deadline_;
        verify_ = verify_options_for(task, opt_);
    }

    Solution run();

private:
    struct Entry {
        smt::SpatialSkeleton skeleton;
        std::vector<ScoredDesign> guesses;
        std::size_t next = 0;  ///< the next guess to refine
    };

    double remaining() const { return deadline_.remaining(); }
    void say(Stage stage, const std::string& message) {
        stage_ = message;
        if (opt_.progress) opt_.progress({stage, message, clock_.seconds()});
    }
    std::optional<Solution> refine(const smt::SpatialSkeleton& skeleton, const ScoredDesign& start);
    Verdict judge(const kinematics::YawPitchDesign& design);
    std::vector<nlp::SpatialPoint> initial_points(const kinematics::YawPitchDesign& design) const;
    Solution timed(Solution solution);
    Solution shorten(std::vector<Entry>& entries, std::size_t found, Solution first);

    const task::SpatialTask& task_;
    const SpatialSynthesisOptions& opt_;
    SynthesisStats& stats_;
    const run::Stopwatch clock_;
    const run::Deadline deadline_;
    control::SpatialMotionOptions motion_;
    verify::VerifyOptions verify_;
    std::vector<std::string> tried_;
    std::string stage_ = "before the front stage";
};

Solution Search::run() {
    Solution out;
    out.task_name = task_.name;
    const auto t_reach = Clock::now();
    if (auto core = spatial_out_of_reach_core(task_)) {
        stats_.front_seconds += seconds_since(t_reach);
        out.status = Status::Infeasible;
        out.explanation.message = "Proved infeasible: " + describe_spatial_reach(task_, *core);
        out.explanation.core = *core;
        say(Stage::Proofs, "reach: " + out.explanation.message);
        return out;
    }
    // Walls in space: milliseconds where no obstacle comes near a shell,
    // within a second otherwise.
    if (auto wall = prove::prove_spatial_enclosure(task_, deadline_.within(kEnclosureSeconds))) {
        stats_.front_seconds += seconds_since(t_reach);
        out.status = Status::Infeasible;
        out.explanation.message = "Proved infeasible: " + wall->message;
        out.explanation.core = std::move(wall->core);
        out.explanation.enclosure = std::move(wall->enclosure);
        say(Stage::Proofs, "walls: " + out.explanation.message);
        return out;
    }
    stats_.front_seconds += seconds_since(t_reach);
    std::vector<int> dofs = task_.robot.dof;
    std::sort(dofs.begin(), dofs.end());
    std::vector<std::vector<task::TaskPart>> cores;
    bool all_unsat = true;
    std::vector<Entry> all;  // every skeleton searched, for the later passes
    for (int dof : dofs) {
        if (remaining() <= 0.0) {
            all_unsat = false;
            break;
        }
        const auto t0 = Clock::now();
        smt::SpatialFrontStageOptions fo = opt_.front;
        fo.time_limit = std::min(fo.time_limit, std::max(0.05, remaining()));
        fo.deadline = deadline_;
        fo.axis_margin = opt_.margins.axis;
        say(Stage::FrontStage, std::to_string(dof) + " joints: front stage");
        smt::SpatialFrontStage front(task_, dof, fo);
        const auto result = front.check();
        if (result == smt::SpatialFrontStage::Result::Unsat) {
            const auto known = std::find_if(cores.begin(), cores.end(),
                                            [&](const auto& c) { return front.conflicts(c); });
            cores.push_back(known != cores.end() ? *known : front.minimal_core());
            stats_.front_seconds += seconds_since(t0);
            say(Stage::FrontStage, std::to_string(dof) +
                                       " joints: proved infeasible, conflict between " +
                                       join(cores.back(), ", "));
            tried_.push_back(std::to_string(dof) + " joints proved infeasible (" +
                             join(cores.back(), ", ") + ")");
            continue;
        }
        all_unsat = false;
        if (result == smt::SpatialFrontStage::Result::Unknown) {
            stats_.front_seconds += seconds_since(t0);
            say(Stage::FrontStage, std::to_string(dof) + " joints: front stage gave up (" +
                                       front.reason_unknown() + ")");
            tried_.push_back(std::to_string(dof) + " joints: front stage undecided");
            continue;
        }
        if (!front.pattern_allowed()) {
            stats_.front_seconds += seconds_since(t0);
            say(Stage::FrontStage,
                std::to_string(dof) +
                    " joints: robot.twists has no 0 and +-pi/2 for a yaw column with pitch links");
            tried_.push_back(std::to_string(dof) +
                             " joints: the only chain pattern modsynth designs, a yaw column "
                             "(twist +-pi/2) with pitch links (twist 0), is not allowed by "
                             "robot.twists");
            continue;
        }
        const double relaxed = seconds_since(t0);
        std::vector<smt::SpatialSkeleton> skeletons = front.skeletons();
        stats_.front_seconds += seconds_since(t0);
        say(Stage::FrontStage,
            text::format("%d joints: relaxation satisfiable (%.3f s), %zu skeleton(s) (%.3f s)",
                         dof, relaxed, skeletons.size(), seconds_since(t0) - relaxed));
        if (skeletons.empty()) {
            tried_.push_back(std::to_string(dof) +
                             " joints: no skeleton of the yaw column and pitch links meets its "
                             "conditions (reach annulus, path off the column's axis)");
            continue;
        }
        // Every skeleton's guesses, then the skeletons in the order of their
        // best guess: clear ones shortest first, then by margin.
        std::vector<Entry> entries;
        for (const auto& sk : skeletons) {
            if (remaining() <= 0.0) break;
            Entry e{sk, spatial_initial_guesses(task_, sk, opt_.first_guesses, opt_.seed,
                                                opt_.margins, deadline_, opt_.guesses)};
            if (!e.guesses.empty()) entries.push_back(std::move(e));
        }
        std::stable_sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
            const auto& x = a.guesses.front();
            const auto& y = b.guesses.front();
            const bool cx = x.margin >= 0.0, cy = y.margin >= 0.0;
            if (cx != cy) return cx;
            if (cx) return chain_length(x.design.arm) < chain_length(y.design.arm);
            return x.margin > y.margin;
        });
        for (std::size_t i = 0; i < entries.size() && remaining() > 0.0; ++i) {
            Entry& e = entries[i];
            ++stats_.skeletons;
            const ScoredDesign& g = e.guesses[e.next++];
            say(Stage::Search,
                describe(e.skeleton) + text::format(": start %s, margin %.4f m",
                                                    describe(g.design).c_str(), g.margin));
            if (auto found = refine(e.skeleton, g))
                return timed(shorten(entries, i, std::move(*found)));
        }
        tried_.push_back(
            text::format("%d joints: %zu skeleton(s) refined without a certified "
                         "motion",
                         dof, entries.size()));
        for (auto& e : entries) all.push_back(std::move(e));
    }
    // Later passes: more guesses of every skeleton, with further seeds, until
    // the time runs out.
    for (unsigned pass = 1; !all.empty() && remaining() > 0.0; ++pass) {
        for (Entry& e : all) {
            if (remaining() <= 0.0) break;
            if (e.next >= e.guesses.size()) {
                e.guesses = spatial_initial_guesses(task_, e.skeleton, opt_.later_guesses,
                                                    opt_.seed + 1000003u * pass, opt_.margins,
                                                    deadline_, opt_.guesses);
                e.next = 0;
                if (e.guesses.empty()) continue;
            }
            const ScoredDesign& g = e.guesses[e.next++];
            say(Stage::Search,
                describe(e.skeleton) + text::format(" (pass %u): start %s, margin %.4f m", pass,
                                                    describe(g.design).c_str(), g.margin));
            if (auto found = refine(e.skeleton, g)) {
                tried_.push_back(text::format("more initial guesses in %u pass(es)", pass));
                return timed(std::move(*found));
            }
        }
    }
    if (all_unsat && !cores.empty()) {
        out.status = Status::Infeasible;
        // A core shared by every joint count (or the union of theirs).
        std::vector<task::TaskPart> core;
        for (const auto& c : cores)
            for (const auto& part : c)
                if (std::find(core.begin(), core.end(), part) == core.end()) core.push_back(part);
        out.explanation.core = core;
        out.explanation.message =
            "Proved infeasible: no chain of " +
            std::string(dofs.size() > 1 ? "any allowed joint count" : "the allowed joint count") +
            " meets the conditions every chain must meet: " + join(tried_, "; ") + ".";
        return out;
    }
    const bool out_of_time = remaining() <= 0.0;
    out.status =
        Status(Status::Unknown, stage_,
               out_of_time ? "time limit" : "every joint count tried without a certified robot");
    out.explanation.message = "No certified robot found" +
                              std::string(out_of_time ? " within the time limit" : "") + ": " +
                              join(tried_, "; ") + ".";
    return out;
}

std::vector<nlp::SpatialPoint> Search::initial_points(
    const kinematics::YawPitchDesign& design) const {
    double total = 0.0;
    for (const auto& p : task_.trajectory) total += geometry::length(p);
    const double spacing = std::max(opt_.point_spacing, total / std::max(1, opt_.max_points));
    std::vector<nlp::SpatialPoint> pts;
    const Vec3 shoulder = design.arm.shoulder();
    for (int j = 0; j < static_cast<int>(task_.trajectory.size()); ++j) {
        const auto& prim = task_.trajectory[static_cast<std::size_t>(j)];
        const double len = geometry::length(prim);
        const int n = std::max(2, static_cast<int>(std::ceil(len / spacing)));
        for (int i = 0; i <= n; ++i) pts.push_back({j, len * i / n});
        // Where the elbow stretches and folds most.
        add_point(pts, {j, geometry::nearest(prim, shoulder).s});
        add_point(pts, {j, geometry::farthest(prim, shoulder).s});
        if (design.hand_links() > 0 && task::has_transition_after(task_, j))
            for (double t : {0.25, 0.5, 0.75}) pts.push_back({j, len, true, t});
    }
    return pts;
}

std::optional<Solution> Search::refine(const smt::SpatialSkeleton& skeleton,
                                       const ScoredDesign& start) {
    nlp::SpatialProblem problem;
    problem.task = &task_;
    problem.start = start.design;
    problem.column = skeleton.column;
    if (skeleton.base_region >= 0)
        problem.base_box = task_.base_regions[static_cast<std::size_t>(skeleton.base_region)];
    problem.margins = opt_.margins;
    problem.points = initial_points(start.design);
    for (int round = 0; round < opt_.refinement_rounds && remaining() > 0.0; ++round) {
        const auto t0 = Clock::now();
        const nlp::SpatialFormulation f(problem);
        nlp::SolverOptions so;
        so.time_limit = std::min(opt_.solve_seconds, std::max(0.05, remaining()));
        so.deadline = deadline_.at_least(0.05);
        so.max_iterations = opt_.solve_iterations;
        const nlp::SolverResult res = nlp::minimize(f, so);
        stats_.refine_seconds += seconds_since(t0);
        ++stats_.nlp_solves;
        kinematics::YawPitchDesign design = problem.start;
        if (res.usable()) {
            design = f.design(res.x);
            say(Stage::Refinement,
                text::format("    refined: %s with %zu points, %d constraints, in %d iterations, "
                             "%.3f s",
                             describe(design).c_str(), problem.points.size(), f.num_constraints(),
                             res.iterations, seconds_since(t0)));
        } else {
            say(Stage::Refinement,
                text::format("    refinement did not converge in %d iterations, %.3f s (",
                             res.iterations, seconds_since(t0)) +
                    res.message + ")");
            // A clear start may still be certified as it is.
            if (round > 0 || start.margin < 0.0) return std::nullopt;
        }
        Verdict verdict = judge(design);
        if (verdict.solution) return std::move(verdict.solution);
        if (verdict.gave_up) return std::nullopt;
        const std::size_t before = problem.points.size();
        for (const auto& p : verdict.points) add_point(problem.points, p);
        if (problem.points.size() == before) return std::nullopt;  // nothing left to learn
        stats_.counterexamples += static_cast<int>(problem.points.size() - before);
        problem.start = design;
    }
    return std::nullopt;
}

Verdict Search::judge(const kinematics::YawPitchDesign& design) {
    Verdict verdict;
    const auto t0 = Clock::now();
    control::MotionFailure failure;
    auto samples = control::plan_spatial_motion(task_, design, motion_, &failure);
    if (!samples) {
        stats_.verify_seconds += seconds_since(t0);
        if (failure.gave_up) {
            say(Stage::Verification, "    motion: gave up (" + failure.message + ")");
            verdict.gave_up = true;
            return verdict;
        }
        say(Stage::Verification, "    motion: out of reach at " + failure.message);
        if (failure.travel) {
            verdict.gave_up = true;  // nothing a path point could fix
            return verdict;
        }
        verdict.points.push_back(
            failure.transition
                ? nlp::SpatialPoint{failure.primitive,
                                    geometry::length(task_.trajectory[static_cast<std::size_t>(
                                        failure.primitive)]),
                                    true, failure.s}
                : nlp::SpatialPoint{failure.primitive, failure.s});
        return verdict;
    }
    const kinematics::DhChain chain = design.chain();
    for (int pass = 0; pass <= opt_.motion_refinement_passes; ++pass) {
        verify::Certificate cert = verify::certify(task_, chain, *samples, verify_);
        if (cert.ok) {
            stats_.verify_seconds += seconds_since(t0);
            say(Stage::Verification,
                text::format("    certified: %zu samples, %s, self-collision "
                             "margin %.4f m, EE deviation <= %.2e m",
                             samples->size(), text::clearance_text(cert.min_clearance).c_str(),
                             cert.min_self_clearance, cert.max_deviation));
            Solution s;
            s.task_name = task_.name;
            s.status = Status::Solved;
            s.dh_robot = chain;
            s.samples = std::move(*samples);
            s.certificate = std::move(cert);
            verdict.solution = std::move(s);
            return verdict;
        }
        if (!cert.violations.empty()) {
            say(Stage::Verification, text::format("    verification: %zu violation(s), first: ",
                                                  cert.violations.size()) +
                                         cert.violations.front().message);
            int added = 0;
            for (const auto& v : cert.violations) {
                if (v.primitive < 0 || v.travel) continue;
                if (added++ >= opt_.counterexamples_per_round) break;
                const double len =
                    geometry::length(task_.trajectory[static_cast<std::size_t>(v.primitive)]);
                verdict.points.push_back(v.transition
                                             ? nlp::SpatialPoint{v.primitive, len, true, v.s}
                                             : nlp::SpatialPoint{v.primitive, v.s});
            }
            if (verdict.points.empty()) verdict.gave_up = true;
            stats_.verify_seconds += seconds_since(t0);
            return verdict;
        }
        if (!control::refine_spatial_motion(task_, design, *samples, cert.coarse_pairs)) break;
    }
    stats_.verify_seconds += seconds_since(t0);
    say(Stage::Verification, "    verification: pairs still too coarse after splitting");
    verdict.gave_up = true;
    return verdict;
}

Solution Search::timed(Solution solution) {
    const auto t0 = Clock::now();
    control::RetimeStats timing;
    solution.samples = control::retime_for(
        task_, std::move(solution.samples),
        control::joint_limits_for(task_, solution.dh_robot->dof()), opt_.retime, &timing);
    stats_.timing = timing;
    say(Stage::Timing,
        text::format("timed: %.3f s of motion, %d rests, %d passes, in %.1f ms", timing.duration,
                     timing.rests, timing.passes, 1e3 * seconds_since(t0)));
    return solution;
}

// The first certified design ends the search of skeletons, but another
// skeleton (a hanging column, another base region) may be shorter: the
// next few skeletons of the same joint count get one refinement each, and
// the shortest certified design is kept (or one as short to within
// length_tie with more clearance, as in the plane).
Solution Search::shorten(std::vector<Entry>& entries, std::size_t found, Solution first) {
    std::vector<Solution> certified;
    certified.push_back(std::move(first));
    const double took = clock_.seconds();
    int variants = 0;
    for (std::size_t i = 0; i < entries.size() && variants < opt_.shortening_variants; ++i) {
        if (i == found) continue;
        if (remaining() < 2.0 * took) {
            say(Stage::Shortening, "no time left to look for a shorter design");
            break;
        }
        Entry& e = entries[i];
        if (e.next >= e.guesses.size()) continue;
        ++variants;
        const ScoredDesign& g = e.guesses[e.next++];
        say(Stage::Shortening,
            describe(e.skeleton) + ": a shorter design? start " + describe(g.design));
        if (auto s = refine(e.skeleton, g)) certified.push_back(std::move(*s));
    }
    std::vector<DesignMerit> merits;
    for (const Solution& s : certified)
        merits.push_back({s.dh_robot->total_length(), s.certificate.min_clearance});
    return std::move(certified[choose_design(merits, opt_.length_tie)]);
}

}  // namespace

bool SpatialSynthesisOptions::IsValid(std::string* error) const {
    return text::OptionCheck("SpatialSynthesisOptions", error)
        .at_least("time_limit", time_limit, 0.0)
        .nested("motion", motion)
        .nested("retime", retime)
        .nested("verify", verify)
        .nested("front", front)
        .nested("guesses", guesses)
        .greater("point_spacing", point_spacing, 0.0)
        .at_least("max_points", max_points, 2)
        .at_least("first_guesses", first_guesses, 1)
        .at_least("later_guesses", later_guesses, 1)
        .at_least("refinement_rounds", refinement_rounds, 1)
        .greater("solve_seconds", solve_seconds, 0.0)
        .at_least("solve_iterations", solve_iterations, 1)
        .at_least("motion_refinement_passes", motion_refinement_passes, 0)
        .at_least("counterexamples_per_round", counterexamples_per_round, 1)
        .at_least("shortening_variants", shortening_variants, 0)
        .at_least("length_tie", length_tie, 0.0)
        .ok();
}

verify::VerifyOptions verify_options_for(const task::SpatialTask&,
                                         const SpatialSynthesisOptions& options) {
    verify::VerifyOptions v = options.verify;
    v.max_joint_step = options.motion.max_joint_step;
    v.max_ee_step = std::max(v.max_ee_step, options.motion.max_ee_step);
    return v;
}

Solution synthesize(const task::SpatialTask& task, const SpatialSynthesisOptions& options,
                    SynthesisStats* stats) {
    text::require_valid(options);
    SynthesisStats local;
    Search search(task, options, stats ? *stats : local);
    return search.run();
}

}  // namespace modsynth::synth
