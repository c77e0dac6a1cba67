#include <modsynth/synth/explanation.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <set>
#include <utility>

#include <modsynth/geometry/distance.h>
#include <modsynth/smt/front_stage.h>
#include <modsynth/synth/obstacle_proof.h>
#include <modsynth/synth/reach_proof.h>
#include <modsynth/synth/synthesizer.h>
#include <modsynth/synth/wall_changes.h>
#include <modsynth/task/strokes.h>
#include <modsynth/text/format.h>
#include <modsynth/text/option_check.h>

namespace modsynth::synth {
namespace {

using geometry::Vec2;
using Clock = std::chrono::steady_clock;

Clock::time_point after(double seconds) {
    return Clock::now() + std::chrono::duration_cast<Clock::duration>(
                              std::chrono::duration<double>(std::min(seconds, 1e6)));
}

double seconds_until(Clock::time_point t) {
    return std::chrono::duration<double>(t - Clock::now()).count();
}

bool has(const std::vector<std::string>& v, const std::string& s) {
    return std::find(v.begin(), v.end(), s) != v.end();
}

std::vector<std::string> with_prefix(const std::vector<std::string>& v, const std::string& prefix) {
    std::vector<std::string> out;
    for (const auto& s : v)
        if (s.rfind(prefix, 0) == 0) out.push_back(s);
    return out;
}

/// The parts that name primitives ("trajectory[j]" or "strokes[s][k]").
std::vector<std::string> primitive_parts(const std::vector<std::string>& v) {
    std::vector<std::string> out;
    for (const auto& s : v)
        if (task::names_primitive(s)) out.push_back(s);
    return out;
}

int index_of(const std::string& part) {
    const auto open = part.find('['), close = part.find(']');
    return std::stoi(part.substr(open + 1, close - open - 1));
}

std::string listing(const std::vector<std::string>& parts, const char* last = " and ") {
    std::string s;
    for (std::size_t i = 0; i < parts.size(); ++i)
        s += (i == 0 ? "" : (i + 1 == parts.size() ? last : ", ")) + parts[i];
    return s;
}

std::string joint_counts(const task::Task& task) {
    std::vector<std::string> d;
    for (int k : task.robot.dof) d.push_back(std::to_string(k));
    return listing(d, " or ");
}

// Front stage verdict over every allowed joint count: true when some count
// is satisfiable (the conflict is gone) and no obstacle proof holds, false
// when all are unsat or undecided.
bool conflict_free(const task::Task& task, double time_limit, Clock::time_point deadline) {
    if (prove_obstacle_infeasible(task)) return false;
    BranchAndBoundOptions bnb;
    bnb.time_limit = std::min(bnb.time_limit, time_limit);
    if (prove_two_joint_infeasible(task, bnb, deadline)) return false;
    for (int dof : task.robot.dof) {
        smt::FrontStageOptions o;
        o.time_limit = time_limit;
        o.deadline = deadline;
        smt::FrontStage fs(task, dof, o);
        if (fs.check() == smt::FrontStage::Result::Sat) return true;
    }
    return false;
}

// Smallest value in [lo, hi] (by bisection to `tolerance`) for which
// `free(value)` holds, assuming monotonicity; nullopt if not even at hi, or
// when the deadline passes first.
template <typename Free>
std::optional<double> smallest(double lo, double hi, double tolerance, Clock::time_point deadline,
                               Free free) {
    if (!free(hi)) return std::nullopt;
    while (hi - lo > tolerance) {
        if (Clock::now() >= deadline) return std::nullopt;
        const double mid = 0.5 * (lo + hi);
        (free(mid) ? hi : lo) = mid;
    }
    return hi;
}

/// The full pipeline on a relaxed task: its status and a sentence saying it.
std::pair<Status, std::string> attempt(const task::Task& relaxed, double seconds) {
    if (seconds <= 0.0) {
        return {Status(Status::Unknown, "before solving", "time limit"),
                "the conflict is gone; not solved: the time limit was reached"};
    }
    SynthesisOptions options;
    options.time_limit = seconds;
    const Solution s = synthesize(relaxed, options);
    if (s.status == Status::Solved) {
        std::string links;
        for (double r : s.robot.link_lengths)
            links += text::format(links.empty() ? "%.3f" : " + %.3f", r);
        return {s.status,
                "solved: " + std::to_string(s.robot.dof()) + " joints, links " + links + " m"};
    }
    if (s.status == Status::Infeasible)
        return {s.status, "still infeasible: " + s.explanation.message};
    return {s.status, "the conflict is gone, but no robot was found within " +
                          text::format("%.0f s", seconds)};
}

}  // namespace

std::vector<std::string> common_core(const task::Task& task,
                                     const std::vector<std::vector<std::string>>& cores,
                                     double time_limit) {
    const Clock::time_point deadline = after(time_limit);
    std::vector<std::vector<std::string>> candidates = cores;
    std::sort(candidates.begin(), candidates.end(),
              [](const auto& a, const auto& b) { return a.size() < b.size(); });
    for (const auto& c : candidates) {
        bool everywhere = true;
        for (int dof : task.robot.dof) {
            smt::FrontStageOptions o;
            o.time_limit = time_limit;
            o.deadline = deadline;
            smt::FrontStage fs(task, dof, o);
            everywhere = everywhere && fs.conflicts(c);
        }
        if (everywhere) return c;
    }
    std::vector<std::string> all;
    for (const auto& c : cores)
        for (const auto& part : c)
            if (!has(all, part)) all.push_back(part);
    return all;
}

InfeasibilityProof prove_infeasible(const task::Task& task, double time_limit) {
    InfeasibilityProof proof;
    const Clock::time_point deadline = after(time_limit);
    // The same proofs, in the same order, as solve's: both name one core.
    if (auto core = out_of_reach_core(task)) {
        proof.proved = true;
        proof.message = describe_conflict(task, *core);
        proof.core = std::move(*core);
        return proof;
    }
    std::optional<ObstacleProof> obstacles = prove_obstacle_infeasible(task);
    if (!obstacles) {
        // explain has the time to shrink the proof's obstacles to a minimal core.
        BranchAndBoundOptions options;
        options.core_time_limit = time_limit;
        obstacles = prove_two_joint_infeasible(task, options, deadline);
    }
    if (obstacles) {
        proof.proved = true;
        proof.core = std::move(obstacles->core);
        proof.message = std::move(obstacles->message);
        proof.separation = std::move(obstacles->separation);
        proof.geodesic = std::move(obstacles->geodesic);
        return proof;
    }
    std::vector<std::vector<std::string>> cores;
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
        proof.core = common_core(task, cores, std::max(0.0, seconds_until(deadline)));
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

std::string describe_conflict(const task::Task& task, const std::vector<std::string>& core) {
    const auto traj = primitive_parts(core);
    const auto obst = with_prefix(core, "obstacles[");
    const bool base = has(core, "base_regions");
    const bool longest = has(core, "robot.max_link_length");
    const bool shortest = has(core, "robot.min_link_length");
    const bool tube = has(core, "robot.link_diameter");
    const std::string arms = "an arm of " + joint_counts(task) + " links";
    if (!traj.empty() && longest && obst.empty() && !shortest) {
        return listing(traj) + (traj.size() > 1 ? " cannot all be reached" : " is out of reach") +
               (base ? " from every allowed base position" : " from any base position") + " by " +
               arms + text::format(" of at most %.2f m.", task.robot.max_link_length);
    }
    if (traj.empty() && !obst.empty() && base && tube) {
        return listing(obst) + (obst.size() > 1 ? " cover" : " covers") +
               " every allowed base position: the first joint would stand inside an obstacle.";
    }
    if (!traj.empty() && !obst.empty() && tube && !base && !longest) {
        return listing(obst) + " lies closer to " + listing(traj) +
               text::format(
                   " than half the tube diameter (%.4f m): the last link, which ends on the path, "
                   "would "
                   "touch it.",
                   task.robot.link_diameter / 2);
    }
    if (!traj.empty() && shortest) {
        return listing(traj) + " passes too close to " +
               (base ? std::string("every allowed base position") : std::string("the base")) +
               text::format(" for links of at least %.2f m: the arm cannot fold that tightly.",
                            task.robot.min_link_length);
    }
    return "These parts of the task cannot all be satisfied by " + arms + ": " + listing(core) +
           ".";
}

std::string describe_part(const task::Task& task, const std::string& part) {
    if (const auto j = task::primitive_of_part(task, part)) {
        const auto& p = task.trajectory.at(*j);
        switch (p.kind) {
            case geometry::PrimitiveKind::Line:
                return part + text::format(": a line from (%.3f, %.3f)", p.start.x(), p.start.y()) +
                       text::format(" to (%.3f, %.3f)", p.end.x(), p.end.y());
            case geometry::PrimitiveKind::Arc:
                return part + text::format(": an arc from (%.3f, %.3f)", p.start.x(), p.start.y()) +
                       text::format(" to (%.3f, %.3f)", p.end.x(), p.end.y()) +
                       text::format(" around (%.3f, %.3f)", p.center.x(), p.center.y());
            case geometry::PrimitiveKind::Circle:
                return part + text::format(": a circle of radius %.3f m around (%.3f, %.3f)",
                                           p.radius, p.center.x(), p.center.y());
        }
    }
    if (part.rfind("obstacles[", 0) == 0) {
        const auto& o = task.obstacles.at(index_of(part));
        return part + text::format(": a disc of radius %.3f m at (%.3f, %.3f)", o.radius,
                                   o.center.x(), o.center.y());
    }
    if (part == "base_regions") {
        std::string s = "base_regions: the base must stand in";
        for (std::size_t k = 0; k < task.base_regions.size(); ++k) {
            const auto& r = task.base_regions[k];
            s += (k ? " or" : "") + text::format(" [%.3f, %.3f] x", r.min.x(), r.max.x()) +
                 text::format(" [%.3f, %.3f]", r.min.y(), r.max.y());
        }
        return s;
    }
    if (part == "robot.max_link_length")
        return part + text::format(": links of at most %.3f m", task.robot.max_link_length);
    if (part == "robot.min_link_length")
        return part + text::format(": links of at least %.3f m", task.robot.min_link_length);
    if (part == "robot.link_diameter")
        return part + text::format(": tubes %.4f m thick", task.robot.link_diameter);
    if (part == "robot.dof") return part + ": " + joint_counts(task) + " joints";
    return part;
}

std::vector<Relaxation> suggest_relaxations(const task::Task& task,
                                            const std::vector<std::string>& core,
                                            double solve_seconds, double time_limit,
                                            const RelaxationOptions& options) {
    text::require_valid(options);
    const double kCheck = options.check_seconds;
    const Clock::time_point deadline = after(time_limit);
    const auto conflict_free = [&](const task::Task& t, double limit) {
        return synth::conflict_free(t, limit, deadline);
    };
    const auto smallest = [&](double lo, double hi, double tolerance, auto free) {
        return synth::smallest(lo, hi, tolerance, deadline, free);
    };
    std::vector<Relaxation> out;
    auto offer = [&](const std::string& part, const std::string& change,
                     const task::Task& relaxed) {
        // Re-checked here, whatever the search that found it assumed.
        if (!conflict_free(relaxed, kCheck)) return false;
        auto [status, outcome] = attempt(relaxed, std::min(solve_seconds, seconds_until(deadline)));
        out.push_back({part, change, relaxed, std::move(status), std::move(outcome)});
        return true;
    };
    // An obstacle proof's own moves (wall_changes.h) stand for its obstacles
    // and base regions: one of each kind, the first that also passes the
    // re-check above.
    const auto walls = prove_obstacle_infeasible(task);
    const bool walled = walls && std::set<std::string>(walls->core.begin(), walls->core.end()) ==
                                     std::set<std::string>(core.begin(), core.end());
    if (walled) {
        for (const auto& kind : wall_changes(task, *walls)) {
            for (const WallChange& c : kind) {
                if (Clock::now() >= deadline) break;
                if (offer(c.part, c.change, c.changed)) break;
            }
        }
    }
    const auto traj = primitive_parts(core);
    for (const std::string& part : core) {
        if (Clock::now() >= deadline) break;
        if (walled && (part == "base_regions" || part.rfind("obstacles[", 0) == 0)) continue;
        task::Task t = task;
        if (part == "robot.max_link_length") {
            const auto v = smallest(task.robot.max_link_length, options.longest_link,
                                    options.length_tolerance, [&](double x) {
                                        t.robot.max_link_length = x;
                                        return conflict_free(t, kCheck);
                                    });
            if (!v) continue;
            t.robot.max_link_length = std::ceil(*v * 100.0) / 100.0;
            offer(part,
                  text::format("robot.max_link_length >= %.2f m", t.robot.max_link_length) +
                      (traj.empty() ? "" : " would make " + listing(traj) + " reachable"),
                  t);
        } else if (part == "robot.min_link_length") {
            const auto v = smallest(-task.robot.min_link_length, 0.0, options.min_length_tolerance,
                                    [&](double x) {
                                        t.robot.min_link_length = -x;
                                        return conflict_free(t, kCheck);
                                    });
            if (!v) continue;
            t.robot.min_link_length = std::floor(-*v * 1000.0) / 1000.0;
            offer(part, text::format("robot.min_link_length <= %.3f m", t.robot.min_link_length),
                  t);
        } else if (part == "robot.link_diameter") {
            const auto v = smallest(-task.robot.link_diameter, -options.thinnest_tube,
                                    options.diameter_tolerance, [&](double x) {
                                        t.robot.link_diameter = -x;
                                        return conflict_free(t, kCheck);
                                    });
            if (!v) continue;
            t.robot.link_diameter = std::floor(-*v * 1000.0) / 1000.0;
            offer(part, text::format("robot.link_diameter <= %.3f m", t.robot.link_diameter), t);
        } else if (part == "base_regions" && !task.base_regions.empty()) {
            // Grow every region by d on all sides; the satisfied relaxation
            // then says where the base can stand, and the suggestion extends
            // the nearest region just to there.
            auto grown = [&](double d) {
                task::Task g = task;
                for (auto& r : g.base_regions)
                    r.min -= Vec2::Constant(d), r.max += Vec2::Constant(d);
                return g;
            };
            const auto v = smallest(0.0, options.farthest_move, options.length_tolerance,
                                    [&](double d) { return conflict_free(grown(d), kCheck); });
            if (!v) continue;
            // Where the base can stand: the model of a satisfiable joint count.
            std::optional<Vec2> found;
            for (int dof : task.robot.dof) {
                smt::FrontStageOptions o;
                o.deadline = deadline;
                smt::FrontStage fs(grown(*v), dof, o);
                if (fs.check() == smt::FrontStage::Result::Sat) {
                    found = fs.skeleton().base;
                    break;
                }
            }
            if (!found) continue;
            const Vec2 b = *found;
            std::size_t nearest = 0;
            double gap = 1e300;
            for (std::size_t k = 0; k < task.base_regions.size(); ++k) {
                const Vec2 clamp =
                    b.cwiseMax(task.base_regions[k].min).cwiseMin(task.base_regions[k].max);
                if ((b - clamp).norm() < gap) gap = (b - clamp).norm(), nearest = k;
            }
            task::Task e = task;
            e.base_regions[nearest].min = e.base_regions[nearest].min.cwiseMin(b);
            e.base_regions[nearest].max = e.base_regions[nearest].max.cwiseMax(b);
            offer(part,
                  "extend base_regions[" + std::to_string(nearest) + "]" +
                      text::format(" by %.2f m towards (%.2f, %.2f)", gap, b.x(), b.y()),
                  e);
        } else if (part == "robot.dof" && task.robot.dof.back() < task::kMaxDof) {
            // Only the 2-joint branch and bound names the joint count: one
            // more joint is a second bend.
            for (int k = task.robot.dof.back() + 1; k <= task::kMaxDof; ++k)
                t.robot.dof.push_back(k);
            if (!conflict_free(t, kCheck)) continue;
            offer(part, "allow " + joint_counts(t) + " joints", t);
        } else if (part.rfind("obstacles[", 0) == 0) {
            const int o = index_of(part);
            t.obstacles.erase(t.obstacles.begin() + o);
            if (!conflict_free(t, kCheck)) continue;
            // The largest radius that still leaves room.
            task::Task s = task;
            const auto v = smallest(-task.obstacles[o].radius, -options.smallest_radius,
                                    options.radius_tolerance, [&](double x) {
                                        s.obstacles[o].radius = -x;
                                        return conflict_free(s, kCheck);
                                    });
            if (v) {
                s.obstacles[o].radius = std::floor(-*v * 1000.0) / 1000.0;
                offer(part, part + text::format(" with radius <= %.3f m", s.obstacles[o].radius),
                      s);
            } else {
                offer(part, "without " + part, t);
            }
        } else if (task::primitive_of_part(task, part) && !task.base_regions.empty()) {
            // Bring the whole path (so it stays connected) towards the base
            // region nearest to this primitive.
            const int j = *task::primitive_of_part(task, part);
            const geometry::Primitive& prim = task.trajectory[j];
            const Vec2 mid = geometry::point_at(prim, geometry::length(prim) / 2);
            Vec2 target = 0.5 * (task.base_regions[0].min + task.base_regions[0].max);
            for (const auto& r : task.base_regions) {
                const Vec2 c = 0.5 * (r.min + r.max);
                if ((c - mid).norm() < (target - mid).norm()) target = c;
            }
            const Vec2 dir = (target - mid).normalized();
            auto moved = [&](double d) {
                task::Task m = task;
                for (geometry::Primitive& p : m.trajectory)
                    p.start += d * dir, p.end += d * dir, p.center += d * dir;
                return m;
            };
            const auto v = smallest(0.0, (target - mid).norm(), options.length_tolerance,
                                    [&](double d) { return conflict_free(moved(d), kCheck); });
            if (!v) continue;
            const double d = std::ceil(*v * 100.0) / 100.0;
            offer(part,
                  "move the path" +
                      text::format(" %.2f m towards (%.2f, %.2f)", d, target.x(), target.y()) +
                      " to bring " + part + " within reach",
                  moved(d));
        }
    }
    return out;
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

}  // namespace modsynth::synth
