#include <modsynth/explanation/spatial_explanation.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <type_traits>
#include <utility>
#include <variant>

#include <modsynth/geometry/curve_distance.h>
#include <modsynth/geometry/obstacle3.h>
#include <modsynth/geometry/primitive3.h>
#include <modsynth/geometry/vec.h>
#include <modsynth/prove/spatial_enclosure.h>
#include <modsynth/prove/spatial_reach_proof.h>
#include <modsynth/run/deadline.h>
#include <modsynth/run/stopwatch.h>
#include <modsynth/smt/spatial_front_stage.h>
#include <modsynth/synth/spatial_synthesizer.h>
#include <modsynth/task/spatial_strokes.h>
#include <modsynth/text/format.h>
#include <modsynth/text/option_check.h>

#include "relaxation_search.h"

namespace modsynth::explanation {
namespace {

using synth::Solution;
using synth::Status;
using task::RobotKey;
using task::TaskPart;

std::string join(const std::vector<TaskPart>& parts) {
    std::string s;
    for (std::size_t i = 0; i < parts.size(); ++i) s += (i ? ", " : "") + task::to_string(parts[i]);
    return s;
}

std::string joint_counts(const std::vector<int>& dof) {
    std::string s;
    for (std::size_t i = 0; i < dof.size(); ++i)
        s += (i == 0 ? "" : i + 1 == dof.size() ? " or " : ", ") + std::to_string(dof[i]);
    return s;
}

// Neither proof holds: no primitive is out of reach, and some allowed joint
// count's relaxation is satisfiable (undecided counts as conflicting, so
// that a suggestion is never unproved).
bool conflict_free(const task::SpatialTask& task, double check_seconds,
                   const run::Deadline& deadline) {
    if (prove::spatial_out_of_reach_core(task)) return false;
    prove::EnclosureOptions walls;
    walls.minimise = false;  // only whether one holds
    if (prove::prove_spatial_enclosure(task, deadline.within(check_seconds), walls)) return false;
    for (int dof : task.robot.dof) {
        smt::SpatialFrontStageOptions o;
        o.time_limit = check_seconds;
        o.deadline = deadline;
        smt::SpatialFrontStage fs(task, dof, o);
        if (fs.check() == smt::SpatialFrontStage::Result::Sat) return true;
    }
    return false;
}

/// The spatial synthesis on a relaxed task: its status and a sentence.
std::pair<Status, std::string> attempt(const task::SpatialTask& relaxed, double seconds) {
    if (seconds <= 0.0) {
        return {Status(Status::Unknown, "before solving", "time limit"),
                "the conflict is gone; not solved: the time limit was reached"};
    }
    synth::SpatialSynthesisOptions options;
    options.time_limit = seconds;
    const run::Stopwatch clock;
    const Solution s = synth::synthesize(relaxed, options);
    if (s.status == Status::Solved)
        return {s.status, text::format("solved in %.2f s: %d joints, chain %.3f m", clock.seconds(),
                                       s.dh_robot->dof(), s.dh_robot->total_length())};
    return unsolved_outcome(s, seconds);
}

class SpatialRelaxers : RelaxationSearch<task::SpatialTask> {
public:
    SpatialRelaxers(const task::SpatialTask& task, const std::vector<TaskPart>& core,
                    double solve_seconds, double time_limit, const RelaxationOptions& options)
        : RelaxationSearch(task, core, solve_seconds, time_limit, options, &conflict_free,
                           &attempt) {}

    std::vector<Relaxation> run();

    void longer_links(const TaskPart& part);
    void more_joints(const TaskPart& part);
    void other_twists(const TaskPart& part);
    void grown_region(const TaskPart& part);
    void moved_path(const TaskPart& part);
    void wider_tool(const TaskPart& part);

    /// For a wall's obstacles: the first whose removal opens it, and the
    /// least move of one of them outwards that does, those that face the
    /// path tried first.
    void obstacle_changes();
    /// Each obstacle's distance from the line between the path (the middle
    /// of the core's first primitive) and the base region nearest it.
    std::map<int, double> facing_distances(const std::vector<int>& ids) const;

private:
    /// Whether a changed task is out of the conflict, for a bisection: when
    /// a wall proves the task infeasible, whether the wall opens (cheap:
    /// offer() re-checks every proof before a change is printed), else
    /// whether the conflict is gone.
    bool opens(const task::SpatialTask& t);

