// The yaw column with pitch links (kinematics/yaw_pitch_ik.h): row 1 a
// column (a_1 = 0, d_1 up, hanging or none, alpha_1 = +-pi/2), rows 2..n
// pitch links (a_k > 0, d_k = 0, alpha_k = 0). Every link stays in the
// vertical plane through the column; with four to six joints the hand
// links' absolute pitches are the design's free numbers along each
// primitive (ArmDesign::along), and the wrist point is solved with the
// 3-joint IK.
//
// Values: [d_1 when the column is up or hanging], a_2 .. a_n.
// Variants: bit 2 the twist of the column (-pi/2 when set), bits 0-1 the
// column: 0 up, 1 hanging, 2 none.
#include <algorithm>
#include <cmath>
#include <limits>

#include <modsynth/arms/family.h>
#include <modsynth/geometry/vec.h>
#include <modsynth/kinematics/yaw_pitch_ik.h>
#include <modsynth/kinematics/yaw_pitch_pose.h>
#include <modsynth/task/spatial_strokes.h>
#include <modsynth/text/format.h>

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
using smt::Term;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr kinematics::IkBranch kBranches[] = {{1, 1}, {1, -1}, {-1, 1}, {-1, -1}};
/// Hand pitches (rad) the guesses try per stroke, evenly over +-kMaxPitch.
constexpr int kHandPitches = 7;
constexpr double kMaxPitch = 1.2;

int column_of(int variant) {
    const int c = variant & 3;
    return c == 0 ? 1 : c == 1 ? -1 : 0;
}
int twist_of(int variant) { return (variant & 4) ? -1 : 1; }
bool has_column(int variant) { return column_of(variant) != 0; }

bool allows(const std::vector<double>& twists, double angle) {
    return std::any_of(twists.begin(), twists.end(),
                       [&](double a) { return std::abs(a - angle) <= 1e-9; });
}

template <class T>
kinematics::YawPitchShape<T> yaw_pitch_shape(const ArmShape<T>& s) {
    kinematics::YawPitchShape<T> y;
    y.base = s.base;
    const std::size_t first = has_column(s.variant) ? 1 : 0;
    y.column = first ? s.values[0] : T(0.0);
    y.links.assign(s.values.begin() + static_cast<std::ptrdiff_t>(first), s.values.end());
    y.column_twist = twist_of(s.variant);
    return y;
}

kinematics::YawPitchArm arm_of(const ArmShape<double>& s) {
    const auto y = yaw_pitch_shape(s);
    kinematics::YawPitchArm arm;
    arm.base = y.base;
    arm.column = y.column;
    arm.column_twist = y.column_twist;
    arm.links = y.links;
    return arm;
}

template <class T>
ArmPose<T> pose_of(const ArmShape<T>& shape, const PoseTarget<T>& target, int branch,
                   const std::vector<T>& along, const PoseMargins& m) {
    const auto y = yaw_pitch_shape(shape);
    const auto p = kinematics::yaw_pitch_pose(y, target.point,
                                              kBranches[static_cast<std::size_t>(branch)], along);
    ArmPose<T> out;
    const bool column = has_column(shape.variant);
    out.points.assign(p.points.begin() + (column ? 0 : 1), p.points.end());
    for (std::size_t k = 0; k + 1 < out.points.size(); ++k)
        out.links.push_back(static_cast<int>(column ? k + 1 : k + 2));
    // o_0 is the base, o_1 the shoulder (a_1 = 0), then each pitch link's end
    // but the last: the yaw-pitch pose's own points, the EE left out.
    out.joints.assign(p.points.begin(), p.points.end() - 1);
    const double shorter =
        std::min(kinematics::value_of(y.links[0]), kinematics::value_of(y.links[1]));
    out.limits.push_back(
        {p.elbow_cos, -m.elbow_cos, m.elbow_cos, shorter, "elbow from its fold and stretch"});
    out.limits.push_back({p.axis_distance, m.axis, kInf, 1.0, "path off the column's axis"});
    return out;
}

class YawPitchFamily final : public Family {
public:
    std::string_view name() const override { return "yaw-pitch"; }
    int along_count(int dof, int) const override { return dof - 3; }
    int branch_count(int) const override { return 4; }

    kinematics::DhChain chain(const ArmDesign& d) const override {
        return kinematics::to_chain(arm_of(d.shape), d.link_diameter);
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
        return kinematics::yaw_pitch_ik(arm_of(d.shape), target.point,
                                        kBranches[static_cast<std::size_t>(branch)], along);
    }

