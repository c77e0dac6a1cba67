// The SCARA: every joint axis vertical (every twist 0), the links in one
// horizontal plane at the height base_z + d_1, the industry's dispensing and
// assembly arm. Row 1 is (a_1, 0, d_1), rows 2..m are (a_k, 0, 0); with a
// quill the last row is (0, 0, -L), a vertical last segment whose joint only
// spins it, so that the tool points straight down. The EE's height is fixed
// by the offsets (base_z + d_1 - L), so the family only traces paths at one
// height. Links 1 and 2 are placed by the planar 2-link IK about the column;
// links 3..m (more joints) have their absolute yaw as the design's free
// numbers along each primitive, as the yaw-pitch arm's hand has its pitch.
//
// Values: [d_1 when the column is up or hanging], a_1 .. a_m, [L with a
// quill]. Variants: bits 0-1 the column (0 up, 1 hanging, 2 none), bit 2 the
// quill.
#include <algorithm>
#include <cmath>
#include <limits>

#include <modsynth/arms/family.h>
#include <modsynth/geometry/vec.h>
#include <modsynth/kinematics/kinematics.h>
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
/// Absolute yaws (rad) the guesses try for the links past the second, per
/// stroke: every 45 degrees.
constexpr int kHandYaws = 8;
/// m: how far the path's points may lie from one height for the family.
constexpr double kHeightTolerance = 1e-6;

int column_of(int variant) {
    const int c = variant & 3;
    return c == 0 ? 1 : c == 1 ? -1 : 0;
}
bool has_quill(int variant) { return (variant & 4) != 0; }
/// Planar links (a_1 .. a_m) of a chain of `dof` joints.
int planar_links(int dof, int variant) { return dof - (has_quill(variant) ? 1 : 0); }

/// The values of a shape, named.
template <class T>
struct Parts {
    T column;              ///< d_1 (0 without a column)
    std::vector<T> links;  ///< a_1 .. a_m
    T quill;               ///< L (0 without a quill)
};

template <class T>
Parts<T> parts_of(const ArmShape<T>& s) {
    Parts<T> p{T(0.0), {}, T(0.0)};
    std::size_t at = 0;
    if (column_of(s.variant) != 0) p.column = s.values[at++];
    const int m = planar_links(s.dof, s.variant);
    for (int k = 0; k < m; ++k) p.links.push_back(s.values[at++]);
    if (has_quill(s.variant)) p.quill = s.values[at++];
    return p;
}

template <class T>
T floored_sqrt(const T& v) {
    using std::sqrt;
    return v > T(1e-18) ? T(sqrt(v)) : T(sqrt(T(1e-18)));
}

