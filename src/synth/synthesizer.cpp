#include <modsynth/synth/synthesizer.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <set>

#include <modsynth/control/motion.h>
#include <modsynth/geometry/polygon.h>
#include <modsynth/geometry/primitive.h>
#include <modsynth/nlp/formulation.h>
#include <modsynth/nlp/solver.h>
#include <modsynth/smt/front_stage.h>
#include <modsynth/synth/explanation.h>
#include <modsynth/synth/initial_guess.h>
#include <modsynth/synth/obstacle_proof.h>
#include <modsynth/verify/verifier.h>
#include <modsynth/text/format.h>

namespace modsynth::synth {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
}


std::string join(const std::vector<std::string>& v, const char* sep) {
    std::string s;
    for (std::size_t i = 0; i < v.size(); ++i) s += (i ? sep : "") + v[i];
    return s;
}

// Points where the refinement constrains the arm: evenly spaced along each
// primitive (critical points are added for the robot at hand).
// The count per primitive is capped, and the spacing widened when the
// whole path would need more than kTotal, so that the program stays small
// on long paths (the counterexamples add points where they are needed).
std::vector<nlp::PathPoint> spaced_points(const task::Task& task) {
    constexpr double kSpacing = 0.025;
    constexpr double kPerPrimitive = 200;
    constexpr double kTotal = 20000;
    double total = 0.0;
    for (const auto& p : task.trajectory) total += geometry::length(p);
    const double spacing = std::max(kSpacing, total / kTotal);
    std::vector<nlp::PathPoint> pts;
    for (int j = 0; j < static_cast<int>(task.trajectory.size()); ++j) {
        const double len = geometry::length(task.trajectory[j]);
        const int n = static_cast<int>(std::clamp(std::ceil(len / spacing), 4.0, kPerPrimitive));
        for (int i = 0; i <= n; ++i) pts.push_back({j, len * i / n});
    }
    return pts;
}

// Whether SV^over could hold near this robot: no obstacle centre inside
// conv(disc(base, r1) and primitive) for any primitive. When one is, the
// over-approximation cannot be met nearby and the attempt would only cost time.
bool swept_over_plausible(const task::Task& task, const kinematics::Robot& robot) {
    for (const auto& prim : task.trajectory) {
        std::vector<geometry::Vec2> pts;
        const double len = geometry::length(prim);
        for (int i = 0; i <= 16; ++i) pts.push_back(geometry::point_at(prim, len * i / 16));
        for (int i = 0; i < 32; ++i)
            pts.push_back(robot.base + robot.link_lengths[0] * geometry::unit(geometry::kTau * i / 32));
        const auto hull = geometry::convex_hull(pts);
        for (const auto& ob : task.obstacles)
            if (geometry::point_in_convex_polygon(ob.center, hull)) return false;
    }
    return true;
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
        const bool known = robot.dof() == 2 || j < static_cast<int>(robot.proximal_angles.size());
        const auto cp = geometry::critical_points(task.trajectory[j], known ? robot.tracing_origin(j) : robot.base);
        add_point(points, j, cp.closest.s);
        add_point(points, j, cp.farthest.s);
    }
}


class Search {
public:
    Search(const task::Task& task, const SynthesisOptions& options, SynthesisStats& stats)
        : task_(task), opt_(options), stats_(stats), start_(Clock::now()), motion_(options.motion) {
        deadline_ = start_ + std::chrono::duration_cast<Clock::duration>(
                                 std::chrono::duration<double>(std::max(0.0, opt_.time_limit)));
        motion_.deadline = deadline_;
        // A long path is sampled more coarsely rather than without bound;
        // the verifier certifies whatever steps the motion takes.
        double total = 0.0;
        for (const auto& p : task.trajectory) total += geometry::length(p);
        motion_.max_ee_step = std::max(motion_.max_ee_step, total / kTraceSamples);
    }