    std::vector<int> variants(int dof, const task::SpatialRobotSpec& spec) const override {
        if (dof < 3 || dof > 6 || !allows(spec.twists, 0.0)) return {};
        for (int twist : {1, -1})
            if (allows(spec.twists, twist * geometry::kPi / 2)) {
                const int bit = twist > 0 ? 0 : 4;
                return {bit | 0, bit | 1, bit | 2};
            }
        return {};
    }
    std::string_view needs() const override {
        return "a yaw column with pitch links needs twists 0 and +-pi/2";
    }
    std::string describe_variant(int variant) const override {
        const int c = column_of(variant);
        return std::string("column ") + (c > 0 ? "up" : c < 0 ? "hanging" : "none");
    }
    std::string describe(const ArmDesign& d) const override {
        const auto arm = arm_of(d.shape);
        std::string links;
        double chain = std::abs(arm.column);
        for (double a : arm.links) {
            links += text::format(links.empty() ? "%.4f" : " + %.4f", a);
            chain += a;
        }
        return text::format("base (%.3f, %.3f, %.3f), d1 %.4f, links ", arm.base.x(), arm.base.y(),
                            arm.base.z(), arm.column) +
               links + text::format(" m (chain %.4f m)", chain);
    }

    std::vector<Bound> value_bounds(const task::SpatialRobotSpec& spec, int dof,
                                    int variant) const override {
        const double lo = spec.min_link_length, hi = spec.max_link_length;
        std::vector<Bound> out;
        const int c = column_of(variant);
        if (c > 0) out.push_back({lo, hi});
        if (c < 0) out.push_back({-hi, -lo});
        for (int k = 0; k < dof - 1; ++k)
            // The tool is part of the last segment (formats.md rule 5).
            out.push_back({k == dof - 2 ? std::max(lo, spec.tool_length) : lo, hi});
        return out;
    }
    Bound along_bound(int) const override { return {-4.0 * geometry::kPi, 4.0 * geometry::kPi}; }
    std::vector<double> length_weights(int dof, int variant) const override {
        std::vector<double> w;
        if (has_column(variant)) w.push_back(column_of(variant));
        w.insert(w.end(), static_cast<std::size_t>(dof - 1), 1.0);
        return w;
    }
    std::vector<kinematics::DesignRow> design_rows(const task::SpatialTask&, int,
                                                   int) const override {
        return {};
    }
    Vec3 reach_centre(const ArmDesign& d) const override { return arm_of(d.shape).shoulder(); }

    // The conditions of the pattern: the links' bounds and the tool, and at
    // every sampled point the wrist's annulus |a_2 - a_3| - hand <= |p - S|
    // <= a_2 + a_3 + hand about the shoulder S = base + d_1 z, and the path
    // off the column's axis.
    smt::Pattern pattern(const PatternContext& c) const override {
        smt::Pattern p;
        const auto& spec = c.task.robot;
        const double e = c.slack;
        const double lo = spec.min_link_length - e, hi = spec.max_link_length + e;
        const task::TaskPart min_link = task::TaskPart::robot(task::RobotKey::MinLinkLength);
        const task::TaskPart max_link = task::TaskPart::robot(task::RobotKey::MaxLinkLength);
        const Term bx = Term::variable("base_x"), by = Term::variable("base_y"),
                   bz = Term::variable("base_z");
        const int col = column_of(c.variant);
        const Term column = col == 0 ? Term(0.0) : Term::variable("d1");
        if (col > 0) p.require({min_link, max_link}, column >= lo && column <= hi);
        if (col < 0) p.require({min_link, max_link}, column <= -lo && column >= -hi);
        const Term a2 = Term::variable("a2"), a3 = Term::variable("a3");
        for (const Term& a : {a2, a3}) {
            p.require(a >= 0.0);
            p.require({min_link}, a >= lo);
            p.require({max_link}, a <= hi);
        }
        const int hands = c.dof - 3;
        Term hand = 0.0;
        if (hands > 0) {
            hand = Term::variable("hand");
            p.require({min_link}, hand >= hands * lo);
            p.require({max_link}, hand <= hands * hi);
        }
        // The tool is part of the last link.
        if (spec.tool_length > 0.0)
            p.require({task::TaskPart::robot(task::RobotKey::ToolLength)},
                      hands > 0 ? hand >= spec.tool_length + (hands - 1) * lo
                                : a3 >= spec.tool_length - e);
        const Term sz = bz + column;
        const Term outer = a2 + a3 + hand;
        const Term inner_a = a2 - a3 - hand, inner_b = a3 - a2 - hand;
        const double axis = std::max(0.0, c.margins.axis - e);
        for (std::size_t j = 0; j < c.points.size(); ++j) {
            const task::TaskPart part = task::primitive_part(c.task, static_cast<int>(j));
            for (const Vec3& q : c.points[j]) {
                const Term dx = q.x() - bx, dy = q.y() - by, dz = q.z() - sz;
                const Term d2 = dx * dx + dy * dy + dz * dz;
                p.require({part}, d2 <= outer * outer + e);
                p.require({part}, inner_a <= 0.0 || d2 >= inner_a * inner_a - e);
                p.require({part}, inner_b <= 0.0 || d2 >= inner_b * inner_b - e);
                p.require({part}, dx * dx + dy * dy >= axis * axis);
            }
        }
        return p;
    }

