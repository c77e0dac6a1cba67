#include <modsynth/verify/verifier.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include <modsynth/geometry/distance.h>
#include <modsynth/geometry/polygon.h>
#include <modsynth/kinematics/clearance_rule.h>
#include <modsynth/kinematics/kinematics.h>
#include <modsynth/kinematics/motion_clearance.h>
#include <modsynth/task/strokes.h>
#include <modsynth/text/format.h>
#include <modsynth/text/option_check.h>

#include "motion_checks.h"

namespace modsynth::verify {
namespace {

using control::Phase;
using control::Sample;
using geometry::Vec2;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kGeomEps = 1e-9;

// Largest distance from the chord of an arc of radius r to the arc, for a
// chord of length c (the shorter arc).
double sagitta(double r, double c) {
    if (r <= 0.0) return 0.0;
    const double h = 0.5 * c;
    return h >= r ? r : r - std::sqrt(r * r - h * h);
}

struct Pose {
    std::vector<Vec2> joints;  // s_1 .. s_{n+1}
    std::vector<double> phi;   // absolute link angles
    Vec2 target;               // where the EE should be
    double deviation = 0.0;
};

class Checker : CheckerBase<task::Task> {
public:
    Checker(const task::Task& task, const kinematics::Robot& robot,
            const std::vector<Sample>& samples, const VerifyOptions& options)
        : CheckerBase(task, samples, options), robot_(robot) {
        cert_.min_clearance = kInf;
        cert_.min_self_clearance = kInf;
    }

    Certificate run() {
        check_structure();
        if (!structure_ok_) return finish();
        check_order(true);
        poses_.reserve(samples_.size());
        for (std::size_t i = 0; i < samples_.size(); ++i)
            poses_.push_back(pose(static_cast<int>(i)));
        for (std::size_t i = 0; i < samples_.size(); ++i) check_sample(static_cast<int>(i));
        for (std::size_t i = 0; i + 1 < samples_.size(); ++i) check_pair(static_cast<int>(i));
        return finish();
    }

private:
    void check_structure() {
        const int n = robot_.dof();
        const auto& allowed = task_.robot.dof;
        if (std::find(allowed.begin(), allowed.end(), n) == allowed.end())
            violation(Violation::Kind::Structure, -1, 0.0,
                      "robot.dof " + std::to_string(n) + " is not allowed by the task");
        for (int k = 0; k < n; ++k) {
            const double r = robot_.link_lengths[k];
            if (!(r >= task_.robot.min_link_length - kGeomEps &&
                  r <= task_.robot.max_link_length + kGeomEps))
                violation(
                    Violation::Kind::Structure, -1, 0.0,
                    text::format("link %d length %.6f m is outside the allowed range", k + 1, r));
        }
        if (robot_.link_diameter < task_.robot.link_diameter)
            violation(Violation::Kind::Structure, -1, 0.0, "link diameter below the task's");
        if (!task_.base_regions.empty() &&
            std::none_of(
                task_.base_regions.begin(), task_.base_regions.end(),
                [&](const task::BaseRegion& r) { return r.contains(robot_.base, kGeomEps); }))
            violation(Violation::Kind::Structure, -1, 0.0,
                      text::format("base (%.6f, %.6f) lies in no base region", robot_.base.x(),
                                   robot_.base.y()));
        check_samples(n);
    }

    Pose pose(int i) const {
        const Sample& a = samples_[i];
        Pose p;
        p.joints = kinematics::forward(robot_.base, robot_.link_lengths, a.q);
        p.phi = kinematics::absolute_angles(a.q);
        const geometry::Primitive& prim = task_.trajectory[control::primitive_index(task_, a)];
        // In travel the EE is free: it is its own target.
        p.target = a.phase == Phase::Trace        ? geometry::point_at(prim, a.s)
                   : a.phase == Phase::Transition ? prim.end
                                                  : p.joints.back();
        p.deviation = (p.joints.back() - p.target).norm();
        return p;
    }

    void check_sample(int i) {
        const Pose& p = poses_[i];
        const int n = robot_.dof();
        const kinematics::ClearanceRule rule{robot_.link_diameter};
        cert_.max_deviation = std::max(cert_.max_deviation, p.deviation);
        if (p.deviation > opt_.deviation_tolerance)
            violation(Violation::Kind::Deviation, i, p.deviation - opt_.deviation_tolerance,
                      text::format("EE is %.6f m off the path", p.deviation));
        for (int k = 0; k < n; ++k) {
            for (std::size_t o = 0; o < task_.obstacles.size(); ++o) {
                const double margin =
                    rule.link_margin(task_.obstacles[o], p.joints[k], p.joints[k + 1]);
                if (margin < 0.0)
                    violation(Violation::Kind::Clearance, i, -margin,
                              text::format("link %d is %.6f m too close to obstacles[%zu]", k + 1,
                                           -margin, o),
                              static_cast<int>(o), k);
            }
            if (k < n - 1) {
                const double margin = rule.self_margin(p.joints[n], p.joints[k], p.joints[k + 1]);
                if (margin < 0.0)
                    violation(Violation::Kind::SelfCollision, i, -margin,
                              text::format("EE is %.6f m too close to link %d", -margin, k + 1), -1,
                              k);
            }
        }
    }