    Solution run();

private:
    double remaining() const { return opt_.time_limit - seconds_since(start_); }
    void say(const std::string& line) const {
        if (opt_.progress) opt_.progress(text::format("[%7.3fs] ", seconds_since(start_)) + line);
    }
    bool try_skeleton(const smt::Skeleton& skeleton, Solution& out, int guesses = 4);
    void shorten(const smt::Skeleton& found, Solution& out);
    bool refine(const smt::Skeleton& skeleton, const kinematics::Robot& start,
                nlp::SweptVolume swept, Solution& out);
    bool finish(const kinematics::Robot& robot, nlp::ArmProblem& problem, Solution& out);

    // Trace samples the path gets at the default step when it is long.
    static constexpr double kTraceSamples = 250000;

    const task::Task& task_;
    const SynthesisOptions& opt_;
    SynthesisStats& stats_;
    Clock::time_point start_;
    Clock::time_point deadline_;
    control::MotionOptions motion_;
    std::vector<std::string> tried_;
};

Solution Search::run() {
    Solution out;
    out.task_name = task_.name;
    // Walls and detours first: exact geometry in milliseconds, where the
    // front stage could only search.
    const auto t_walls = Clock::now();
    if (auto walls = prove_obstacle_infeasible(task_)) {
        stats_.front_seconds += seconds_since(t_walls);
        say("obstacles: proved infeasible, " + walls->message);
        out.status = Status::Infeasible;
        out.explanation.message = "Proved infeasible: " + walls->message;
        out.explanation.core = std::move(walls->core);
        out.explanation.separation = std::move(walls->separation);
        out.explanation.geodesic = std::move(walls->geodesic);
        return out;
    }
    stats_.front_seconds += seconds_since(t_walls);
    std::vector<std::vector<std::string>> cores;
    bool all_unsat = true;
    for (int dof : task_.robot.dof) {
        if (remaining() <= 0.0) {
            all_unsat = false;
            break;
        }
        const auto t0 = Clock::now();
        smt::FrontStageOptions fo;
        fo.time_limit = std::min(10.0, std::max(0.1, remaining()));
        fo.seed = opt_.seed;
        // Tearing down a large encoding takes time too: the front stage
        // stops a little before the run must end.
        fo.deadline = deadline_ - std::chrono::duration_cast<Clock::duration>(
                                      std::chrono::duration<double>(std::min(0.3, 0.1 * opt_.time_limit)));
        say(std::to_string(dof) + " joints: front stage");
        smt::FrontStage front(task_, dof, fo);
        auto result = front.check();
        stats_.front_seconds += seconds_since(t0);
        if (result == smt::FrontStage::Result::Unsat) {
            // A core found for fewer joints often holds here too: checking
            // it is cheaper than minimising afresh.
            const auto known = std::find_if(cores.begin(), cores.end(),
                                            [&](const auto& c) { return front.conflicts(c); });
            cores.push_back(known != cores.end() ? *known : front.minimal_core());
            say(std::to_string(dof) + " joints: proved infeasible, conflict between " + join(cores.back(), ", "));
            tried_.push_back(std::to_string(dof) + " joints proved infeasible (" + join(cores.back(), ", ") + ")");
            continue;
        }
        all_unsat = false;
        if (result == smt::FrontStage::Result::Unknown) {
            say(std::to_string(dof) + " joints: front stage gave up (" + front.reason_unknown() + ")");
            tried_.push_back(std::to_string(dof) + " joints: front stage undecided");
            continue;
        }
        int skeletons = 0;
        while (result == smt::FrontStage::Result::Sat && remaining() > 0.0) {
            const smt::Skeleton sk = front.skeleton();
            ++skeletons;
            ++stats_.skeletons;
            say(text::format("%d joints: skeleton %d (elbow %+d, base region %d)", dof, skeletons, sk.elbow,
                             sk.base_region));
            if (try_skeleton(sk, out)) {
                shorten(sk, out);
                return out;
            }
            front.block(sk);
            const auto t1 = Clock::now();
            result = front.check();
            stats_.front_seconds += seconds_since(t1);
        }
        const bool exhausted = result != smt::FrontStage::Result::Sat;
        tried_.push_back(text::format("%d joints: %d skeleton(s) searched", dof, skeletons) +
                         (exhausted ? " (all of them) without a certified motion" : ""));
        if (exhausted) say(std::to_string(dof) + " joints: search exhausted");
    }
    if (all_unsat && !cores.empty()) {
        const auto t0 = Clock::now();
        out.status = Status::Infeasible;
        out.explanation.core = common_core(task_, cores, std::max(0.1, std::min(5.0, remaining())));
        out.explanation.message = "Proved infeasible: " + describe_conflict(task_, out.explanation.core);
        stats_.front_seconds += seconds_since(t0);
        return out;
    }
    out.status = Status::Unknown;
    out.explanation.message = "No certified robot found" +
                              std::string(remaining() <= 0.0 ? " within the time limit" : "") + ": " +
                              join(tried_, "; ") + ".";
    for (const auto& c : cores)
        for (const auto& part : c)
            if (std::find(out.explanation.core.begin(), out.explanation.core.end(), part) == out.explanation.core.end())
                out.explanation.core.push_back(part);
    return out;
}