    std::optional<ArmShape<double>> draw(const DrawContext& c, std::mt19937& rng,
                                         int candidate) const override {
        const auto& spec = c.task.robot;
        const double lo = spec.min_link_length, hi = spec.max_link_length;
        const int hands = c.dof - 3;
        std::uniform_real_distribution<double> u(0.0, 1.0);
        kinematics::YawPitchArm arm;
        arm.column_twist = twist_of(c.variant);
        for (int i = 0; i < 3; ++i)
            arm.base[i] = c.base_box.min[i] + u(rng) * (c.base_box.max[i] - c.base_box.min[i]);
        const int sign = column_of(c.variant);
        if (sign != 0) {
            // Half the draws aim the shoulder at the path's heights.
            double mag = lo + u(rng) * (hi - lo);
            if (candidate % 2 == 1) {
                const double z =
                    c.path_min.z() - 0.2 + u(rng) * (c.path_max.z() - c.path_min.z() + 0.4);
                const double want = sign * (z - arm.base.z());
                if (want >= lo && want <= hi) mag = want;
            }
            arm.column = sign * mag;
        }
        const Vec3 shoulder = arm.shoulder();
        double far = 0.0, close = kInf;
        for (const Vec3& p : c.probe) {
            const double r = (p - shoulder).norm();
            far = std::max(far, r);
            close = std::min(close, r);
        }
        double hand = 0.0;
        std::vector<double> hand_links;
        for (int h = 0; h < hands; ++h) {
            hand_links.push_back(lo + u(rng) * (std::min(hi, std::max(lo, 0.35)) - lo));
            hand += hand_links.back();
        }
        const double need = std::max(2.0 * lo, 1.01 * far - (hands > 0 ? u(rng) * hand : 0.0));
        const double sum = std::min(2.0 * hi, need + u(rng) * std::max(0.02, 0.5 * need));
        const double diff = (2.0 * u(rng) - 1.0) * std::max(0.0, 0.9 * (close + hand));
        arm.links = {std::clamp(0.5 * (sum + diff), lo, hi),
                     std::clamp(0.5 * (sum - diff), lo, hi)};
        for (double a : hand_links) arm.links.push_back(a);
        arm.links.back() = std::max(arm.links.back(), std::min(hi, spec.tool_length));
        ArmShape<double> s;
        s.dof = c.dof;
        s.variant = c.variant;
        s.base = arm.base;
        if (sign != 0) s.values.push_back(arm.column);
        s.values.insert(s.values.end(), arm.links.begin(), arm.links.end());
        return s;
    }

    std::vector<std::vector<double>> along_grid(int dof, int) const override {
        const int hands = dof - 3;
        if (hands <= 0) return {{}};
        std::vector<std::vector<double>> out;
        for (int i = 0; i < kHandPitches; ++i) {
            const double pitch = -kMaxPitch + 2.0 * kMaxPitch * i / (kHandPitches - 1);
            out.push_back(std::vector<double>(static_cast<std::size_t>(hands), pitch));
        }
        return out;
    }

    std::optional<ArmShape<double>> read(const kinematics::DhChain& chain) const override {
        const auto arm = kinematics::as_yaw_pitch(chain);
        if (!arm) return std::nullopt;
        ArmShape<double> s;
        s.dof = arm->dof();
        const int column = std::abs(arm->column) <= kinematics::kZeroSegment ? 2
                           : arm->column > 0                                 ? 0
                                                                             : 1;
        s.variant = (arm->column_twist < 0 ? 4 : 0) | column;
        s.base = arm->base;
        if (column != 2) s.values.push_back(arm->column);
        s.values.insert(s.values.end(), arm->links.begin(), arm->links.end());
        return s;
    }
};

}  // namespace

const Family& yaw_pitch_family() {
    static const YawPitchFamily family;
    return family;
}

}  // namespace modsynth::arms
