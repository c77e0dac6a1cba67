#include <modsynth/explanation/explanation.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <utility>

#include <modsynth/explanation/wall_changes.h>
#include <modsynth/prove/conflict_text.h>
#include <modsynth/prove/loop_proof.h>
#include <modsynth/prove/obstacle_proof.h>
#include <modsynth/prove/provers.h>
#include <modsynth/run/deadline.h>
#include <modsynth/run/stopwatch.h>
#include <modsynth/smt/common_core.h>
#include <modsynth/smt/front_stage.h>
#include <modsynth/synth/synthesizer.h>
#include <modsynth/text/format.h>
#include <modsynth/text/option_check.h>

#include "relaxation_search.h"

namespace modsynth::explanation {

using prove::BranchAndBoundOptions;
using prove::describe_conflict;
using prove::joint_counts;
using prove::listing;
using prove::Proof;
using prove::prove_obstacle_infeasible;
using prove::prove_two_joint_infeasible;
using prove::Prover;
using prove::provers;
using synth::Solution;
using synth::Status;
using synth::SynthesisOptions;
using synth::synthesize;

namespace {

using geometry::Vec2;
using task::RobotKey;
using task::TaskPart;

// Front stage verdict over every allowed joint count: true when some count
// is satisfiable (the conflict is gone) and no obstacle proof holds, false
// when all are unsat or undecided (2 joints count as unsat where a loop of
// the path winds round an obstacle, loop_proof.h).
bool conflict_free(const task::Task& task, double time_limit, const run::Deadline& deadline) {
    if (prove_obstacle_infeasible(task)) return false;
    BranchAndBoundOptions bnb;
    bnb.time_limit = std::min(bnb.time_limit, time_limit);
    if (prove_two_joint_infeasible(task, bnb, deadline)) return false;
    const bool two_joint_loop = prove::prove_two_joint_loop(task).has_value();
    for (int dof : task.robot.dof) {
        if (dof == 2 && two_joint_loop) continue;
        smt::FrontStageOptions o;
        o.time_limit = time_limit;
        o.deadline = deadline;
        smt::FrontStage fs(task, dof, o);
        if (fs.check() == smt::FrontStage::Result::Sat) return true;
    }
    return false;
}

/// The full pipeline on a relaxed task: its status and a sentence saying it.
std::pair<Status, std::string> attempt(const task::Task& relaxed, double seconds) {
    if (seconds <= 0.0) {
        return {Status(Status::Unknown, "before solving", "time limit"),
                "the conflict is gone; not solved: the time limit was reached"};
    }
    SynthesisOptions options;
    options.time_limit = seconds;
    const run::Stopwatch clock;
    const Solution s = synthesize(relaxed, options);
    if (s.status == Status::Solved) {
        std::string links;
        for (double r : s.robot.link_lengths)
            links += text::format(links.empty() ? "%.3f" : " + %.3f", r);
        return {s.status, text::format("solved in %.2f s: ", clock.seconds()) +
                              std::to_string(s.robot.dof()) + " joints, links " + links + " m"};
    }
    return unsolved_outcome(s, seconds);
}

// The search for the smallest change of each core part: one relaxer per
// kind of part (the table below), each bisecting one number of the task
// until the conflict is gone, and offering the change once re-checked.
class Relaxers : RelaxationSearch<task::Task> {
public:
    Relaxers(const task::Task& task, const std::vector<TaskPart>& core, double solve_seconds,
             double time_limit, const RelaxationOptions& options)
        : RelaxationSearch(task, core, solve_seconds, time_limit, options, &conflict_free,
                           &attempt) {
        for (const TaskPart& p : core)
            if (p.kind() == TaskPart::Kind::Primitive) paths_.push_back(task::to_string(p));
    }

    std::vector<Relaxation> run();

