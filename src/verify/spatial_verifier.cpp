#include <modsynth/verify/spatial_verifier.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <modsynth/control/spatial_samples.h>
#include <modsynth/geometry/distance3.h>
#include <modsynth/geometry/obstacle3.h>
#include <modsynth/kinematics/dh_motion_bound.h>
#include <modsynth/task/spatial_strokes.h>
#include <modsynth/text/format.h>
#include <modsynth/text/option_check.h>

#include "motion_checks.h"

namespace modsynth::verify {
namespace {

using control::Phase;
using control::Sample;
using geometry::Vec3;
using kinematics::Segment3;
constexpr double kInf = std::numeric_limits<double>::infinity();
/// Slack on the structure's lengths and the base region (m), as in the plane.
constexpr double kGeomEps = 1e-9;
/// formats.md: a chain's alpha equals one of robot.twists within this.
constexpr double kTwistTolerance = 1e-9;

struct Pose {
    std::vector<Eigen::Isometry3d> frames;
    std::vector<Segment3> segments;
    Vec3 ee = Vec3::Zero();
    Vec3 target = Vec3::Zero();  ///< where the EE should be
    double deviation = 0.0;
};

Vec3 lerp(const Vec3& a, const Vec3& b, double t) { return a + t * (b - a); }

class Checker : CheckerBase<task::SpatialTask> {
public:
    Checker(const task::SpatialTask& task, const kinematics::DhChain& chain,
            const std::vector<Sample>& samples, const VerifyOptions& options)
        : CheckerBase(task, samples, options),
          chain_(chain),
          layout_(kinematics::segment_layout(chain)),
          parts_(kinematics::clearance_parts(layout_, task.robot.tool_length,
                                             chain.link_diameter / 2.0)) {
        cert_.min_clearance = kInf;
        cert_.min_self_clearance = kInf;
        for (const auto& o : task.obstacles) cores_.push_back(geometry::core_of(o));
    }

    Certificate run() {
        check_structure();
        if (!structure_ok_) return finish();
        check_order(false);
        poses_.reserve(samples_.size());
        for (std::size_t i = 0; i < samples_.size(); ++i)
            poses_.push_back(pose(static_cast<int>(i)));
        for (std::size_t i = 0; i < samples_.size(); ++i) check_sample(static_cast<int>(i));
        for (std::size_t i = 0; i + 1 < samples_.size(); ++i) check_pair(static_cast<int>(i));
        check_fallback();
        return finish();
    }

private:
    int segments() const { return static_cast<int>(layout_.size()); }
    double diameter() const { return chain_.link_diameter; }
    /// 1-based link of segment k: the frame it is fixed in.
    int link_of(int k) const { return layout_[static_cast<std::size_t>(k)].link + 1; }
    /// The last joint that moves segment k: a d part lies on its own joint's axis.
    int last_joint_of(int k) const {
        return layout_[static_cast<std::size_t>(k)].along_axis ? link_of(k) - 1 : link_of(k);
    }