template <class T>
ArmPose<T> pose_of(const ArmShape<T>& shape, const PoseTarget<T>& target, int branch,
                   const std::vector<T>& yaws, const PoseMargins& m) {
    using std::cos;
    using std::sin;
    const Parts<T> p = parts_of(shape);
    const T h = shape.base.z() + p.column;
    const Point3<T> top(shape.base.x(), shape.base.y(), h);
    // The planar links end above the target, at the links' height.
    const Point3<T> end(target.point.x(), target.point.y(), h);
    T wx = end.x(), wy = end.y();
    std::vector<Point3<T>> hand;  // from the wrist out, filled backwards
    const int m_links = static_cast<int>(p.links.size());
    std::vector<T> hx, hy;
    for (int k = 2; k < m_links; ++k) {
        hx.push_back(p.links[static_cast<std::size_t>(k)] *
                     cos(yaws[static_cast<std::size_t>(k - 2)]));
        hy.push_back(p.links[static_cast<std::size_t>(k)] *
                     sin(yaws[static_cast<std::size_t>(k - 2)]));
        wx = wx - hx.back();
        wy = wy - hy.back();
    }
    const T& a1 = p.links[0];
    const T& a2 = p.links[1];
    const T x = wx - top.x(), y = wy - top.y();
    const T l2 = x * x + y * y;
    const T l = floored_sqrt(l2);
    const T along = (a1 * a1 - a2 * a2 + l2) / (T(2.0) * l);
    const T across = floored_sqrt(T(a1 * a1 - along * along));
    // q_2 > 0 (branch 0) puts the elbow to the right of the line from the
    // column to the wrist, seen from above.
    const double e = branch == 0 ? 1.0 : -1.0;
    const Point3<T> elbow(top.x() + (along * x + e * across * y) / l,
                          top.y() + (along * y - e * across * x) / l, h);
    ArmPose<T> out;
    out.points.push_back(shape.base);
    if (column_of(shape.variant) != 0) out.points.push_back(top);
    out.points.push_back(elbow);
    Point3<T> at(wx, wy, h);
    out.points.push_back(at);
    for (std::size_t i = 0; i < hx.size(); ++i) {
        at = Point3<T>(at.x() + hx[i], at.y() + hy[i], h);
        out.points.push_back(at);
    }
    if (has_quill(shape.variant)) out.points.push_back(Point3<T>(end.x(), end.y(), h - p.quill));
    const std::size_t segments = out.points.size() - 1;
    for (std::size_t k = 0; k < segments; ++k) {
        // The column and link 1's a part are both link 1; the quill is the
        // last link.
        const int offset = column_of(shape.variant) != 0 ? 0 : 1;
        int link = static_cast<int>(k) + offset;
        if (column_of(shape.variant) != 0 && k == 0) link = 1;
        if (has_quill(shape.variant) && k + 1 == segments) link = shape.dof;
        out.links.push_back(std::max(1, link));
    }
    // o_0 is the base, o_k the end of planar link k: every point from the
    // elbow on but the EE (with a quill, the last is the quill's top).
    out.joints.push_back(shape.base);
    for (std::size_t k = column_of(shape.variant) != 0 ? 2 : 1; k + 1 < out.points.size(); ++k)
        out.joints.push_back(out.points[k]);
    const T cos_q2 = (l2 - a1 * a1 - a2 * a2) / (T(2.0) * a1 * a2);
    const double shorter = std::min(kinematics::value_of(a1), kinematics::value_of(a2));
    out.limits.push_back(
        {cos_q2, -m.elbow_cos, m.elbow_cos, shorter, "elbow from its fold and stretch"});
    return out;
}

double path_height(const task::SpatialTask& task) {
    return geometry::start_point(task.trajectory.front()).z();
}

bool allows_zero(const std::vector<double>& twists) {
    return std::any_of(twists.begin(), twists.end(), [](double a) { return std::abs(a) <= 1e-9; });
}

class ScaraFamily final : public Family {
public:
    std::string_view name() const override { return "scara"; }
    int along_count(int dof, int variant) const override {
        return std::max(0, planar_links(dof, variant) - 2);
    }
    int branch_count(int) const override { return 2; }

    kinematics::DhChain chain(const ArmDesign& d) const override {
        const Parts<double> p = parts_of(d.shape);
        kinematics::DhChain c;
        c.base = d.shape.base;
        c.link_diameter = d.link_diameter;
        for (std::size_t k = 0; k < p.links.size(); ++k)
            c.rows.push_back({p.links[k], 0.0, k == 0 ? p.column : 0.0});
        if (has_quill(d.shape.variant)) c.rows.push_back({0.0, 0.0, -p.quill});
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
        const std::vector<double>& yaws) const override {
        const Parts<double> p = parts_of(d.shape);
        const Vec3 base = d.shape.base;
        double wx = target.point.x(), wy = target.point.y();
        for (std::size_t k = 2; k < p.links.size(); ++k) {
            wx -= p.links[k] * std::cos(yaws[k - 2]);
            wy -= p.links[k] * std::sin(yaws[k - 2]);
        }
        const double a1 = p.links[0], a2 = p.links[1];
        const double x = wx - base.x(), y = wy - base.y();
        const double c = (x * x + y * y - a1 * a1 - a2 * a2) / (2.0 * a1 * a2);
        if (!(std::abs(c) <= 1.0 - 1e-9)) return std::nullopt;
        const double q2 = (branch == 0 ? 1.0 : -1.0) * std::acos(c);
        const double q1 = std::atan2(y, x) - std::atan2(a2 * std::sin(q2), a1 + a2 * std::cos(q2));
        std::vector<double> q{std::remainder(q1, geometry::kTau), q2};
        double yaw = q1 + q2;
        for (std::size_t k = 2; k < p.links.size(); ++k) {
            q.push_back(yaws[k - 2] - yaw);
            yaw = yaws[k - 2];
        }
        if (has_quill(d.shape.variant)) q.push_back(0.0);  // it only spins the quill
        // The closed form is exact in the plane; the height is the design's.
        const Vec3 reached = kinematics::end_effector(chain(d), q);
        const double scale = 1.0 + std::abs(p.column) + a1 + a2 + (target.point - base).norm();
        const Vec3 off = reached - target.point;
        if (!(std::hypot(off.x(), off.y()) <= 1e-9 * scale) ||
            !(std::abs(off.z()) <= 10.0 * kHeightTolerance))
            return std::nullopt;
        return q;
    }