    void check_pair(int i) {
        const Sample& sa = samples_[i];
        const Sample& sb = samples_[i + 1];
        const Pose& a = poses_[i];
        const Pose& b = poses_[i + 1];
        const int n = robot_.dof();
        const kinematics::ClearanceRule rule{robot_.link_diameter};

        double step = 0.0;
        for (int k = 0; k < n; ++k) step = std::max(step, std::abs(sb.q[k] - sa.q[k]));
        cert_.max_joint_step = std::max(cert_.max_joint_step, step);
        if (step > opt_.max_joint_step + 1e-12) {
            violation(Violation::Kind::JointStep, i, step - opt_.max_joint_step,
                      text::format("a joint moves %.6f rad to the next sample", step));
            return;  // the bounds below assume small steps
        }
        // E_k: bound on |p''| for any point of link k (certified-verification.md).
        const std::vector<double> e = kinematics::sweep_bounds(robot_, a.phi, b.phi);
        const bool in_transition = sa.phase == Phase::Transition || sb.phase == Phase::Transition;
        // Between strokes (travel, or one stroke's end straight to the next
        // one's start) the EE is free and only clearance is checked.
        const bool free =
            sa.phase == Phase::Travel || sb.phase == Phase::Travel || sa.stroke != sb.stroke;
        const bool same_trace = sa.phase == Phase::Trace && sb.phase == Phase::Trace &&
                                sa.primitive == sb.primitive && sa.stroke == sb.stroke;
        // From a junction's sample, at the end of one primitive, to a
        // sample past the start of the next.
        const bool across = control::junction(sa, sb) && sb.s > 0.0;
        const bool refinable = (same_trace && sb.s - sa.s > 1e-7) || (across && sb.s > 1e-7) ||
                               (in_transition && std::abs(sb.q[0] - sa.q[0]) > 1e-7) ||
                               (free && step > 1e-7);
        bool coarse = false;
        auto settle = [&](double bound, bool samples_ok) {
            if (bound >= 0.0) return;
            if (samples_ok && refinable) {
                coarse = true;
            } else if (samples_ok) {
                violation(Violation::Kind::Clearance, i, -bound,
                          "motion between samples not certified");
            }
        };

        // Guarantee 1/2: the EE stays near the path between the samples.
        double sag = 0.0;
        if (same_trace || across) {
            const geometry::Primitive& prim = task_.trajectory[control::primitive_index(task_, sb)];
            // Across a junction the target chord runs from the end of sa's
            // primitive, within the join tolerance (added) of the start of
            // sb's, along sb's.
            const geometry::Vec2 from = same_trace ? a.target : prim.start;
            switch (prim.kind) {
                case geometry::PrimitiveKind::Line:
                    break;
                case geometry::PrimitiveKind::Arc:
                case geometry::PrimitiveKind::Circle:
                    sag = sagitta(prim.radius, (b.target - from).norm());
                    break;
            }
            if (across) sag += (a.target - prim.start).norm();
        }
        // Across a boundary both targets are the same transition point (up to
        // the task's join tolerance, which is added).
        if (!free) {
            const double gap = same_trace || across ? sag : (a.target - b.target).norm();
            const double dev = std::max(a.deviation, b.deviation) + e[n - 1] / 8.0 + gap;
            cert_.max_deviation = std::max(cert_.max_deviation, dev);
            settle(opt_.deviation_tolerance - dev,
                   std::max(a.deviation, b.deviation) <= opt_.deviation_tolerance);
        }

        for (int k = 0; k < n; ++k) {
            const std::vector<Vec2> hull =
                geometry::convex_hull({a.joints[k], a.joints[k + 1], b.joints[k], b.joints[k + 1]});
            for (const task::Obstacle& ob : task_.obstacles) {
                const double bound = geometry::point_convex_polygon(ob.center, hull) - e[k] / 8.0 -
                                     rule.obstacle_distance(ob);
                cert_.min_clearance = std::min(cert_.min_clearance, bound);
                const bool ok = rule.link_margin(ob, a.joints[k], a.joints[k + 1]) >= 0.0 &&
                                rule.link_margin(ob, b.joints[k], b.joints[k + 1]) >= 0.0;
                settle(bound, ok);
            }
            if (k < n - 1) {
                const double bound =
                    geometry::segment_convex_polygon(a.joints[n], b.joints[n], hull) -
                    (e[n - 1] + e[k]) / 8.0 - rule.self_distance();
                cert_.min_self_clearance = std::min(cert_.min_self_clearance, bound);
                const bool ok =
                    rule.self_margin(a.joints[n], a.joints[k], a.joints[k + 1]) >= 0.0 &&
                    rule.self_margin(b.joints[n], b.joints[k], b.joints[k + 1]) >= 0.0;
                settle(bound, ok);
            }
        }
        if (coarse) cert_.coarse_pairs.push_back(i);
    }

    const kinematics::Robot& robot_;
    std::vector<Pose> poses_;
};

}  // namespace

bool VerifyOptions::IsValid(std::string* error) const {
    return text::OptionCheck("VerifyOptions", error)
        .greater("deviation_tolerance", deviation_tolerance, 0.0)
        .greater("max_joint_step", max_joint_step, 0.0)
        .greater("max_ee_step", max_ee_step, 0.0)
        .ok();
}

VerifyOptions options_for(const control::MotionOptions& motion, const VerifyOptions& base) {
    VerifyOptions o = base;
    o.max_joint_step = motion.max_joint_step;
    o.max_ee_step = std::max(base.max_ee_step, motion.max_ee_step);
    return o;
}

Certificate certify(const task::Task& task, const kinematics::Robot& robot,
                    const std::vector<control::Sample>& samples, const VerifyOptions& options) {
    text::require_valid(options);
    return Checker(task, robot, samples, options).run();
}

}  // namespace modsynth::verify