// The first certified robot ends the search, but it is often not the
// shortest: the refinement only sees its own elbow sign and base region, and
// the other branch can need much shorter links (on tasks/rose.json, 0.54 m
// against 0.97 m). Each other elbow sign and base region gets one initial
// guess; a fixed amount of work, so that solutions stay repeatable.
void Search::shorten(const smt::Skeleton& found, Solution& out) {
    for (int region : task::base_region_choices(task_)) {
        for (int elbow : {1, -1}) {
            if ((region == found.base_region && elbow == found.elbow) || remaining() <= 0.0) continue;
            smt::Skeleton variant = found;
            variant.base_region = region;
            variant.elbow = elbow;
            say(text::format("%d joints: shorter robot with elbow %+d, base region %d?", found.dof, elbow, region));
            Solution candidate;
            candidate.task_name = out.task_name;
            if (try_skeleton(variant, candidate, 1) &&
                candidate.robot.total_length() < out.robot.total_length() - 1e-6) {
                say(text::format("    shorter: total length %.4f m", candidate.robot.total_length()));
                out = std::move(candidate);
            }
        }
    }
}

bool Search::try_skeleton(const smt::Skeleton& skeleton, Solution& out, int count) {
    const auto guesses = initial_guesses(task_, skeleton, count, opt_.seed, deadline_);
    for (const auto& g : guesses) {
        if (remaining() <= 0.0) return false;
        say(text::format("  start: base (%.3f, %.3f), total length %.3f m", g.robot.base.x(), g.robot.base.y(),
                g.robot.total_length()) +
            text::format(", margin %.4f m", g.margin));
        // SV^over bounds a 2-link arm; with three joints the proximal link
        // moves between primitives and the sampled model is used directly.
        if (skeleton.dof == 2 && !task_.obstacles.empty() && swept_over_plausible(task_, g.robot) &&
            refine(skeleton, g.robot, nlp::SweptVolume::Over, out))
            return true;
        if (refine(skeleton, g.robot, nlp::SweptVolume::Sampled, out)) return true;
    }
    return false;
}

bool Search::refine(const smt::Skeleton& skeleton, const kinematics::Robot& start,
                    nlp::SweptVolume swept, Solution& out) {
    const char* name = swept == nlp::SweptVolume::Over ? "SV-over" : "sampled";
    nlp::ArmProblem problem;
    problem.transition_depth = 3;
    problem.task = &task_;
    problem.skeleton = skeleton;
    problem.start = start;
    problem.swept = swept;
    problem.points = spaced_points(task_);
    add_critical_points(task_, start, problem.points);
    constexpr int kRounds = 12;
    for (int round = 0; round < kRounds && remaining() > 0.0; ++round) {
        const auto t0 = Clock::now();
        const nlp::Formulation f = nlp::formulate(problem);
        nlp::SolverOptions so;
        // A refinement that needs more than this is better restarted from
        // another initial guess than waited for.
        so.time_limit = std::min(round == 0 ? 3.0 : 1.5, std::max(0.05, remaining()));
        so.max_iterations = round == 0 ? 200 : 100;
        const nlp::SolverResult res = nlp::minimize(f.program, so);
        stats_.refine_seconds += seconds_since(t0);
        ++stats_.nlp_solves;
        if (!res.usable()) {
            say(std::string("    ") + name + ": refinement did not converge (" + res.message + ")");
            return false;
        }
        const kinematics::Robot robot = nlp::robot_from(f, res.x);
        std::string links;
        for (double r : robot.link_lengths) links += text::format(links.empty() ? "%.4f" : " + %.4f", r);
        say(std::string("    ") + name + ": candidate links " + links +
            text::format(" m with %zu points, %d variables", problem.points.size(), f.program.num_variables()));
        const std::size_t before = problem.points.size();
        const int depth_before = problem.transition_depth;
        if (finish(robot, problem, out)) return true;
        if (problem.points.size() == before && problem.transition_depth == depth_before)
            return false;  // nothing left to learn
        stats_.counterexamples += static_cast<int>(problem.points.size() - before);
        problem.start = robot;
        if (swept == nlp::SweptVolume::Over) problem.swept = nlp::SweptVolume::Sampled;
        name = "sampled";
    }
    return false;
}

