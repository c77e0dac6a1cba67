#include <modsynth/control/motion.h>

#include <algorithm>
#include <cassert>
#include <cmath>

#include <modsynth/control/travel.h>
#include <modsynth/geometry/primitive.h>
#include <modsynth/kinematics/chain_layout.h>
#include <modsynth/kinematics/kinematics.h>
#include <modsynth/task/strokes.h>
#include <modsynth/text/format.h>
#include <modsynth/text/option_check.h>

#include "sample_parameters.h"
#include "walk.h"

namespace modsynth::control {
namespace {

// q for the distal pair from `origin` reaching p, after a proximal angle q1
// (three joints) or alone (two joints), unwrapped next to `previous`.
std::optional<std::vector<double>> arm_configuration(const kinematics::Robot& robot,
                                                     const geometry::Vec2& origin, double q1,
                                                     const geometry::Vec2& p,
                                                     const std::vector<double>* previous) {
    const int n = robot.dof();
    const auto ik = kinematics::inverse_two_link(origin, robot.link_lengths[n - 2],
                                                 robot.link_lengths[n - 1], p, robot.elbow);
    if (!ik) return std::nullopt;
    std::vector<double> q = n == 2 ? std::vector<double>{ik->phi1, ik->q2}
                                   : std::vector<double>{q1, ik->phi1 - q1, ik->q2};
    if (previous) {
        for (std::size_t k = 0; k < q.size(); ++k)
            q[k] = kinematics::unwrap_near(q[k], (*previous)[k]);
    }
    return q;
}

std::string transition_name(const task::Task& task, int j) {
    return "the transition after " + task::part_name(task, j);
}

std::string travel_name(const task::Task& task, int j) {
    return "the travel after " + task::part_name(task, j);
}

std::string point_name(const task::Task& task, int j, double s) {
    return task::part_name(task, j) + text::format(" at %.4f m from its start", s);
}

}  // namespace

bool MotionOptions::IsValid(std::string* error) const {
    return text::OptionCheck("MotionOptions", error)
        .greater("max_joint_step", max_joint_step, 0.0)
        .greater("max_ee_step", max_ee_step, 0.0)
        .greater("junction_step", junction_step, 0.0)
        .greater("ee_speed", ee_speed, 0.0)
        .greater("joint_speed", joint_speed, 0.0)
        .holds("max_samples", max_samples >= 2, "must be at least 2")
        .at_least("step_attempts", step_attempts, 1)
        .greater("ticks_per_second", ticks_per_second, 0.0)
        .ok();
}

std::optional<std::vector<double>> configuration_at(const task::Task& task,
                                                    const kinematics::Robot& robot, int j, double s,
                                                    const std::vector<double>* previous) {
    const geometry::Vec2 p = geometry::point_at(task.trajectory[j], s);
    if (!robot.has_proximal_link()) return arm_configuration(robot, robot.base, 0.0, p, previous);
    if (static_cast<int>(robot.proximal_angles.size()) <= j) return std::nullopt;
    const double q1 = robot.proximal_angles[j];
    return arm_configuration(robot, robot.tracing_origin(j), q1, p, previous);
}

std::optional<std::vector<double>> transition_configuration(const task::Task& task,
                                                            const kinematics::Robot& robot, int j,
                                                            double q1,
                                                            const std::vector<double>* previous) {
    if (!robot.has_proximal_link()) return std::nullopt;
    return arm_configuration(robot, robot.distal_origin(q1), q1, task.trajectory[j].end, previous);
}

std::optional<std::vector<Sample>> plan_motion(const task::Task& task,
                                               const kinematics::Robot& robot,
                                               const MotionOptions& options,
                                               MotionFailure* failure) {
    text::require_valid(options);
    std::vector<Sample> out;
    double failed_at = 0.0;
    bool gave_up = false;
    const WalkLimits limits{options.max_samples, options.deadline, options.step_attempts};
    // A step fits when no joint moves more than max_joint_step.
    const auto shrink = [&](const std::vector<double>& last,
                            const std::vector<double>& next) -> std::optional<double> {
        const double change = largest_change(last, next);
        if (change <= options.max_joint_step) return std::nullopt;
        return std::max(0.1, 0.9 * options.max_joint_step / change);
    };
    // Walks as control/walk.h does; on a stop, failed_at and gave_up say
    // where and why.
    const auto walk_to = [&](double from, double to, double first_step, double max_step,
                             Phase phase, int k, int stroke, auto config_at) {
        const auto stop =
            walk(from, to, first_step, max_step, limits, phase, k, stroke, out, config_at, shrink);
        if (stop) failed_at = stop->at, gave_up = stop->gave_up;
        return !stop;
    };
    auto fail = [&](int j, bool transition, double s,
                    bool travel = false) -> std::optional<std::vector<Sample>> {
        if (failure) {
            *failure = {j,
                        transition,
                        travel,
                        s,
                        gave_up,
                        transition ? transition_name(task, j)
                        : travel   ? travel_name(task, j)
                                   : point_name(task, j, s)};
            if (gave_up) {
                failure->message =
                    out.size() >= options.max_samples
                        ? text::format("%zu samples, the most a motion may have", out.size())
                        : std::string("the time limit");
            }
        }
        return std::nullopt;
    };
    TravelOptions travel_options;
    travel_options.max_joint_step = options.max_joint_step;
    travel_options.deadline = options.deadline;
    const int m = static_cast<int>(task.trajectory.size());
    for (int j = 0; j < m; ++j) {
        const int stroke = task::stroke_of(task, j);
        const int k = task::index_in_stroke(task, j);
        std::optional<std::vector<double>> q;
        // Primitive j follows j - 1 in its stroke with no transition
        // between: the last sample of j - 1 stands at the junction.
        bool junction = j > 0 && k > 0 && !robot.has_proximal_link();
        if (j > 0 && k > 0 && robot.has_proximal_link()) {
            // The EE holds the transition point while the first joint sweeps
            // the short way round to its angle for the next primitive.
            const double from = out.back().q[0];
            const double to =
                from + std::remainder(robot.proximal_angles[j] - from, geometry::kTau);
            const std::size_t before = out.size();
            const bool ok =
                walk_to(from, to, options.max_joint_step, options.max_joint_step, Phase::Transition,
                        k - 1, stroke, [&](double q1, const std::vector<double>* prev) {
                            return transition_configuration(task, robot, j - 1, q1, prev);
                        });
            if (!ok) return fail(j - 1, true, failed_at);
            if (out.size() > before) {
                out.pop_back();  // the last pose is the next trace's first
            } else {
                junction = true;
            }
        } else if (j > 0 && k == 0) {
            // A new stroke: travel, pen up, to the pose that starts it.
            const auto start = configuration_at(task, robot, j, 0.0, &out.back().q);
            if (!start) return fail(j, false, 0.0);
            const auto plan = plan_travel(task, robot, out.back().q, *start, travel_options);
            if (!plan) {
                gave_up = options.deadline.expired();
                return fail(j - 1, false, 0.0, true);
            }
            const int last = task::index_in_stroke(task, j - 1);
            for (std::size_t i = 0; i + 1 < plan->poses.size(); ++i)
                out.push_back({0.0, Phase::Travel, last, 0.0, plan->poses[i], stroke - 1});
            q = plan->poses.back();
        }
        const double length = geometry::length(task.trajectory[j]);
        const double max_step = trace_step_limit(task.trajectory[j], options.max_ee_step);
        // At a junction the sample there ends primitive j - 1, and the
        // trace of j begins a short step past it (its start is the same
        // pose): a repeated pose would be a step that does not move, where
        // any timing must stop.
        double first_step = max_step;
        if (junction) {
            first_step = std::min(options.junction_step, 0.5 * length);
        } else {
            if (!q) {
                const std::vector<double>* prev = out.empty() ? nullptr : &out.back().q;
                q = configuration_at(task, robot, j, 0.0, prev);
            }
            if (!q) return fail(j, false, 0.0);
            out.push_back({0.0, Phase::Trace, k, 0.0, *q, stroke});
        }
        const bool ok = walk_to(0.0, length, first_step, max_step, Phase::Trace, k, stroke,
                                [&](double s, const std::vector<double>* p) {
                                    return configuration_at(task, robot, j, s, p);
                                });
        if (!ok) return fail(j, false, failed_at);
    }
    return out;
}

bool refine_motion(const task::Task& task, const kinematics::Robot& robot,
                   std::vector<Sample>& samples, const std::vector<int>& pairs) {
    std::vector<int> sorted = pairs;
    std::sort(sorted.rbegin(), sorted.rend());  // back to front keeps indices valid
    for (int i : sorted) {
        const Sample& a = samples[i];
        const Sample& b = samples[i + 1];
        std::optional<Sample> mid;
        if (a.phase == Phase::Travel || b.phase == Phase::Travel || a.stroke != b.stroke) {
            // Between strokes the arm moves linearly in joint space: the
            // midpoint is on the motion already, and halves the pair.
            std::vector<double> q(a.q.size());
            for (std::size_t k = 0; k < q.size(); ++k) q[k] = 0.5 * (a.q[k] + b.q[k]);
            mid = Sample{a.t, Phase::Travel, a.primitive, 0.0, std::move(q), a.stroke};
        } else if (a.phase == Phase::Trace && b.phase == Phase::Trace &&
                   a.primitive == b.primitive) {
            const double s = 0.5 * (a.s + b.s);
            if (auto q = configuration_at(task, robot, primitive_index(task, a), s, &a.q))
                mid = Sample{a.t, Phase::Trace, a.primitive, s, *q, a.stroke};
        } else if (a.phase == Phase::Trace && b.phase == Phase::Trace &&
                   b.primitive == a.primitive + 1 && b.s > 0.0) {
            // Across a junction: a stands where b's primitive starts.
            const double s = 0.5 * b.s;
            if (auto q = configuration_at(task, robot, primitive_index(task, b), s, &a.q))
                mid = Sample{a.t, Phase::Trace, b.primitive, s, *q, b.stroke};
        } else if (robot.has_proximal_link() &&
                   (a.phase == Phase::Transition || b.phase == Phase::Transition)) {
            const Sample& t = a.phase == Phase::Transition ? a : b;
            const double q1 = 0.5 * (a.q[0] + b.q[0]);
            if (auto q = transition_configuration(task, robot, primitive_index(task, t), q1, &a.q))
                mid = Sample{a.t, Phase::Transition, t.primitive, q1, *q, t.stroke};
        }
        if (!mid) return false;
        samples.insert(samples.begin() + i + 1, *mid);
    }
    return true;
}

void recover_parameters(const task::Task& task, const kinematics::Robot& robot,
                        std::vector<Sample>& samples) {
    recover_parameters_with(
        task, samples, [&](std::size_t i, const geometry::Primitive& prim, bool first) {
            const double length = geometry::length(prim);
            const geometry::Vec2 ee =
                kinematics::forward(robot.base, robot.link_lengths, samples[i].q).back();
            double s = geometry::nearest(prim, ee).s;
            switch (prim.kind) {
                case geometry::PrimitiveKind::Line:
                case geometry::PrimitiveKind::Arc:
                    break;
                case geometry::PrimitiveKind::Circle:
                    // A circle's start is also its end: a run begins at 0, and
                    // goes on from the sample before, not back to the start.
                    if (first && s > length - 1e-5) s = 0.0;
                    if (!first) {
                        double d = s - samples[i - 1].s;
                        d -= length * std::round(d / length);
                        s = samples[i - 1].s + d;
                    }
                    break;
            }
            return s;
        });
}

void assign_times(std::vector<Sample>& samples, const MotionOptions& options) {
    text::require_valid(options);
    if (samples.empty()) return;
    samples[0].t = 0.0;
    for (std::size_t i = 1; i < samples.size(); ++i) {
        const Sample& a = samples[i - 1];
        Sample& b = samples[i];
        const double path = (a.phase == Phase::Trace && b.phase == Phase::Trace &&
                             a.primitive == b.primitive && a.stroke == b.stroke)
                                ? std::abs(b.s - a.s)
                                : 0.0;
        const double dt =
            std::max(path / options.ee_speed, largest_change(a.q, b.q) / options.joint_speed);
        b.t = std::round((a.t + dt) * options.ticks_per_second) / options.ticks_per_second;
    }
}

}  // namespace modsynth::control
