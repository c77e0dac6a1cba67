// A wrist on a yaw-pitch arm: rows (0, s pi/2, d_1), (a_2, 0, 0),
// (a_3, 0, 0), (0, s pi/2, 0), (a_5, 0, 0). Joint 4 pitches the wrist in
// the arm's plane like a hand link, and its twist turns joint 5's axis into
// that plane, so that joint 5 swings the tool link out of it: the tool can
// point along any direction u but the plane's normal (the wrist's fold).
// The closed form: the wrist point W = p - a_5 u lies in the arm's plane
// (joint 4 sits on it), the yaw-pitch IK places links 2 and 3 for W, and the
// wrist's two angles are u's pitch in that plane and its tilt out of it.
//
// Values: [d_1 when the column is up or hanging], a_2, a_3, a_5. Variants
// as the yaw-pitch arm's (bit 2: both twists -pi/2; bits 0-1 the column).
// Free numbers per primitive end: u's azimuth and elevation; where the
// task gives the primitive a tool_axis, u is its wanted direction.
#include <algorithm>
#include <cmath>
#include <limits>

#include <modsynth/arms/family.h>
#include <modsynth/geometry/vec.h>
#include <modsynth/kinematics/yaw_pitch_ik.h>
#include <modsynth/kinematics/yaw_pitch_pose.h>
#include <modsynth/text/format.h>

#include "../yaw_pitch/yaw_pitch_parts.h"

namespace modsynth::arms {
namespace {

using geometry::Vec3;
using kinematics::AD;
using kinematics::ArmDesign;
using kinematics::ArmPose;
using kinematics::ArmShape;
using kinematics::Point3;
using kinematics::PoseMargins;
using kinematics::PoseTarget;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kDof = 5;
/// (u . n)^2 at most this, n the arm plane's normal: the tool 16 degrees
/// from the wrist's fold at least, where joint 4's angle is undefined.
constexpr double kFoldSin2 = 0.92;
/// The yaw-pitch chain a wrist sits on: a column and links 2, 3, 4 (its
/// fourth link is the tool link a_5, in the same slot of the values).
constexpr int kCarrierDof = 4;

using yaw_pitch::allows;
using yaw_pitch::has_column;
using yaw_pitch::kBranches;
using yaw_pitch::twist_of;

/// The tool's unit direction: the target's when it wants one, else the
/// free numbers' (azimuth, elevation).
template <class T>
Point3<T> tool_of(const PoseTarget<T>& target, const std::vector<T>& along) {
    using std::cos;
    using std::sin;
    if (target.tool_axis) return *target.tool_axis;
    const T ce = cos(along[1]);
    return Point3<T>(ce * cos(along[0]), ce * sin(along[0]), sin(along[1]));
}

/// The yaw-pitch arm under the wrist: the column and links 2 and 3.
template <class T>
kinematics::YawPitchShape<T> carrier(const ArmShape<T>& s) {
    return yaw_pitch::shape_of(s, 2);
}

template <class T>
const T& tool_link(const ArmShape<T>& s) {
    return s.values.back();
}

kinematics::YawPitchArm carrier_arm(const ArmShape<double>& s) { return yaw_pitch::arm_of(s, 2); }

template <class T>
ArmPose<T> pose_of(const ArmShape<T>& shape, const PoseTarget<T>& target, int branch,
                   const std::vector<T>& along, const PoseMargins& m) {
    const Point3<T> u = tool_of(target, along);
    const Point3<T> wrist = target.point - u * tool_link(shape);
    const auto y = carrier(shape);
    const auto p =
        kinematics::yaw_pitch_pose(y, wrist, kBranches[static_cast<std::size_t>(branch)], {});
    ArmPose<T> out;
    const bool column = has_column(shape.variant);
    out.points.assign(p.points.begin() + (column ? 0 : 1), p.points.end());
    out.points.push_back(target.point);
    for (int link : {1, 2, 3, 5})
        if (column || link != 1) out.links.push_back(link);
    out.joints.assign(p.points.begin(), p.points.end());
    out.joints.push_back(p.points.back());  // o_4 = o_3: joints 4 and 5 cross there
    const double shorter =
        std::min(kinematics::value_of(y.links[0]), kinematics::value_of(y.links[1]));
    out.limits.push_back(
        {p.elbow_cos, -m.elbow_cos, m.elbow_cos, shorter, "elbow from its fold and stretch"});
    out.limits.push_back({p.axis_distance, m.axis, kInf, 1.0, "wrist off the column's axis"});
    const Point3<T> v = wrist - (y.base + Point3<T>(T(0.0), T(0.0), y.column));
    const T out_of_plane = (u.y() * v.x() - u.x() * v.y()) / p.axis_distance;
    out.limits.push_back({T(out_of_plane * out_of_plane), -1.0, kFoldSin2,
                          kinematics::value_of(tool_link(shape)), "wrist from its fold"});
    return out;
}

class WristFamily final : public Family {
public:
    std::string_view name() const override { return "wrist"; }
    int along_count(int, int) const override { return 2; }
    int branch_count(int) const override { return 4; }

    kinematics::DhChain chain(const ArmDesign& d) const override {
        auto c = kinematics::to_chain(carrier_arm(d.shape), d.link_diameter);
        const double alpha = twist_of(d.shape.variant) * geometry::kPi / 2.0;
        c.rows.push_back({0.0, alpha, 0.0});
        c.rows.push_back({tool_link(d.shape), 0.0, 0.0});
        return c;
    }