// Plans and certifies the motion. On failure, adds what went wrong to the
// problem for the next refinement (counterexample-guided): the offending
// points of a trace, or finer transitions.
bool Search::finish(const kinematics::Robot& robot, nlp::ArmProblem& problem, Solution& out) {
    constexpr int kMaxTransitionDepth = 4;
    std::vector<nlp::PathPoint>& points = problem.points;
    const auto t0 = Clock::now();
    control::MotionFailure failure;
    auto motion = control::plan_motion(task_, robot, motion_, &failure);
    if (!motion && failure.gave_up) {
        say("    motion planning stopped: " + failure.message);
        stats_.verify_seconds += seconds_since(t0);
        return false;  // nothing learnt: the refinement of this guess ends
    }
    if (!motion) {
        say("    out of reach at " + failure.message);
        if (failure.transition) {
            problem.transition_depth = std::min(kMaxTransitionDepth, problem.transition_depth + 1);
        } else {
            add_point(points, failure.primitive, failure.s);
        }
        add_critical_points(task_, robot, points);
        stats_.verify_seconds += seconds_since(t0);
        return false;
    }
    verify::VerifyOptions vo;
    vo.max_joint_step = motion_.max_joint_step;
    vo.max_ee_step = std::max(vo.max_ee_step, motion_.max_ee_step);
    verify::Certificate cert = verify::certify(task_, robot, *motion, vo);
    for (int pass = 0; pass < 8 && cert.violations.empty() && !cert.coarse_pairs.empty() && remaining() > 0.0;
         ++pass) {
        if (!control::refine_motion(task_, robot, *motion, cert.coarse_pairs)) break;
        cert = verify::certify(task_, robot, *motion, vo);
    }
    stats_.verify_seconds += seconds_since(t0);
    if (cert.ok) {
        control::assign_times(*motion, motion_);
        out.status = Status::Solved;
        out.robot = robot;
        out.samples = std::move(*motion);
        out.certificate = std::move(cert);
        say(text::format("    certified: clearance margin %.4f m, self margin %.4f m, deviation %.2g m",
                out.certificate.min_clearance, out.certificate.min_self_clearance,
                out.certificate.max_deviation));
        return true;
    }
    std::set<std::pair<int, long>> seen;
    int added = 0;
    for (const auto& v : cert.violations) {
        if (v.primitive < 0) continue;
        if (v.transition) {
            problem.transition_depth = std::min(kMaxTransitionDepth, problem.transition_depth + 1);
            continue;
        }
        if (!seen.insert({v.primitive, std::lround(v.s * 1e3)}).second) continue;
        add_point(points, v.primitive, v.s);
        if (++added >= 24) break;
    }
    if (!cert.violations.empty())
        say("    verification: " + std::to_string(cert.violations.size()) + " violation(s), first: " +
            cert.violations.front().message);
    add_critical_points(task_, robot, points);
    return false;
}

}  // namespace

Solution synthesize(const task::Task& task, const SynthesisOptions& options, SynthesisStats* stats) {
    SynthesisStats local;
    Search search(task, options, stats ? *stats : local);
    return search.run();
}

}  // namespace modsynth::synth