    std::optional<bool> walled_;
    bool moved_path_done_ = false;
};

bool SpatialRelaxers::opens(const task::SpatialTask& t) {
    prove::EnclosureOptions quick;
    quick.minimise = false;
    if (!walled_) walled_ = prove::prove_spatial_enclosure(task_, deadline_, quick).has_value();
    if (*walled_) return !prove::prove_spatial_enclosure(t, deadline_, quick);
    return free(t);
}

struct SpatialRelaxer {
    TaskPart::Kind kind;
    std::optional<RobotKey> key;  ///< for robot parts: which key
    void (SpatialRelaxers::*relax)(const TaskPart&);
};

const SpatialRelaxer kSpatialRelaxers[] = {
    {TaskPart::Kind::Robot, RobotKey::MaxLinkLength, &SpatialRelaxers::longer_links},
    {TaskPart::Kind::Robot, RobotKey::Dof, &SpatialRelaxers::more_joints},
    {TaskPart::Kind::Robot, RobotKey::Twists, &SpatialRelaxers::other_twists},
    {TaskPart::Kind::BaseRegions, std::nullopt, &SpatialRelaxers::grown_region},
    {TaskPart::Kind::BaseRegion, std::nullopt, &SpatialRelaxers::grown_region},
    {TaskPart::Kind::Primitive, std::nullopt, &SpatialRelaxers::moved_path},
};

/// m: how close a moved path or obstacle may come to the other and still
/// count as off it (the reader refuses a path that touches an obstacle).
constexpr double kClear = 1e-3;
/// How many obstacles of a wall are tried for a removal, and for a move
/// (each a bisection).
constexpr std::size_t kObstacleTries = 8;
constexpr std::size_t kMoveTries = 3;

/// Whether the path keeps kClear off every obstacle (a task a reader
/// accepts). Past the deadline a change counts as not clear: each pair of
/// a long helix and an obstacle may take tens of milliseconds.
bool path_clear(const task::SpatialTask& task, const run::Deadline& deadline) {
    for (const auto& o : task.obstacles) {
        const auto gap = [&](const geometry::Vec3& p) {
            return std::max(0.0, geometry::point_gap(p, o));
        };
        for (const auto& p : task.trajectory) {
            if (deadline.expired()) return false;
            if (geometry::comes_within(p, gap, kClear)) return false;
        }
    }
    return true;
}

std::string vec_text(const geometry::Vec3& p) {
    return text::format("(%.3f, %.3f, %.3f)", p.x(), p.y(), p.z());
}

geometry::Obstacle3 moved(const geometry::Obstacle3& o, const geometry::Vec3& by) {
    return std::visit(
        [&](const auto& x) -> geometry::Obstacle3 {
            auto m = x;
            using T = std::decay_t<decltype(x)>;
            if constexpr (std::is_same_v<T, geometry::Sphere>) {
                m.center += by;
            } else if constexpr (std::is_same_v<T, geometry::Capsule>) {
                m.a += by;
                m.b += by;
            } else {
                m.min += by;
                m.max += by;
            }
            return m;
        },
        o);
}

std::string size_text(const geometry::Obstacle3& o) {
    return std::visit(
        [](const auto& x) -> std::string {
            using T = std::decay_t<decltype(x)>;
            if constexpr (std::is_same_v<T, geometry::Box3>) {
                const geometry::Vec3 d = x.max - x.min;
                return text::format("a box of %.3f x %.3f x %.3f m", d.x(), d.y(), d.z());
            } else if constexpr (std::is_same_v<T, geometry::Sphere>) {
                return text::format("a sphere of radius %.3f m", x.radius);
            } else {
                return text::format("a capsule of radius %.3f m", x.radius);
            }
        },
        o);
}

std::vector<Relaxation> SpatialRelaxers::run() {
    obstacle_changes();
    for (const TaskPart& part : core_) {
        if (deadline_.expired()) break;
        if (part.kind() == TaskPart::Kind::ToolAxis || part.field() == "tool_axis") {
            wider_tool(part);
            continue;
        }
        for (const SpatialRelaxer& r : kSpatialRelaxers) {
            if (r.kind != part.kind() || (r.key && !part.is_robot(*r.key)) || !part.field().empty())
                continue;
            (this->*r.relax)(part);
            break;
        }
    }
    return std::move(out_);
}

void SpatialRelaxers::longer_links(const TaskPart& part) {
    task::SpatialTask t = task_;
    const auto v = smallest(task_.robot.max_link_length, options_.longest_link,
                            options_.length_tolerance, [&](double x) {
                                t.robot.max_link_length = x;
                                return free(t);
                            });
    if (!v) return;
    t.robot.max_link_length = std::ceil(*v * 100.0) / 100.0;
    offer(part, text::format("robot.max_link_length >= %.2f m", t.robot.max_link_length), t);
}

// The least tolerance of a tool axis (the task's, or one primitive's) that
// removes the conflict, up to a right angle.
void SpatialRelaxers::wider_tool(const TaskPart& part) {
    task::SpatialTask t = task_;
    std::vector<task::ToolAxis*> axes;
    if (part.kind() == TaskPart::Kind::ToolAxis) {
        if (t.tool_axis) axes.push_back(&*t.tool_axis);
    } else {
        for (int j = 0; j < static_cast<int>(t.tool_axes.size()); ++j)
            if (t.tool_axes[static_cast<std::size_t>(j)] && task::tool_axis_part(task_, j) == part)
                axes.push_back(&*t.tool_axes[static_cast<std::size_t>(j)]);
    }
    if (axes.empty()) return;
    const double from = axes.front()->tolerance;
    const auto v = smallest(from, geometry::kPi / 2.0, 1e-3, [&](double th) {
        for (task::ToolAxis* a : axes) a->tolerance = th;
        return free(t);
    });
    if (!v) return;
    const double degrees = std::min(90.0, std::ceil(*v * 1800.0 / geometry::kPi) / 10.0);
    for (task::ToolAxis* a : axes) {
        a->tolerance = degrees * geometry::kPi / 180.0;
        a->tolerance_given = true;
    }
    offer(part,
          text::format("%s.tolerance >= %.1f degrees", task::to_string(part).c_str(), degrees), t);
}

// The fewest joints more than the task allows that remove the conflict.
void SpatialRelaxers::more_joints(const TaskPart& part) {
    const int most = *std::max_element(task_.robot.dof.begin(), task_.robot.dof.end());
    task::SpatialTask t = task_;
    for (int k = most + 1; k <= task::kMaxSpatialDof; ++k) {
        t.robot.dof.push_back(k);
        if (free(t)) {
            offer(part, "allow " + joint_counts(t.robot.dof) + " joints", t);
            return;
        }
    }
}

// With only vertical joint axes the EE keeps one height; a twist of
// +-pi/2 tilts an axis.
void SpatialRelaxers::other_twists(const TaskPart& part) {
    task::SpatialTask t = task_;
    t.robot.twists.push_back(geometry::kPi / 2);
    t.robot.twists.push_back(-geometry::kPi / 2);
    offer(part, "allow the twists +-pi/2 in robot.twists (a joint axis that tilts)", t);
}

// The region that needs the least growth on every side; for the whole list,
// each region is tried.
void SpatialRelaxers::grown_region(const TaskPart& part) {
    const int n = static_cast<int>(task_.base_regions.size());
    std::optional<std::pair<int, double>> best;
    for (int k = 0; k < n; ++k) {
        if (part.kind() == TaskPart::Kind::BaseRegion && part.index() != k) continue;
        if (deadline_.expired()) break;
        task::SpatialTask g = task_;
        const geometry::Box3 box = task_.base_regions[static_cast<std::size_t>(k)];
        const auto grow = [&](double d) {
            auto& b = g.base_regions[static_cast<std::size_t>(k)];
            b.min = box.min - geometry::Vec3::Constant(d);
            b.max = box.max + geometry::Vec3::Constant(d);
            return free(g);
        };
        const double hi = best ? best->second : options_.farthest_move;
        if (const auto v = smallest(0.0, hi, options_.length_tolerance, grow))
            if (!best || *v < best->second) best = {k, *v};
    }
    if (!best) return;
    task::SpatialTask g = task_;
    const double d = std::ceil(best->second * 100.0) / 100.0;
    auto& b = g.base_regions[static_cast<std::size_t>(best->first)];
    b.min -= geometry::Vec3::Constant(d);
    b.max += geometry::Vec3::Constant(d);
    offer(part,
          "grow " + task::to_string(TaskPart::base_region(best->first)) +
              text::format(" by %.2f m on every side", d),
          g);
}

std::map<int, double> SpatialRelaxers::facing_distances(const std::vector<int>& ids) const {
    // A point of the path in the core (the middle of its first primitive)
    // and the base region nearest it.
    std::optional<geometry::Vec3> point;
    for (const TaskPart& p : core_) {
        if (p.kind() != TaskPart::Kind::Primitive) continue;
        for (int k = 0; k < static_cast<int>(task_.trajectory.size()) && !point; ++k)
            if (task::primitive_part(task_, k) == p) {
                const auto& prim = task_.trajectory[static_cast<std::size_t>(k)];
                point = geometry::point_at(prim, geometry::length(prim) / 2);
            }
        if (point) break;
    }
    std::map<int, double> out;
    for (int i : ids) out[i] = 0.0;
    if (!point || task_.base_regions.empty()) return out;
    geometry::Vec3 base = task_.base_regions.front().center();
    for (const auto& r : task_.base_regions)
        if ((r.center() - *point).norm() < (base - *point).norm()) base = r.center();
    const geometry::Vec3 d = *point - base;
    for (int i : ids) {
        const geometry::Vec3 c =
            geometry::bounding_sphere(task_.obstacles[static_cast<std::size_t>(i)]).center;
        const double t =
            d.squaredNorm() > 0.0 ? std::clamp((c - base).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
        out[i] = (c - (base + t * d)).norm();
    }
    return out;
}

void SpatialRelaxers::obstacle_changes() {
    std::vector<int> ids;
    for (const TaskPart& p : core_)
        if (p.kind() == TaskPart::Kind::Obstacle && p.index() >= 0 &&
            p.index() < static_cast<int>(task_.obstacles.size()))
            ids.push_back(p.index());
    if (ids.empty()) return;
    // Outwards: away from the middle of the wall's obstacles.
    geometry::Vec3 middle = geometry::Vec3::Zero();
    for (int i : ids)
        middle += geometry::bounding_sphere(task_.obstacles[static_cast<std::size_t>(i)]).center;
    middle /= static_cast<double>(ids.size());
    // The wall opens where it faces the path: the obstacles nearest the line
    // from the base to the path first (taking away one behind the base
    // leaves the arm walled off from the path by the rest), then the
    // smallest, the least to take away or carry.
    const auto facing = facing_distances(ids);
    std::stable_sort(ids.begin(), ids.end(), [&](int a, int b) {
        const double fa = std::round(facing.at(a) * 1000.0), fb = std::round(facing.at(b) * 1000.0);
        if (fa != fb) return fa < fb;
        return geometry::bounding_sphere(task_.obstacles[static_cast<std::size_t>(a)]).radius <
               geometry::bounding_sphere(task_.obstacles[static_cast<std::size_t>(b)]).radius;
    });
    if (ids.size() > kObstacleTries) ids.resize(kObstacleTries);
    for (int i : ids) {
        if (deadline_.expired()) return;
        task::SpatialTask t = task_;
        t.obstacles.erase(t.obstacles.begin() + i);
        if (!opens(t)) continue;
        const auto& o = task_.obstacles[static_cast<std::size_t>(i)];
        if (offer(TaskPart::obstacle(i),
                  "remove " + task::to_string(TaskPart::obstacle(i)) + " (" + size_text(o) + ")",
                  t))
            break;
    }
    const double farthest = std::min(options_.farthest_move, 2.0);
    if (ids.size() > kMoveTries) ids.resize(kMoveTries);
    for (int i : ids) {
        if (deadline_.expired()) return;
        const auto& o = task_.obstacles[static_cast<std::size_t>(i)];
        geometry::Vec3 dir = geometry::bounding_sphere(o).center - middle;
        if (dir.norm() < 1e-9) continue;
        dir.normalize();
        const auto shifted = [&](double d) {
            task::SpatialTask t = task_;
            t.obstacles[static_cast<std::size_t>(i)] = moved(o, d * dir);
            return t;
        };
        const auto v = smallest(0.0, farthest, options_.length_tolerance, [&](double d) {
            const task::SpatialTask t = shifted(d);
            return path_clear(t, deadline_) && opens(t);
        });
        if (!v) continue;
        const double d = std::ceil(*v * 100.0) / 100.0;
        const task::SpatialTask t = shifted(d);
        if (!path_clear(t, deadline_)) continue;
        if (offer(TaskPart::obstacle(i),
                  "move " + task::to_string(TaskPart::obstacle(i)) +
                      text::format(" %.2f m outwards, by ", d) + vec_text(d * dir) +
                      ": the wall opens",
                  t))
            break;
    }
}

// The whole path (so it stays connected) towards the base region nearest
// to the wall's point, or to this primitive; once for all primitives.
void SpatialRelaxers::moved_path(const TaskPart& part) {
    if (moved_path_done_ || task_.base_regions.empty()) return;
    moved_path_done_ = true;
    std::optional<int> j;
    for (int k = 0; k < static_cast<int>(task_.trajectory.size()); ++k)
        if (task::primitive_part(task_, k) == part) j = k;
    if (!j) return;
    const auto& prim = task_.trajectory[static_cast<std::size_t>(*j)];
    const geometry::Vec3 from = geometry::point_at(prim, geometry::length(prim) / 2);
    geometry::Vec3 target = task_.base_regions.front().center();
    for (const auto& r : task_.base_regions)
        if ((r.center() - from).norm() < (target - from).norm()) target = r.center();
    const double distance = (target - from).norm();
    if (distance < 1e-9) return;
    const geometry::Vec3 dir = (target - from) / distance;
    const auto shifted = [&](double d) {
        task::SpatialTask m = task_;
        for (auto& p : m.trajectory) p = geometry::translate(p, d * dir);
        return m;
    };
    const auto v = smallest(0.0, distance, options_.length_tolerance, [&](double d) {
        const task::SpatialTask m = shifted(d);
        return path_clear(m, deadline_) && opens(m);
    });
    if (!v) return;
    const double d = std::min(distance, std::ceil(*v * 100.0) / 100.0);
    const task::SpatialTask m = shifted(d);
    if (!path_clear(m, deadline_)) return;
    offer(part,
          "move the path" + text::format(" %.2f m towards ", d) + vec_text(target) + ", by " +
              vec_text(d * dir),
          m);
}

}  // namespace

InfeasibilityProof prove_infeasible(const task::SpatialTask& task, double time_limit) {
    InfeasibilityProof proof;
    const run::Deadline deadline = run::Deadline::in(time_limit);
    if (auto core = prove::spatial_out_of_reach_core(task)) {
        proof.proved = true;
        proof.message = prove::describe_spatial_reach(task, *core);
        proof.core = std::move(*core);
        return proof;
    }
    // The same proofs in the same order as solve's: both name one core.
    if (auto wall = prove::prove_spatial_enclosure(task, deadline)) {
        proof.proved = true;
        proof.message = std::move(wall->message);
        proof.core = std::move(wall->core);
        proof.enclosure = std::move(wall->enclosure);
        return proof;
    }
    // Every joint count's minimal core; the core is their union, as solve's.
    std::vector<TaskPart> core;
    std::string counts;
    for (int dof : task.robot.dof) {
        smt::SpatialFrontStageOptions o;
        o.time_limit = std::max(0.05, std::min(o.time_limit, deadline.remaining()));
        o.deadline = deadline;
        smt::SpatialFrontStage fs(task, dof, o);
        const auto r = fs.check();
        if (r != smt::SpatialFrontStage::Result::Unsat) {
            proof.open +=
                (proof.open.empty() ? "" : "; ") + std::to_string(dof) + " joints " +
                (r == smt::SpatialFrontStage::Result::Sat ? "not ruled out" : "undecided");
            continue;
        }
        const std::vector<TaskPart> c = fs.minimal_core();
        if (c.empty()) {
            proof.open += (proof.open.empty() ? "" : "; ") + std::to_string(dof) +
                          " joints: no core within the time limit";
            continue;
        }
        counts += (counts.empty() ? "" : "; ") + std::to_string(dof) + " joints: " + join(c);
        for (const TaskPart& p : c)
            if (std::find(core.begin(), core.end(), p) == core.end()) core.push_back(p);
    }
    proof.proved = proof.open.empty() && !core.empty();
    if (proof.proved) {
        proof.core = std::move(core);
        proof.message = "no chain of " + joint_counts(task.robot.dof) +
                        " joints meets the conditions every chain must meet (reach of the "
                        "sampled path points from a base in the base regions, and the EE's "
                        "height when every joint axis is vertical); the conflicting parts, per "
                        "joint count: " +
                        counts + ".";
    }
    return proof;
}

std::string unproved_message(const task::SpatialTask&, const InfeasibilityProof& proof,
                             const Solution& s) {
    if (s.status == Status::Solved)
        return "No conflict: a " + std::to_string(s.dh_robot->dof()) +
               "-joint robot does this task (run solve).";
    return "Not proved infeasible (" + proof.open + "); " + s.explanation.message;
}

std::vector<Relaxation> suggest_relaxations(const task::SpatialTask& task,
                                            const std::vector<TaskPart>& core, double solve_seconds,
                                            double time_limit, const RelaxationOptions& options) {
    text::require_valid(options);
    return SpatialRelaxers(task, core, solve_seconds, time_limit, options).run();
}

}  // namespace modsynth::explanation