    ArmPose<double> pose(const ArmShape<double>& shape, const PoseTarget<double>& target,
                         int branch, const std::vector<double>& along,
                         const PoseMargins& margins) const override {
        return pose_of(shape, target, branch, along, margins);
    }
    ArmPose<AD> pose(const ArmShape<AD>& shape, const PoseTarget<AD>& target, int branch,
                     const std::vector<AD>& along, const PoseMargins& margins) const override {
        return pose_of(shape, target, branch, along, margins);
    }

    std::optional<std::vector<double>> joint_angles(
        const ArmDesign& d, const PoseTarget<double>& target, int branch,
        const std::vector<double>& along) const override {
        const Vec3 u = tool_of(target, along).normalized();
        const auto arm = carrier_arm(d.shape);
        const Vec3 wrist = target.point - tool_link(d.shape) * u;
        auto q =
            kinematics::yaw_pitch_ik(arm, wrist, kBranches[static_cast<std::size_t>(branch)], {});
        if (!q) return std::nullopt;
        const auto frames = kinematics::frames(kinematics::to_chain(arm, d.link_diameter), *q);
        const auto& r = frames.back().linear();
        const Vec3 x3 = r.col(0), z3 = r.col(2);
        // Joint 4 turns x_3 to x' in the plane, joint 5 tilts the tool out
        // of it: u = cos(q5) x' + s sin(q5) z_3.
        const Vec3 in_plane = u - u.dot(z3) * z3;
        const double c5 = in_plane.norm();
        if (!(c5 > 1e-6)) return std::nullopt;
        const Vec3 x4 = in_plane / c5;
        q->push_back(std::atan2(x3.cross(x4).dot(z3), x3.dot(x4)));
        q->push_back(std::atan2(twist_of(d.shape.variant) * u.dot(z3), c5));
        return q;
    }

    std::vector<int> variants(int dof, const task::SpatialRobotSpec& spec) const override {
        if (dof != kDof || !allows(spec.twists, 0.0)) return {};
        for (int twist : {1, -1})
            if (allows(spec.twists, twist * geometry::kPi / 2)) {
                const int bit = twist > 0 ? 0 : 4;
                return {bit | 0, bit | 1, bit | 2};
            }
        return {};
    }
    std::string_view needs() const override {
        return "a wrist on a yaw column needs 5 joints and twists 0 and +-pi/2";
    }
    std::string describe_variant(int variant) const override {
        return yaw_pitch_family().describe_variant(variant) + ", wrist";
    }
    std::string describe(const ArmDesign& d) const override {
        const auto arm = carrier_arm(d.shape);
        const double a5 = tool_link(d.shape);
        return text::format(
            "base (%.3f, %.3f, %.3f), d1 %.4f, links %.4f + %.4f m, wrist, tool link %.4f m "
            "(chain %.4f m)",
            arm.base.x(), arm.base.y(), arm.base.z(), arm.column, arm.links[0], arm.links[1], a5,
            std::abs(arm.column) + arm.links[0] + arm.links[1] + a5);
    }

    std::vector<Bound> value_bounds(const task::SpatialRobotSpec& spec, int,
                                    int variant) const override {
        return yaw_pitch_family().value_bounds(spec, kCarrierDof, variant);
    }
    Bound along_bound(int) const override { return {-4.0 * geometry::kPi, 4.0 * geometry::kPi}; }
    std::vector<double> length_weights(int, int variant) const override {
        return yaw_pitch_family().length_weights(kCarrierDof, variant);
    }
    std::vector<kinematics::DesignRow> design_rows(const task::SpatialTask&, int,
                                                   int) const override {
        return {};
    }
    Vec3 reach_centre(const ArmDesign& d) const override { return carrier_arm(d.shape).shoulder(); }

    // The wrist point lies within a_5 of the EE: the yaw-pitch arm's reach
    // with the tool link as its hand.
    smt::Pattern pattern(const PatternContext& c) const override {
        return yaw_pitch_reach(
            {c.task, kCarrierDof, c.variant, c.points, c.slack, c.margins, c.tool_share});
    }

    std::optional<ArmShape<double>> draw(const DrawContext& c, std::mt19937& rng,
                                         int candidate) const override {
        DrawContext carrier_context = c;
        carrier_context.dof = kCarrierDof;
        auto s = yaw_pitch_draw(carrier_context, rng, candidate);
        if (s) s->dof = kDof;
        return s;
    }

    std::vector<std::vector<double>> along_grid(int, int) const override {
        const double h = geometry::kPi / 2.0;
        return {{0.0, -h}, {0.0, 0.0}, {h, 0.0}, {2.0 * h, 0.0}, {-h, 0.0}};
    }

    std::vector<std::optional<double>> pointing_along(int, int, const Vec3& wanted,
                                                      double) const override {
        return {std::atan2(wanted.y(), wanted.x()), std::asin(std::clamp(wanted.z(), -1.0, 1.0))};
    }

    std::optional<ArmShape<double>> read(const kinematics::DhChain& chain) const override {
        if (chain.dof() != kDof) return std::nullopt;
        const auto& r4 = chain.rows[3];
        const auto& r5 = chain.rows[4];
        const double alpha = chain.rows[0].alpha;
        constexpr double e = 1e-9;
        if (std::abs(r4.a) > e || std::abs(r4.d) > e || std::abs(r4.alpha - alpha) > e ||
            !(r5.a > e) || std::abs(r5.d) > e || std::abs(r5.alpha) > e)
            return std::nullopt;
        kinematics::DhChain carried = chain;
        carried.rows.resize(3);
        auto s = yaw_pitch_family().read(carried);
        if (!s) return std::nullopt;
        s->dof = kDof;
        s->values.push_back(r5.a);
        return s;
    }
};

}  // namespace

const Family& wrist_family() {
    static const WristFamily family;
    return family;
}

}  // namespace modsynth::arms