    // Guarantee 5 and what the replay needs.
    void check_structure() {
        const auto& spec = task_.robot;
        const int n = chain_.dof();
        if (std::find(spec.dof.begin(), spec.dof.end(), n) == spec.dof.end())
            structure("robot.dof " + std::to_string(n) + " is not allowed by the task");
        for (int k = 0; k < n; ++k) {
            const kinematics::DhRow& r = chain_.rows[static_cast<std::size_t>(k)];
            if (r.a < 0.0) structure(text::format("link %d: a = %.6f m is negative", k + 1, r.a));
            const std::pair<const char*, double> lengths[] = {{"a", r.a}, {"|d|", std::abs(r.d)}};
            for (const auto& [name, v] : lengths) {
                if (!(std::abs(v) > kinematics::kZeroSegment)) continue;
                if (!(v >= spec.min_link_length - kGeomEps && v <= spec.max_link_length + kGeomEps))
                    structure(text::format("link %d: %s = %.6f m is outside the allowed range",
                                           k + 1, name, v));
            }
            if (std::none_of(spec.twists.begin(), spec.twists.end(),
                             [&](double t) { return std::abs(r.alpha - t) <= kTwistTolerance; }))
                structure(text::format("link %d: alpha = %.9f is not one of robot.twists", k + 1,
                                       r.alpha));
        }
        if (!(chain_.link_diameter >= spec.link_diameter))
            structure("link diameter below the task's");
        if (!task_.base_regions.empty() &&
            std::none_of(
                task_.base_regions.begin(), task_.base_regions.end(),
                [&](const geometry::Box3& b) { return b.contains(chain_.base, kGeomEps); }))
            structure(text::format("base (%.6f, %.6f, %.6f) lies in no base region",
                                   chain_.base.x(), chain_.base.y(), chain_.base.z()));
        const double last = layout_.empty() ? 0.0 : layout_.back().length;
        if (spec.tool_length > last + kGeomEps)
            structure(
                text::format("robot.tool_length %.6f m is longer than the chain's last "
                             "segment (%.6f m)",
                             spec.tool_length, last));
        check_samples(n);
    }

    Pose pose(int i) const {
        const Sample& a = samples_[i];
        Pose p;
        p.frames = kinematics::frames(chain_, a.q);
        p.segments = kinematics::chain_segments(chain_, p.frames);
        p.ee = p.frames.back().translation();
        const geometry::Primitive3& prim = task_.trajectory[control::primitive_index(task_, a)];
        // In travel the EE is free: it is its own target.
        p.target = a.phase == Phase::Trace        ? geometry::point_at(prim, a.s)
                   : a.phase == Phase::Transition ? geometry::end_point(prim)
                                                  : p.ee;
        p.deviation = (p.ee - p.target).norm();
        return p;
    }

    /// Ends of clearance part `k` at a pose.
    std::pair<Vec3, Vec3> part_ends(const Pose& p, const kinematics::SegmentPart& part) const {
        const Segment3& s = p.segments[static_cast<std::size_t>(part.segment)];
        return {lerp(s.start, s.end, part.from), lerp(s.start, s.end, part.to)};
    }

    double part_margin(const Pose& p, const kinematics::SegmentPart& part, int o) const {
        const auto [a, b] = part_ends(p, part);
        return geometry::segment_gap(a, b, task_.obstacles[static_cast<std::size_t>(o)]) -
               diameter() / 2.0;
    }

    double pair_margin(const Pose& p, int k, int l) const {
        const Segment3& s = p.segments[static_cast<std::size_t>(k)];
        const Segment3& t = p.segments[static_cast<std::size_t>(l)];
        return geometry::segment_segment(s.start, s.end, t.start, t.end) - diameter();
    }

    double ee_margin(const Pose& p, int k) const {
        const Segment3& s = p.segments[static_cast<std::size_t>(k)];
        return geometry::point_segment(p.ee, s.start, s.end) - diameter();
    }

    void check_sample(int i) {
        const Pose& p = poses_[static_cast<std::size_t>(i)];
        cert_.max_deviation = std::max(cert_.max_deviation, p.deviation);
        if (p.deviation > opt_.deviation_tolerance)
            violation(Violation::Kind::Deviation, i, p.deviation - opt_.deviation_tolerance,
                      text::format("EE is %.6f m off the path", p.deviation));
        for (const auto& part : parts_) {
            const int link = layout_[static_cast<std::size_t>(part.segment)].link;
            for (int o = 0; o < static_cast<int>(task_.obstacles.size()); ++o) {
                const double margin = part_margin(p, part, o);
                if (margin < 0.0)
                    violation(
                        Violation::Kind::Clearance, i, -margin,
                        text::format("link %d is %.6f m too close to obstacles[%d] (%s)", link + 1,
                                     -margin, o, geometry::type_name(task_.obstacles[o])),
                        o, link);
            }
        }
        for (int k = 0; k < segments(); ++k) {
            for (int l = k + 2; l < segments(); ++l) {
                const double margin = pair_margin(p, k, l);
                if (margin < 0.0)
                    violation(Violation::Kind::SelfCollision, i, -margin,
                              text::format("links %d and %d are %.6f m apart", link_of(k),
                                           link_of(l), margin + diameter()),
                              -1, link_of(k) - 1);
            }
            if (k + 1 < segments()) {
                const double margin = ee_margin(p, k);
                if (margin < 0.0)
                    violation(
                        Violation::Kind::SelfCollision, i, -margin,
                        text::format("EE is %.6f m from link %d", margin + diameter(), link_of(k)),
                        -1, link_of(k) - 1);
            }
        }
    }