    void longer_links(const TaskPart& part);
    void shorter_links(const TaskPart& part);
    void thinner_tube(const TaskPart& part);
    void more_joints(const TaskPart& part);
    void grown_regions(const TaskPart& part);
    void smaller_obstacle(const TaskPart& part);
    void moved_path(const TaskPart& part);

private:
    std::vector<std::string> paths_;  ///< the core's primitives, by name
};

struct Relaxer {
    TaskPart::Kind kind;
    std::optional<RobotKey> key;  ///< for robot parts: which key
    void (Relaxers::*relax)(const TaskPart&);
};

// Parts of other kinds (a single base region, the modules, ...) get no
// suggestion: no proof names them.
const Relaxer kRelaxers[] = {
    {TaskPart::Kind::Robot, RobotKey::MaxLinkLength, &Relaxers::longer_links},
    {TaskPart::Kind::Robot, RobotKey::MinLinkLength, &Relaxers::shorter_links},
    {TaskPart::Kind::Robot, RobotKey::LinkDiameter, &Relaxers::thinner_tube},
    {TaskPart::Kind::Robot, RobotKey::Dof, &Relaxers::more_joints},
    {TaskPart::Kind::BaseRegions, std::nullopt, &Relaxers::grown_regions},
    {TaskPart::Kind::Obstacle, std::nullopt, &Relaxers::smaller_obstacle},
    {TaskPart::Kind::Primitive, std::nullopt, &Relaxers::moved_path},
};

std::vector<Relaxation> Relaxers::run() {
    // An obstacle proof's own moves (wall_changes.h) stand for its obstacles
    // and base regions: one of each kind, the first that also passes the
    // re-check.
    const auto walls = prove_obstacle_infeasible(task_);
    const bool walled = walls && std::set<TaskPart>(walls->core.begin(), walls->core.end()) ==
                                     std::set<TaskPart>(core_.begin(), core_.end());
    if (walled) {
        for (const auto& kind : wall_changes(task_, *walls)) {
            for (const WallChange& c : kind) {
                if (deadline_.expired()) break;
                if (offer(c.part, c.change, c.changed)) break;
            }
        }
    }
    for (const TaskPart& part : core_) {
        if (deadline_.expired()) break;
        if (walled &&
            (part.kind() == TaskPart::Kind::BaseRegions || part.kind() == TaskPart::Kind::Obstacle))
            continue;
        for (const Relaxer& r : kRelaxers) {
            if (r.kind != part.kind() || (r.key && !part.is_robot(*r.key)) || !part.field().empty())
                continue;
            (this->*r.relax)(part);
            break;
        }
    }
    return std::move(out_);
}

void Relaxers::longer_links(const TaskPart& part) {
    task::Task t = task_;
    const auto v = smallest(task_.robot.max_link_length, options_.longest_link,
                            options_.length_tolerance, [&](double x) {
                                t.robot.max_link_length = x;
                                return free(t);
                            });
    if (!v) return;
    t.robot.max_link_length = std::ceil(*v * 100.0) / 100.0;
    offer(part,
          text::format("robot.max_link_length >= %.2f m", t.robot.max_link_length) +
              (paths_.empty() ? "" : " would make " + listing(paths_) + " reachable"),
          t);
}

void Relaxers::shorter_links(const TaskPart& part) {
    task::Task t = task_;
    const auto v =
        smallest(-task_.robot.min_link_length, 0.0, options_.min_length_tolerance, [&](double x) {
            t.robot.min_link_length = -x;
            return free(t);
        });
    if (!v) return;
    t.robot.min_link_length = std::floor(-*v * 1000.0) / 1000.0;
    offer(part, text::format("robot.min_link_length <= %.3f m", t.robot.min_link_length), t);
}

void Relaxers::thinner_tube(const TaskPart& part) {
    task::Task t = task_;
    const auto v = smallest(-task_.robot.link_diameter, -options_.thinnest_tube,
                            options_.diameter_tolerance, [&](double x) {
                                t.robot.link_diameter = -x;
                                return free(t);
                            });
    if (!v) return;
    t.robot.link_diameter = std::floor(-*v * 1000.0) / 1000.0;
    offer(part, text::format("robot.link_diameter <= %.3f m", t.robot.link_diameter), t);
}

// Only the 2-joint branch and bound names the joint count: one more joint
// is a second bend.
void Relaxers::more_joints(const TaskPart& part) {
    if (task_.robot.dof.back() >= task::kMaxDof) return;
    task::Task t = task_;
    for (int k = task_.robot.dof.back() + 1; k <= task::kMaxDof; ++k) t.robot.dof.push_back(k);
    if (!free(t)) return;
    offer(part, "allow " + joint_counts(t) + " joints", t);
}

// Grows every region by d on all sides; the satisfied relaxation then says
// where the base can stand, and the suggestion extends the nearest region
// just to there.
void Relaxers::grown_regions(const TaskPart& part) {
    if (task_.base_regions.empty()) return;
    auto grown = [&](double d) {
        task::Task g = task_;
        for (auto& r : g.base_regions) r.min -= Vec2::Constant(d), r.max += Vec2::Constant(d);
        return g;
    };
    const auto v = smallest(0.0, options_.farthest_move, options_.length_tolerance,
                            [&](double d) { return free(grown(d)); });
    if (!v) return;
    // Where the base can stand: the model of a satisfiable joint count.
    std::optional<Vec2> found;
    for (int dof : task_.robot.dof) {
        smt::FrontStageOptions o;
        o.deadline = deadline_;
        smt::FrontStage fs(grown(*v), dof, o);
        if (fs.check() == smt::FrontStage::Result::Sat) {
            found = fs.skeleton().base;
            break;
        }
    }
    if (!found) return;
    const Vec2 b = *found;
    std::size_t nearest = 0;
    double gap = 1e300;
    for (std::size_t k = 0; k < task_.base_regions.size(); ++k) {
        const Vec2 clamp =
            b.cwiseMax(task_.base_regions[k].min).cwiseMin(task_.base_regions[k].max);
        if ((b - clamp).norm() < gap) gap = (b - clamp).norm(), nearest = k;
    }
    task::Task e = task_;
    e.base_regions[nearest].min = e.base_regions[nearest].min.cwiseMin(b);
    e.base_regions[nearest].max = e.base_regions[nearest].max.cwiseMax(b);
    offer(part,
          "extend " + task::to_string(TaskPart::base_region(static_cast<int>(nearest))) +
              text::format(" by %.2f m towards (%.2f, %.2f)", gap, b.x(), b.y()),
          e);
}

// The largest radius that still leaves room, or else no obstacle at all.
void Relaxers::smaller_obstacle(const TaskPart& part) {
    const int o = part.index();
    if (o < 0 || o >= static_cast<int>(task_.obstacles.size())) return;
    task::Task t = task_;
    t.obstacles.erase(t.obstacles.begin() + o);
    if (!free(t)) return;
    task::Task s = task_;
    const auto v = smallest(-task_.obstacles[o].radius, -options_.smallest_radius,
                            options_.radius_tolerance, [&](double x) {
                                s.obstacles[o].radius = -x;
                                return free(s);
                            });
    const std::string name = task::to_string(part);
    if (v) {
        s.obstacles[o].radius = std::floor(-*v * 1000.0) / 1000.0;
        offer(part, name + text::format(" with radius <= %.3f m", s.obstacles[o].radius), s);
    } else {
        offer(part, "without " + name, t);
    }
}

// Brings the whole path (so it stays connected) towards the base region
// nearest to this primitive.
void Relaxers::moved_path(const TaskPart& part) {
    const auto j = task::primitive_index(task_, part);
    if (!j || task_.base_regions.empty()) return;
    const geometry::Primitive& prim = task_.trajectory[*j];
    const Vec2 mid = geometry::point_at(prim, geometry::length(prim) / 2);
    Vec2 target = 0.5 * (task_.base_regions[0].min + task_.base_regions[0].max);
    for (const auto& r : task_.base_regions) {
        const Vec2 c = 0.5 * (r.min + r.max);
        if ((c - mid).norm() < (target - mid).norm()) target = c;
    }
    const Vec2 dir = (target - mid).normalized();
    auto moved = [&](double d) {
        task::Task m = task_;
        for (geometry::Primitive& p : m.trajectory) p = geometry::translate(p, d * dir);
        return m;
    };
    const auto v = smallest(0.0, (target - mid).norm(), options_.length_tolerance,
                            [&](double d) { return free(moved(d)); });
    if (!v) return;
    const double d = std::ceil(*v * 100.0) / 100.0;
    offer(part,
          "move the path" +
              text::format(" %.2f m towards (%.2f, %.2f)", d, target.x(), target.y()) +
              " to bring " + task::to_string(part) + " within reach",
          moved(d));
}

}  // namespace

InfeasibilityProof prove_infeasible(const task::Task& task, double time_limit) {
    InfeasibilityProof proof;
    const run::Deadline deadline = run::Deadline::in(time_limit);
    // The same proofs, in the same order, as solve's: both name one core.
    // explain has the time to shrink a branch and bound's obstacles to a
    // minimal core.
    BranchAndBoundOptions bnb;
    bnb.core_time_limit = time_limit;
    for (const Prover& prover : provers(bnb)) {
        std::optional<Proof> found = prover.prove(task, deadline);
        if (!found) continue;
        proof.proved = true;
        proof.core = std::move(found->core);
        proof.message = std::move(found->message);
        proof.separation = std::move(found->separation);
        proof.geodesic = std::move(found->geodesic);
        return proof;
    }
    std::vector<std::vector<TaskPart>> cores;
    for (int dof : task.robot.dof) {
        smt::FrontStageOptions o;
        o.time_limit = time_limit;
        o.deadline = deadline;
        smt::FrontStage fs(task, dof, o);
        const auto r = fs.check();
        if (r != smt::FrontStage::Result::Unsat) {
            proof.open += (proof.open.empty() ? "" : "; ") + std::to_string(dof) + " joints " +
                          (r == smt::FrontStage::Result::Sat ? "not ruled out" : "undecided");
            continue;
        }
        cores.push_back(fs.minimal_core());
        if (cores.back().empty())
            proof.open += (proof.open.empty() ? "" : "; ") + std::to_string(dof) +
                          " joints: no core within the time limit";
    }
    proof.proved = proof.open.empty() && !cores.empty();
    if (proof.proved) {
        proof.core = smt::common_core(task, cores, std::max(0.0, deadline.remaining()));
        proof.message = describe_conflict(task, proof.core);
    }
    return proof;
}

std::string proved_message(const InfeasibilityProof& proof) {
    return "Proved infeasible: " + proof.message;
}

std::string unproved_message(const InfeasibilityProof& proof, const Solution& s) {
    if (s.status == Status::Solved)
        return "No conflict: a " + std::to_string(s.robot.dof()) +
               "-joint robot does this task (run solve).";
    return "Not proved infeasible (" + proof.open + "); " + s.explanation.message;
}

std::vector<Relaxation> suggest_relaxations(const task::Task& task,
                                            const std::vector<TaskPart>& core, double solve_seconds,
                                            double time_limit, const RelaxationOptions& options) {
    text::require_valid(options);
    return Relaxers(task, core, solve_seconds, time_limit, options).run();
}

bool RelaxationOptions::IsValid(std::string* error) const {
    return text::OptionCheck("RelaxationOptions", error)
        .greater("check_seconds", check_seconds, 0.0)
        .greater("longest_link", longest_link, 0.0)
        .greater("farthest_move", farthest_move, 0.0)
        .greater("length_tolerance", length_tolerance, 0.0)
        .greater("min_length_tolerance", min_length_tolerance, 0.0)
        .greater("diameter_tolerance", diameter_tolerance, 0.0)
        .greater("radius_tolerance", radius_tolerance, 0.0)
        .greater("thinnest_tube", thinnest_tube, 0.0)
        .greater("smallest_radius", smallest_radius, 0.0)
        .ok();
}

}  // namespace modsynth::explanation