    std::vector<int> variants(int dof, const task::SpatialRobotSpec& spec) const override {
        if (dof < 3 || dof > 6 || !allows_zero(spec.twists)) return {};
        return {2, 0, 6, 4, 1, 5};
    }
    std::string_view needs() const override { return "a SCARA needs a twist of 0"; }
    std::string describe_variant(int variant) const override {
        const int c = column_of(variant);
        return std::string("column ") +
               (c > 0   ? "up"
                : c < 0 ? "hanging"
                        : "none") +
               (has_quill(variant) ? ", quill" : "");
    }
    std::string describe(const ArmDesign& d) const override {
        const Parts<double> p = parts_of(d.shape);
        std::string links;
        double chain_length = std::abs(p.column) + p.quill;
        for (double a : p.links) {
            links += text::format(links.empty() ? "%.4f" : " + %.4f", a);
            chain_length += a;
        }
        return text::format("base (%.3f, %.3f, %.3f), d1 %.4f, links ", d.shape.base.x(),
                            d.shape.base.y(), d.shape.base.z(), p.column) +
               links + (has_quill(d.shape.variant) ? text::format(", quill %.4f", p.quill) : "") +
               text::format(" m (chain %.4f m)", chain_length);
    }

    std::vector<Bound> value_bounds(const task::SpatialRobotSpec& spec, int dof,
                                    int variant) const override {
        const double lo = spec.min_link_length, hi = spec.max_link_length;
        std::vector<Bound> out;
        const int c = column_of(variant);
        if (c > 0) out.push_back({lo, hi});
        if (c < 0) out.push_back({-hi, -lo});
        const int m = planar_links(dof, variant);
        const bool quill = has_quill(variant);
        // The tool is part of the last segment (formats.md rule 5).
        for (int k = 0; k < m; ++k)
            out.push_back({!quill && k == m - 1 ? std::max(lo, spec.tool_length) : lo, hi});
        if (quill) out.push_back({std::max(lo, spec.tool_length), hi});
        return out;
    }
    Bound along_bound(int) const override { return {-4.0 * geometry::kPi, 4.0 * geometry::kPi}; }
    std::vector<double> length_weights(int dof, int variant) const override {
        std::vector<double> w;
        if (column_of(variant) != 0) w.push_back(column_of(variant));
        w.insert(w.end(), static_cast<std::size_t>(planar_links(dof, variant)), 1.0);
        if (has_quill(variant)) w.push_back(1.0);
        return w;
    }
    // The EE at the path's height: base_z + d_1 - L.
    std::vector<kinematics::DesignRow> design_rows(const task::SpatialTask& task, int dof,
                                                   int variant) const override {
        kinematics::DesignRow row;
        row.base = Vec3(0.0, 0.0, 1.0);
        if (column_of(variant) != 0) row.values.push_back(1.0);
        row.values.insert(row.values.end(), static_cast<std::size_t>(planar_links(dof, variant)),
                          0.0);
        if (has_quill(variant)) row.values.push_back(-1.0);
        row.lower = row.upper = path_height(task);
        row.what = "the EE at the path's height";
        return {row};
    }
    Vec3 reach_centre(const ArmDesign& d) const override {
        return d.shape.base + Vec3(0.0, 0.0, parts_of(d.shape).column);
    }