    /// Points given in the world at a pose, in the coordinates of its frame k.
    static Vec3 local(const Pose& p, int k, const Vec3& x) {
        return p.frames[static_cast<std::size_t>(k)].inverse() * x;
    }

    void check_pair(int i) {
        const Sample& sa = samples_[static_cast<std::size_t>(i)];
        const Sample& sb = samples_[static_cast<std::size_t>(i) + 1];
        const Pose& a = poses_[static_cast<std::size_t>(i)];
        const Pose& b = poses_[static_cast<std::size_t>(i) + 1];
        const int n = chain_.dof();

        std::vector<double> dq(static_cast<std::size_t>(n));
        double step = 0.0;
        for (int k = 0; k < n; ++k) {
            dq[static_cast<std::size_t>(k)] = sb.q[k] - sa.q[k];
            step = std::max(step, std::abs(dq[static_cast<std::size_t>(k)]));
        }
        cert_.max_joint_step = std::max(cert_.max_joint_step, step);
        if (step > opt_.max_joint_step + 1e-12) {
            violation(Violation::Kind::JointStep, i, step - opt_.max_joint_step,
                      text::format("a joint moves %.6f rad to the next sample", step));
            return;  // the bounds below are meant for small steps
        }
        const bool in_transition = sa.phase == Phase::Transition || sb.phase == Phase::Transition;
        // Between strokes (travel, or one stroke's end straight to the next
        // one's start) the EE is free and only rules 3 and 4 apply.
        const bool free =
            sa.phase == Phase::Travel || sb.phase == Phase::Travel || sa.stroke != sb.stroke;
        const bool same_trace = sa.phase == Phase::Trace && sb.phase == Phase::Trace &&
                                sa.primitive == sb.primitive && sa.stroke == sb.stroke;
        const bool refinable =
            (same_trace && sb.s - sa.s > 1e-7) || ((in_transition || free) && step > 1e-7);
        bool coarse = false;
        auto settle = [&](double bound, auto samples_ok) {
            if (bound >= 0.0) return;
            if (!samples_ok()) return;  // the sample's own violation reports it
            if (refinable) {
                coarse = true;
            } else {
                violation(Violation::Kind::Clearance, i, -bound,
                          "motion between samples not certified");
            }
        };
        const double total = chain_.total_length();

        // Guarantees 1 and 2: the EE stays near the path between the samples.
        if (!free) {
            double gap = (a.target - b.target).norm();
            if (same_trace) {
                // The path between the two targets is within k ds^2 / 8 of
                // their chord (k its largest curvature, ds its length).
                const geometry::Primitive3& prim =
                    task_.trajectory[control::primitive_index(task_, sa)];
                const double ds = sb.s - sa.s;
                gap = geometry::max_curvature(prim) * ds * ds / 8.0;
            }
            const double worst = std::max(a.deviation, b.deviation);
            const double dev = worst + kinematics::chord_gap(chain_, dq, 0, n, total) + gap;
            cert_.max_deviation = std::max(cert_.max_deviation, dev);
            settle(opt_.deviation_tolerance - dev,
                   [&] { return worst <= opt_.deviation_tolerance; });
        }

        // Guarantee 3: every clearance part against every obstacle, in the
        // world, through the hull of the part's ends at both samples.
        for (const auto& part : parts_) {
            const auto [a0, a1] = part_ends(a, part);
            const auto [b0, b1] = part_ends(b, part);
            const std::array<Vec3, 4> hull{a0, a1, b0, b1};
            const auto& l = layout_[static_cast<std::size_t>(part.segment)];
            const double reach = l.chain_start + part.to * l.length;
            const double g =
                kinematics::chord_gap(chain_, dq, 0, last_joint_of(part.segment), reach);
            for (int o = 0; o < static_cast<int>(cores_.size()); ++o) {
                const auto& core = cores_[static_cast<std::size_t>(o)];
                const double bound =
                    geometry::hull_distance(hull, core.span()) - g - core.radius - diameter() / 2.0;
                cert_.min_clearance = std::min(cert_.min_clearance, bound);
                settle(bound, [&] {
                    return part_margin(a, part, o) >= 0.0 && part_margin(b, part, o) >= 0.0;
                });
            }
        }

        // Guarantee 4: seen from the frame segment k is fixed in, the other
        // segment (or the EE) moves by the joints after k's link only.
        for (int k = 0; k < segments(); ++k) {
            const int frame = link_of(k);
            const Segment3& sk = a.segments[static_cast<std::size_t>(k)];
            const std::array<Vec3, 2> fixed{local(a, frame, sk.start), local(a, frame, sk.end)};
            for (int l = k + 2; l < segments(); ++l) {
                const Segment3& la = a.segments[static_cast<std::size_t>(l)];
                const Segment3& lb = b.segments[static_cast<std::size_t>(l)];
                const std::array<Vec3, 4> moving{local(a, frame, la.start), local(a, frame, la.end),
                                                 local(b, frame, lb.start),
                                                 local(b, frame, lb.end)};
                const auto& ll = layout_[static_cast<std::size_t>(l)];
                const double g = kinematics::chord_gap(chain_, dq, frame, last_joint_of(l),
                                                       ll.chain_start + ll.length);
                const double bound = geometry::hull_distance(fixed, moving) - g - diameter();
                cert_.min_self_clearance = std::min(cert_.min_self_clearance, bound);
                settle(bound,
                       [&] { return pair_margin(a, k, l) >= 0.0 && pair_margin(b, k, l) >= 0.0; });
            }
            if (k + 1 < segments()) {
                const std::array<Vec3, 2> chord{local(a, frame, a.ee), local(b, frame, b.ee)};
                const double g = kinematics::chord_gap(chain_, dq, frame, n, total);
                const double bound = geometry::hull_distance(fixed, chord) - g - diameter();
                cert_.min_self_clearance = std::min(cert_.min_self_clearance, bound);
                settle(bound, [&] { return ee_margin(a, k) >= 0.0 && ee_margin(b, k) >= 0.0; });
            }
        }
        if (coarse) cert_.coarse_pairs.push_back(i);
    }

    // Guarantee 1's "never jumps ahead" as a reader measures progress: by the
    // EE's own nearest point on the path. The targets advance monotonically
    // and the EE stays within max_deviation of them, so its nearest point
    // (within twice that of the target's, on a curve) can fall back behind
    // the farthest one reached so far by at most four times the deviation:
    // that must stay within the tolerance too.
    void check_fallback() {
        const double back = 4.0 * cert_.max_deviation;
        if (back > opt_.deviation_tolerance)
            violation(Violation::Kind::Deviation, -1, back - opt_.deviation_tolerance,
                      text::format("the EE may fall back along the path by up to %.6f m "
                                   "(four times its deviation)",
                                   back));
    }

    const kinematics::DhChain& chain_;
    std::vector<kinematics::SegmentLayout> layout_;
    std::vector<kinematics::SegmentPart> parts_;
    std::vector<geometry::ObstacleCore> cores_;
    std::vector<Pose> poses_;
};

}  // namespace

Certificate certify(const task::SpatialTask& task, const kinematics::DhChain& chain,
                    const std::vector<control::Sample>& samples, const VerifyOptions& options) {
    text::require_valid(options);
    return Checker(task, chain, samples, options).run();
}

}  // namespace modsynth::verify
