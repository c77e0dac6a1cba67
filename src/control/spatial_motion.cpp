#include <modsynth/control/spatial_motion.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <modsynth/control/spatial_samples.h>
#include <modsynth/geometry/primitive3.h>
#include <modsynth/kinematics/dh_motion_bound.h>
#include <modsynth/kinematics/kinematics.h>
#include <modsynth/task/spatial_strokes.h>
#include <modsynth/text/format.h>
#include <modsynth/text/option_check.h>

#include "walk.h"

namespace modsynth::control {
namespace {

void unwrap(std::vector<double>& q, const std::vector<double>* previous) {
    if (!previous) return;
    for (std::size_t k = 0; k < q.size(); ++k) q[k] = kinematics::unwrap_near(q[k], (*previous)[k]);
}

std::vector<double> lerp(const std::vector<double>& a, const std::vector<double>& b, double t) {
    std::vector<double> out(a.size());
    for (std::size_t k = 0; k < a.size(); ++k) out[k] = a[k] + t * (b[k] - a[k]);
    return out;
}

/// The pose of `design` with its EE at `target`, unwrapped next to
/// `previous` when given.
std::optional<std::vector<double>> configuration(const kinematics::ArmDesign& design, int branch,
                                                 const geometry::Vec3& target,
                                                 const std::vector<double>& along,
                                                 const std::vector<double>* previous) {
    kinematics::PoseTarget<double> t;
    t.point = target;
    auto q = design.model->joint_angles(design, t, branch, along);
    if (q) unwrap(*q, previous);
    return q;
}

int branch_of(const task::SpatialTask& task, const kinematics::ArmDesign& design, int j) {
    return design.branches[static_cast<std::size_t>(task::stroke_of(task, j))];
}

std::optional<std::vector<double>> transition_configuration(const task::SpatialTask& task,
                                                            const kinematics::ArmDesign& design,
                                                            int j, double t,
                                                            const std::vector<double>* previous) {
    return configuration(design, branch_of(task, design, j),
                         geometry::end_point(task.trajectory[static_cast<std::size_t>(j)]),
                         design.transition_along(j, t), previous);
}

void check_fits(const task::SpatialTask& task, const kinematics::ArmDesign& design) {
    const auto m = task.trajectory.size();
    const int along = design.model->along_count(design.dof(), design.shape.variant);
    if (design.branches.size() != static_cast<std::size_t>(task::stroke_count(task)))
        throw std::invalid_argument("plan_spatial_motion: one IK branch per stroke is needed");
    if (along > 0 && (design.along.size() != m ||
                      std::any_of(design.along.begin(), design.along.end(), [&](const auto& p) {
                          return static_cast<int>(p.size()) != 2 * along;
                      })))
        throw std::invalid_argument(
            "plan_spatial_motion: the free numbers of every primitive's ends are needed");
}

}  // namespace

bool SpatialMotionOptions::IsValid(std::string* error) const {
    return text::OptionCheck("SpatialMotionOptions", error)
        .greater("max_joint_step", max_joint_step, 0.0)
        .greater("max_ee_step", max_ee_step, 0.0)
        .greater("max_chord_gap", max_chord_gap, 0.0)
        .holds("max_samples", max_samples >= 2, "must be at least 2")
        .at_least("step_attempts", step_attempts, 1)
        .ok();
}

std::optional<std::vector<double>> spatial_configuration_at(const task::SpatialTask& task,
                                                            const kinematics::ArmDesign& design,
                                                            int j, double s,
                                                            const std::vector<double>* previous) {
    const geometry::Primitive3& prim = task.trajectory[static_cast<std::size_t>(j)];
    const double length = geometry::length(prim);
    return configuration(design, branch_of(task, design, j), geometry::point_at(prim, s),
                         design.along_at(j, length > 0.0 ? s / length : 0.0), previous);
}

std::optional<std::vector<Sample>> plan_spatial_motion(const task::SpatialTask& task,
                                                       const kinematics::ArmDesign& design,
                                                       const SpatialMotionOptions& options,
                                                       MotionFailure* failure) {
    text::require_valid(options);
    check_fits(task, design);
    std::vector<Sample> out;
    const kinematics::DhChain chain = design.chain();
    const double total = chain.total_length();
    const WalkLimits limits{options.max_samples, options.deadline, options.step_attempts};
    // A step fits when no joint moves more than max_joint_step and the EE
    // strays from its chord by at most max_chord_gap. The chord bound is
    // quadratic in the step, the joint step linear: shrinking by the joint
    // ratio alone may not be enough, so at least a tenth goes every time.
    const auto shrink = [&](const std::vector<double>& last,
                            const std::vector<double>& next) -> std::optional<double> {
        const double change = largest_change(last, next);
        std::vector<double> dq(next.size());
        for (std::size_t k = 0; k < next.size(); ++k) dq[k] = next[k] - last[k];
        if (change <= options.max_joint_step &&
            kinematics::chord_gap(chain, dq, 0, chain.dof(), total) <= options.max_chord_gap)
            return std::nullopt;
        return std::clamp(0.9 * options.max_joint_step / std::max(change, 1e-300), 0.1, 0.7);
    };
    double failed_at = 0.0;
    bool gave_up = false;
    const auto walk_to = [&](double to, double step, Phase phase, int k, int stroke,
                             auto config_at) {
        const auto stop =
            walk(0.0, to, step, step, limits, phase, k, stroke, out, config_at, shrink);
        if (stop) failed_at = stop->at, gave_up = stop->gave_up;
        return !stop;
    };
    auto fail = [&](int j, bool transition, double s,
                    bool travel = false) -> std::optional<std::vector<Sample>> {
        if (failure) {
            const std::string name = task::part_name(task, j);
            *failure = {j,
                        transition,
                        travel,
                        s,
                        gave_up,
                        transition ? "the transition after " + name
                        : travel   ? "the travel after " + name
                                   : name + text::format(" at %.4f m from its start", s)};
            if (gave_up)
                failure->message =
                    out.size() >= options.max_samples
                        ? text::format("%zu samples, the most a motion may have", out.size())
                        : std::string("the time limit");
        }
        return std::nullopt;
    };
    const int m = static_cast<int>(task.trajectory.size());
    for (int j = 0; j < m; ++j) {
        const int stroke = task::stroke_of(task, j);
        const int k = j - task::stroke_first(task, stroke);
        std::optional<std::vector<double>> q;
        if (k > 0 && design.sweeps_after(j - 1)) {
            // The EE holds the join while the free numbers sweep linearly to
            // the next primitive's.
            const std::size_t before = out.size();
            const bool ok =
                walk_to(1.0, 1.0, Phase::Transition, k - 1, stroke,
                        [&](double t, const std::vector<double>* prev) {
                            return transition_configuration(task, design, j - 1, t, prev);
                        });
            if (!ok) return fail(j - 1, true, failed_at);
            if (out.size() > before) out.pop_back();  // the last pose is the next trace's first
        } else if (j > 0 && k == 0) {
            // A new stroke: a straight joint-space line, each joint the short
            // way round, to the pose that starts it.
            q = spatial_configuration_at(task, design, j, 0.0, &out.back().q);
            if (!q) return fail(j, false, 0.0);
            const std::vector<double> from = out.back().q;
            const int steps =
                static_cast<int>(std::ceil(largest_change(from, *q) / options.max_joint_step));
            const int last =
                task::stroke_last(task, stroke - 1) - task::stroke_first(task, stroke - 1);
            for (int i = 1; i < steps; ++i)
                out.push_back({0.0, Phase::Travel, last, 0.0,
                               lerp(from, *q, static_cast<double>(i) / steps), stroke - 1});
        }
        if (!q)
            q = spatial_configuration_at(task, design, j, 0.0,
                                         out.empty() ? nullptr : &out.back().q);
        if (!q) return fail(j, false, 0.0);
        out.push_back({0.0, Phase::Trace, k, 0.0, *q, stroke});
        const geometry::Primitive3& prim = task.trajectory[static_cast<std::size_t>(j)];
        const double length = geometry::length(prim);
        const bool ok = walk_to(length, trace_step_limit(prim, options.max_ee_step), Phase::Trace,
                                k, stroke, [&](double s, const std::vector<double>* prev) {
                                    return spatial_configuration_at(task, design, j, s, prev);
                                });
        if (!ok) return fail(j, false, failed_at);
        out.back().s = length;  // exactly, as the verifier checks the end
    }
    return out;
}

bool refine_spatial_motion(const task::SpatialTask& task, const kinematics::ArmDesign& design,
                           std::vector<Sample>& samples, const std::vector<int>& pairs) {
    std::vector<int> sorted = pairs;
    std::sort(sorted.rbegin(), sorted.rend());  // back to front keeps indices valid
    for (int i : sorted) {
        const Sample& a = samples[static_cast<std::size_t>(i)];
        const Sample& b = samples[static_cast<std::size_t>(i) + 1];
        std::optional<Sample> mid;
        if (a.phase == Phase::Travel || b.phase == Phase::Travel || a.stroke != b.stroke) {
            mid = Sample{a.t, Phase::Travel, a.primitive, 0.0, lerp(a.q, b.q, 0.5), a.stroke};
            if (a.phase != Phase::Travel) {  // the travel is tagged by the stroke it leaves
                mid->primitive =
                    task::stroke_last(task, a.stroke) - task::stroke_first(task, a.stroke);
            }
        } else if (a.phase == Phase::Trace && b.phase == Phase::Trace &&
                   a.primitive == b.primitive) {
            const double s = 0.5 * (a.s + b.s);
            if (auto q = spatial_configuration_at(task, design, primitive_index(task, a), s, &a.q))
                mid = Sample{a.t, Phase::Trace, a.primitive, s, *q, a.stroke};
        } else if (a.phase == Phase::Transition || b.phase == Phase::Transition) {
            // Trace end -> transition (t from 0), transition -> next trace
            // start (t to 1).
            const Sample& t = a.phase == Phase::Transition ? a : b;
            const double ta = a.phase == Phase::Transition ? a.s : 0.0;
            const double tb = b.phase == Phase::Transition ? b.s : 1.0;
            const double tm = 0.5 * (ta + tb);
            if (auto q = transition_configuration(task, design, primitive_index(task, t), tm, &a.q))
                mid = Sample{a.t, Phase::Transition, t.primitive, tm, *q, t.stroke};
        }
        if (!mid) return false;
        samples.insert(samples.begin() + i + 1, *mid);
    }
    return true;
}

}  // namespace modsynth::control