    // The conditions of the pattern: every sampled point at the EE's height
    // base_z + d_1 - L, and within the planar arm's annulus |a_1 - a_2| -
    // hand <= |p - base| <= a_1 + a_2 + hand about the column, in the plane.
    smt::Pattern pattern(const PatternContext& c) const override {
        smt::Pattern p;
        const auto& spec = c.task.robot;
        const double e = c.slack;
        const double lo = spec.min_link_length - e, hi = spec.max_link_length + e;
        const task::TaskPart min_link = task::TaskPart::robot(task::RobotKey::MinLinkLength);
        const task::TaskPart max_link = task::TaskPart::robot(task::RobotKey::MaxLinkLength);
        const task::TaskPart twists = task::TaskPart::robot(task::RobotKey::Twists);
        const Term bx = Term::variable("base_x"), by = Term::variable("base_y"),
                   bz = Term::variable("base_z");
        const int col = column_of(c.variant);
        const Term column = col == 0 ? Term(0.0) : Term::variable("d1");
        if (col > 0) p.require({min_link, max_link}, column >= lo && column <= hi);
        if (col < 0) p.require({min_link, max_link}, column <= -lo && column >= -hi);
        const bool quill = has_quill(c.variant);
        const Term length = quill ? Term::variable("quill") : Term(0.0);
        if (quill) {
            p.require({min_link}, length >= lo);
            p.require({max_link}, length <= hi);
        }
        const Term a1 = Term::variable("a1"), a2 = Term::variable("a2");
        for (const Term& a : {a1, a2}) {
            p.require(a >= 0.0);
            p.require({min_link}, a >= lo);
            p.require({max_link}, a <= hi);
        }
        const int hands = planar_links(c.dof, c.variant) - 2;
        Term hand = 0.0;
        if (hands > 0) {
            hand = Term::variable("hand");
            p.require({min_link}, hand >= hands * lo);
            p.require({max_link}, hand <= hands * hi);
        }
        if (spec.tool_length > 0.0)
            p.require({task::TaskPart::robot(task::RobotKey::ToolLength)},
                      quill       ? length >= spec.tool_length - e
                      : hands > 0 ? hand >= spec.tool_length + (hands - 1) * lo
                                  : a2 >= spec.tool_length - e);
        const Term height = bz + column - length;
        const Term outer = a1 + a2 + hand;
        const Term inner_a = a1 - a2 - hand, inner_b = a2 - a1 - hand;
        const double tol = kHeightTolerance + e;
        for (std::size_t j = 0; j < c.points.size(); ++j) {
            const task::TaskPart part = task::primitive_part(c.task, static_cast<int>(j));
            for (const Vec3& q : c.points[j]) {
                p.require({part, twists}, height - q.z() <= tol && q.z() - height <= tol);
                const Term dx = q.x() - bx, dy = q.y() - by;
                const Term d2 = dx * dx + dy * dy;
                p.require({part}, d2 <= outer * outer + e);
                p.require({part}, inner_a <= 0.0 || d2 >= inner_a * inner_a - e);
                p.require({part}, inner_b <= 0.0 || d2 >= inner_b * inner_b - e);
            }
        }
        return p;
    }

    std::optional<ArmShape<double>> draw(const DrawContext& c, std::mt19937& rng,
                                         int) const override {
        const auto& spec = c.task.robot;
        const double lo = spec.min_link_length, hi = spec.max_link_length;
        const double zp = path_height(c.task);
        if (c.path_max.z() - c.path_min.z() > kHeightTolerance) return std::nullopt;
        std::uniform_real_distribution<double> u(0.0, 1.0);
        const int col = column_of(c.variant);
        const bool quill = has_quill(c.variant);
        const double shortest_quill = std::max(lo, spec.tool_length);
        const geometry::Box3& box = c.base_box;
        Vec3 base;
        for (int i = 0; i < 2; ++i) base[i] = box.min[i] + u(rng) * (box.max[i] - box.min[i]);
        // The heights: base_z + d_1 - L = the path's, with each in its bounds.
        double column = 0.0, length = 0.0;
        bool placed = false;
        for (int attempt = 0; attempt < 20 && !placed; ++attempt) {
            base.z() = box.min.z() + u(rng) * (box.max.z() - box.min.z());
            if (col == 0) {
                if (quill) {
                    length = base.z() - zp;
                } else {
                    base.z() = zp;
                }
            } else if (quill) {
                column = col * (lo + u(rng) * (hi - lo));
                length = base.z() + column - zp;
            } else {
                column = zp - base.z();
            }
            placed = base.z() >= box.min.z() - 1e-12 && base.z() <= box.max.z() + 1e-12 &&
                     (col == 0 ||
                      (std::abs(column) >= lo && std::abs(column) <= hi && column * col > 0)) &&
                     (!quill || (length >= shortest_quill && length <= hi));
        }
        if (!placed) return std::nullopt;
        const Vec3 top = base + Vec3(0.0, 0.0, column);
        double far = 0.0, close = kInf;
        for (const Vec3& p : c.probe) {
            const double r = std::hypot(p.x() - top.x(), p.y() - top.y());
            far = std::max(far, r);
            close = std::min(close, r);
        }
        const int m = planar_links(c.dof, c.variant);
        double hand = 0.0;
        std::vector<double> hand_links;
        for (int k = 2; k < m; ++k) {
            hand_links.push_back(lo + u(rng) * (std::min(hi, std::max(lo, 0.35)) - lo));
            hand += hand_links.back();
        }
        const double need = std::max(2.0 * lo, 1.01 * far - (m > 2 ? u(rng) * hand : 0.0));
        const double sum = std::min(2.0 * hi, need + u(rng) * std::max(0.02, 0.5 * need));
        const double diff = (2.0 * u(rng) - 1.0) * std::max(0.0, 0.9 * (close + hand));
        std::vector<double> links{std::clamp(0.5 * (sum + diff), lo, hi),
                                  std::clamp(0.5 * (sum - diff), lo, hi)};
        links.insert(links.end(), hand_links.begin(), hand_links.end());
        if (!quill) links.back() = std::max(links.back(), std::min(hi, spec.tool_length));
        ArmShape<double> s;
        s.dof = c.dof;
        s.variant = c.variant;
        s.base = base;
        if (col != 0) s.values.push_back(column);
        s.values.insert(s.values.end(), links.begin(), links.end());
        if (quill) s.values.push_back(length);
        return s;
    }

    std::vector<std::vector<double>> along_grid(int dof, int variant) const override {
        const int hands = planar_links(dof, variant) - 2;
        if (hands <= 0) return {{}};
        std::vector<std::vector<double>> out;
        for (int i = 0; i < kHandYaws; ++i)
            out.push_back(std::vector<double>(static_cast<std::size_t>(hands),
                                              -geometry::kPi + geometry::kTau * i / kHandYaws));
        return out;
    }

    std::optional<ArmShape<double>> read(const kinematics::DhChain& chain) const override {
        const int n = chain.dof();
        if (n < 3 || n > 6) return std::nullopt;
        for (const auto& r : chain.rows)
            if (std::abs(r.alpha) > 1e-9) return std::nullopt;
        const auto& last = chain.rows.back();
        const bool quill = std::abs(last.a) <= kinematics::kZeroSegment && last.d < 0.0;
        const int m = quill ? n - 1 : n;
        for (int k = 0; k < m; ++k) {
            const auto& r = chain.rows[static_cast<std::size_t>(k)];
            if (!(r.a > kinematics::kZeroSegment)) return std::nullopt;
            if (k > 0 && std::abs(r.d) > kinematics::kZeroSegment) return std::nullopt;
        }
        const double d1 = chain.rows[0].d;
        const int column = std::abs(d1) <= kinematics::kZeroSegment ? 2 : d1 > 0 ? 0 : 1;
        ArmShape<double> s;
        s.dof = n;
        s.variant = column | (quill ? 4 : 0);
        s.base = chain.base;
        if (column != 2) s.values.push_back(d1);
        for (int k = 0; k < m; ++k) s.values.push_back(chain.rows[static_cast<std::size_t>(k)].a);
        if (quill) s.values.push_back(-last.d);
        return s;
    }
};

}  // namespace

const Family& scara_family() {
    static const ScaraFamily family;
    return family;
}

}  // namespace modsynth::arms
