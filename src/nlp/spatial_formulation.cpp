#include <modsynth/nlp/spatial_formulation.h>

#include <unsupported/Eigen/AutoDiff>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <modsynth/geometry/distance3.h>
#include <modsynth/geometry/obstacle3.h>
#include <modsynth/geometry/primitive3.h>
#include <modsynth/kinematics/yaw_pitch_pose.h>
#include <modsynth/task/spatial_strokes.h>
#include <modsynth/text/format.h>

namespace modsynth::nlp {
namespace {

using geometry::Vec3;
constexpr double kInf = std::numeric_limits<double>::infinity();
/// Variables one point's constraints depend on, at most: the base (3), the
/// column, five pitch links and two pitches of three hand links.
constexpr int kMaxLocal = 16;
using Derivatives = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxLocal, 1>;
using AD = Eigen::AutoDiffScalar<Derivatives>;
using P3 = kinematics::Point3<AD>;

AD constant(double v) { return AD(v); }

P3 constant(const Vec3& v) { return P3(constant(v.x()), constant(v.y()), constant(v.z())); }

Vec3 value(const P3& p) { return {p.x().value(), p.y().value(), p.z().value()}; }

AD safe_norm(const P3& v) {
    const AD sq = v.x() * v.x() + v.y() * v.y() + v.z() * v.z();
    return sq.value() > 1e-24 ? AD(sqrt(sq)) : AD(sqrt(sq + AD(1e-24)));
}

/// Parameters (s, t) of a nearest pair of points of segments ab and cd:
/// the distance is a minimum over them, so by the envelope theorem its
/// derivative is that of |a(s) - c(t)| at fixed (s, t).
std::pair<double, double> nearest_parameters(const Vec3& a, const Vec3& b, const Vec3& c,
                                             const Vec3& d) {
    std::pair<double, double> best{0.0, geometry::segment_parameter(a, c, d)};
    double best_d = (a - (c + best.second * (d - c))).norm();
    auto consider = [&](double s, double t) {
        const double v = (a + s * (b - a) - (c + t * (d - c))).norm();
        if (v < best_d) best_d = v, best = {s, t};
    };
    consider(1.0, geometry::segment_parameter(b, c, d));
    consider(geometry::segment_parameter(c, a, b), 0.0);
    consider(geometry::segment_parameter(d, a, b), 1.0);
    const Vec3 d1 = b - a, d2 = d - c, r = a - c;
    const double aa = d1.squaredNorm(), ee = d2.squaredNorm(), ab = d1.dot(d2);
    const double denom = aa * ee - ab * ab;
    if (aa > 0.0 && ee > 0.0 && denom > 1e-14 * aa * ee) {
        const double cc = d1.dot(r), ff = d2.dot(r);
        const double s = (ab * ff - cc * ee) / denom;
        const double t = (aa * ff - ab * cc) / denom;
        if (s > 0.0 && s < 1.0 && t > 0.0 && t < 1.0) consider(s, t);
    }
    return best;
}

P3 lerp(const P3& a, const P3& b, const AD& t) { return a + (b - a) * t; }

/// Distance between segments pq and rs, differentiable in their ends.
AD segment_distance(const P3& p, const P3& q, const P3& r, const P3& s) {
    const auto [u, v] = nearest_parameters(value(p), value(q), value(r), value(s));
    return safe_norm(lerp(p, q, constant(u)) - lerp(r, s, constant(v)));
}

AD point_segment_distance(const P3& x, const P3& p, const P3& q) {
    const double t = geometry::segment_parameter(value(x), value(p), value(q));
    return safe_norm(x - lerp(p, q, constant(t)));
}

/// formats.md's clearance of segment pq to an obstacle (geometry::segment_gap).
AD obstacle_gap(const P3& p, const P3& q, const geometry::Obstacle3& o) {
    if (const auto* s = std::get_if<geometry::Sphere>(&o))
        return point_segment_distance(constant(s->center), p, q) - constant(s->radius);
    if (const auto* c = std::get_if<geometry::Capsule>(&o))
        return segment_distance(p, q, constant(c->a), constant(c->b)) - constant(c->radius);
    const auto& box = std::get<geometry::Box3>(o);
    double t = 0.0;
    geometry::segment_box(value(p), value(q), box, &t);
    const P3 x = lerp(p, q, constant(t));
    P3 off = x;
    for (int i = 0; i < 3; ++i) {
        const double v = x[i].value();
        off[i] = v < box.min[i]   ? x[i] - constant(box.min[i])
                 : v > box.max[i] ? x[i] - constant(box.max[i])
                                  : constant(0.0);
    }
    return safe_norm(off);
}

enum class Kind { Reach, Axis, SelfPair, SelfEe, Clearance };

struct Row {
    Kind kind = Kind::Reach;
    int a = -1;  ///< segment (SelfPair, SelfEe, Clearance: the part of it that must keep clear)
    int b = -1;  ///< segment (SelfPair), obstacle (Clearance)
};

/// One point's rows, and the variables they depend on.
struct Block {
    SpatialPoint point;
    Vec3 target = Vec3::Zero();
    std::vector<int> locals;  ///< global index of each local variable
    /// Local index of each hand link's pitch at the two ends of the
    /// interpolation (start/end of the primitive, or the two sides of the
    /// join in a transition), and the fraction between them.
    std::vector<std::pair<int, int>> pitch_locals;
    double fraction = 0.0;
    std::vector<Row> rows;
    int first_row = 0;
    int first_entry = 0;
};

using Part = kinematics::PosePart<AD>;

}  // namespace

struct SpatialFormulation::Impl {
    const task::SpatialTask& task;
    SpatialProblem problem;
    int dof = 0;
    bool has_column = false;
    // Variable layout.
    int column_var = -1;
    int first_link = 0;
    int first_pitch = 0;
    std::vector<double> lower, upper, x0;
    std::vector<Block> blocks;
    std::vector<double> row_lower, row_upper;
    std::vector<std::string> labels;
    std::vector<Entry> structure;
    // The last evaluation, shared by eval_constraints and eval_jacobian.
    mutable std::vector<double> cached_x, cached_g, cached_jac;

    explicit Impl(const SpatialProblem& p) : task(*p.task), problem(p) {}

    int pitch_var(int j, int h) const { return first_pitch + 2 * ((dof - 3) * j + h); }

    void build();
    void add_block(const SpatialPoint& point, const std::vector<double>& x);
    int segments() const { return has_column ? dof : dof - 1; }
    std::vector<AD> local_values(const Block& b, const double* x) const;
    kinematics::YawPitchPose<AD> pose(const Block& b, const std::vector<AD>& v) const;
    std::vector<Part> parts(const std::vector<std::pair<P3, P3>>& segs) const;
    AD row_value(const Row& r, const kinematics::YawPitchPose<AD>& pose,
                 const std::vector<std::pair<P3, P3>>& segs, const std::vector<Part>& parts) const;
    void evaluate(const double* x) const;
};

namespace {

std::string where(const task::SpatialTask& task, const SpatialPoint& p) {
    if (p.transition)
        return text::format("the transition after %s at %.3f of its sweep",
                            task::part_name(task, p.primitive).c_str(), p.t);
    return text::format("%s at %.4f m", task::part_name(task, p.primitive).c_str(), p.s);
}

}  // namespace

void SpatialFormulation::Impl::build() {
    const auto& d = problem.start;
    dof = d.arm.dof();
    has_column = problem.column != 0;
    const auto& spec = task.robot;
    const int m = static_cast<int>(task.trajectory.size());
    if (dof < 3 || static_cast<int>(d.branches.size()) != task::stroke_count(task) ||
        (dof > 3 && static_cast<int>(d.pitches.size()) != m))
        throw std::invalid_argument("SpatialFormulation: the start design does not fit the task");
    // The base.
    for (int i = 0; i < 3; ++i) {
        lower.push_back(problem.base_box ? problem.base_box->min[i] : -kInf);
        upper.push_back(problem.base_box ? problem.base_box->max[i] : kInf);
        x0.push_back(d.arm.base[i]);
    }
    const double lo = spec.min_link_length, hi = spec.max_link_length;
    if (has_column) {
        column_var = static_cast<int>(x0.size());
        lower.push_back(problem.column > 0 ? lo : -hi);
        upper.push_back(problem.column > 0 ? hi : -lo);
        x0.push_back(d.arm.column);
    }
    first_link = static_cast<int>(x0.size());
    for (int k = 0; k < dof - 1; ++k) {
        // The tool is part of the last segment (formats.md rule 5).
        const bool last = k == dof - 2;
        lower.push_back(last ? std::max(lo, spec.tool_length) : lo);
        upper.push_back(hi);
        x0.push_back(d.arm.links[static_cast<std::size_t>(k)]);
    }
    first_pitch = static_cast<int>(x0.size());
    if (dof > 3) {
        for (int j = 0; j < m; ++j) {
            for (int h = 0; h < dof - 3; ++h) {
                const auto& hp =
                    d.pitches[static_cast<std::size_t>(j)][static_cast<std::size_t>(h)];
                for (double v : {hp.start, hp.end}) {
                    lower.push_back(-4.0 * geometry::kPi);
                    upper.push_back(4.0 * geometry::kPi);
                    x0.push_back(v);
                }
            }
        }
    }
    for (std::size_t i = 0; i < x0.size(); ++i) x0[i] = std::clamp(x0[i], lower[i], upper[i]);
    for (const SpatialPoint& p : problem.points) add_block(p, x0);
}

void SpatialFormulation::Impl::add_block(const SpatialPoint& point, const std::vector<double>& x) {
    Block b;
    b.point = point;
    const geometry::Primitive3& prim = task.trajectory[static_cast<std::size_t>(point.primitive)];
    const double length = geometry::length(prim);
    b.target = point.transition ? geometry::end_point(prim) : geometry::point_at(prim, point.s);
    for (int i = 0; i < first_pitch; ++i) b.locals.push_back(i);
    if (dof > 3) {
        b.fraction = point.transition ? point.t : (length > 0.0 ? point.s / length : 0.0);
        for (int h = 0; h < dof - 3; ++h) {
            const int from = point.transition ? pitch_var(point.primitive, h) + 1
                                              : pitch_var(point.primitive, h);
            const int to = point.transition ? pitch_var(point.primitive + 1, h)
                                            : pitch_var(point.primitive, h) + 1;
            b.pitch_locals.push_back(
                {static_cast<int>(b.locals.size()), static_cast<int>(b.locals.size()) + 1});
            b.locals.push_back(from);
            b.locals.push_back(to);
        }
    }
    // Which rows: every reach, axis and self-collision rule; the obstacles
    // near the chain at the start.
    const auto values = local_values(b, x.data());
    const auto ps = pose(b, values);
    const auto segs = kinematics::pose_segments(ps, has_column);
    const auto prts = parts(segs);
    const std::string at = where(task, point);
    const double diameter = task.robot.link_diameter;
    const auto& mg = problem.margins;
    auto add = [&](Row r, double lo, double hi, std::string label) {
        b.rows.push_back(r);
        row_lower.push_back(lo);
        row_upper.push_back(hi);
        labels.push_back(std::move(label) + " at " + at);
    };
    add({Kind::Reach}, -mg.elbow_cos, mg.elbow_cos, "elbow from its fold and stretch");
    add({Kind::Axis}, mg.axis, kInf, "path off the column's axis");
    const int n = static_cast<int>(segs.size());
    // The link each segment belongs to, 1-based, for labels.
    auto link = [&](int k) { return has_column ? k + 1 : k + 2; };
    for (int k = 0; k < n; ++k) {
        for (int l = k + 2; l < n; ++l)
            add({Kind::SelfPair, k, l}, diameter + mg.self, kInf,
                text::format("links %d and %d apart", link(k), link(l)));
        if (k + 1 < n)
            add({Kind::SelfEe, k}, diameter + mg.self, kInf,
                text::format("EE away from link %d", link(k)));
    }
    for (const Part& part : prts) {
        for (int o = 0; o < static_cast<int>(task.obstacles.size()); ++o) {
            const Row r{Kind::Clearance, part.segment, o};
            if (row_value(r, ps, segs, prts).value() > mg.near) continue;
            add(r, diameter / 2.0 + mg.clearance, kInf,
                text::format("clearance of link %d to obstacles[%d]", link(part.segment), o));
        }
    }
    b.first_row = static_cast<int>(row_lower.size() - b.rows.size());
    b.first_entry = static_cast<int>(structure.size());
    for (int r = 0; r < static_cast<int>(b.rows.size()); ++r)
        for (int v : b.locals) structure.push_back({b.first_row + r, v});
    blocks.push_back(std::move(b));
}

std::vector<AD> SpatialFormulation::Impl::local_values(const Block& b, const double* x) const {
    const int n = static_cast<int>(b.locals.size());
    std::vector<AD> v;
    v.reserve(b.locals.size());
    for (int i = 0; i < n; ++i) v.emplace_back(x[b.locals[static_cast<std::size_t>(i)]], n, i);
    return v;
}

kinematics::YawPitchPose<AD> SpatialFormulation::Impl::pose(const Block& b,
                                                            const std::vector<AD>& v) const {
    kinematics::YawPitchShape<AD> shape;
    shape.base = P3(v[0], v[1], v[2]);
    shape.column = has_column ? v[static_cast<std::size_t>(column_var)] : constant(0.0);
    for (int k = 0; k < dof - 1; ++k)
        shape.links.push_back(v[static_cast<std::size_t>(first_link + k)]);
    shape.column_twist = problem.start.arm.column_twist;
    std::vector<AD> pitches;
    for (const auto& [from, to] : b.pitch_locals)
        pitches.push_back(v[static_cast<std::size_t>(from)] +
                          (v[static_cast<std::size_t>(to)] - v[static_cast<std::size_t>(from)]) *
                              constant(b.fraction));
    const auto& branch =
        problem.start.branches[static_cast<std::size_t>(task::stroke_of(task, b.point.primitive))];
    return kinematics::yaw_pitch_pose(shape, constant(b.target), branch, pitches);
}

std::vector<Part> SpatialFormulation::Impl::parts(
    const std::vector<std::pair<P3, P3>>& segs) const {
    return kinematics::pose_clearance_parts(segs, task.robot.link_diameter / 2.0,
                                            task.robot.tool_length);
}

AD SpatialFormulation::Impl::row_value(const Row& r, const kinematics::YawPitchPose<AD>& pose,
                                       const std::vector<std::pair<P3, P3>>& segs,
                                       const std::vector<Part>& prts) const {
    switch (r.kind) {
        case Kind::Reach:
            return pose.elbow_cos;
        case Kind::Axis:
            return pose.axis_distance;
        case Kind::SelfPair: {
            const auto& [p, q] = segs[static_cast<std::size_t>(r.a)];
            const auto& [u, v] = segs[static_cast<std::size_t>(r.b)];
            return segment_distance(p, q, u, v);
        }
        case Kind::SelfEe: {
            const auto& [p, q] = segs[static_cast<std::size_t>(r.a)];
            return point_segment_distance(pose.points.back(), p, q);
        }
        case Kind::Clearance: {
            // A part may vanish when the design moves (a mount or a tool
            // longer than its segment): nothing is left to keep clear.
            const auto part = std::find_if(prts.begin(), prts.end(),
                                           [&](const Part& x) { return x.segment == r.a; });
            if (part == prts.end()) return constant(kInf);
            const auto& [p, q] = segs[static_cast<std::size_t>(part->segment)];
            return obstacle_gap(lerp(p, q, part->from), lerp(p, q, part->to),
                                task.obstacles[static_cast<std::size_t>(r.b)]);
        }
    }
    return constant(0.0);
}

void SpatialFormulation::Impl::evaluate(const double* x) const {
    const std::size_t nv = x0.size();
    if (!cached_x.empty() && std::equal(cached_x.begin(), cached_x.end(), x)) return;
    cached_x.assign(x, x + nv);
    cached_g.assign(row_lower.size(), 0.0);
    cached_jac.assign(structure.size(), 0.0);
    for (const Block& b : blocks) {
        const auto values = local_values(b, x);
        const auto ps = pose(b, values);
        const auto segs = kinematics::pose_segments(ps, has_column);
        const auto prts = parts(segs);
        int entry = b.first_entry;
        for (int r = 0; r < static_cast<int>(b.rows.size()); ++r) {
            AD v = row_value(b.rows[static_cast<std::size_t>(r)], ps, segs, prts);
            double g = v.value();
            // A non-finite value (a vanished part) is reported as satisfied
            // with no derivative; Ipopt would stop at a NaN.
            const bool finite = std::isfinite(g);
            if (!finite) g = 1e3;
            cached_g[static_cast<std::size_t>(b.first_row + r)] = g;
            const auto& d = v.derivatives();
            for (int i = 0; i < static_cast<int>(b.locals.size()); ++i, ++entry) {
                const double dv = finite && i < d.size() ? d[i] : 0.0;
                cached_jac[static_cast<std::size_t>(entry)] = std::isfinite(dv) ? dv : 0.0;
            }
        }
    }
}

SpatialFormulation::SpatialFormulation(const SpatialProblem& problem)
    : impl_(std::make_unique<Impl>(problem)) {
    if (problem.task == nullptr) throw std::invalid_argument("SpatialFormulation: no task");
    impl_->build();
}

SpatialFormulation::~SpatialFormulation() = default;

int SpatialFormulation::num_variables() const { return static_cast<int>(impl_->x0.size()); }
int SpatialFormulation::num_constraints() const {
    return static_cast<int>(impl_->row_lower.size());
}
const std::vector<double>& SpatialFormulation::variable_lower() const { return impl_->lower; }
const std::vector<double>& SpatialFormulation::variable_upper() const { return impl_->upper; }
const std::vector<double>& SpatialFormulation::start() const { return impl_->x0; }
double SpatialFormulation::constraint_lower(int m) const {
    return impl_->row_lower[static_cast<std::size_t>(m)];
}
double SpatialFormulation::constraint_upper(int m) const {
    return impl_->row_upper[static_cast<std::size_t>(m)];
}
const std::string& SpatialFormulation::constraint_label(int m) const {
    return impl_->labels[static_cast<std::size_t>(m)];
}
const std::vector<SmoothProgram::Entry>& SpatialFormulation::jacobian_structure() const {
    return impl_->structure;
}

double SpatialFormulation::eval_objective(const double* x) const {
    const Impl& s = *impl_;
    double f = 0.0;
    if (s.has_column) f += s.problem.column * x[s.column_var];
    for (int k = 0; k < s.dof - 1; ++k) f += x[s.first_link + k];
    const double w = s.problem.margins.sweep_weight;
    const int m = static_cast<int>(s.task.trajectory.size());
    if (s.dof > 3)
        for (int j = 0; j + 1 < m; ++j)
            if (task::has_transition_after(s.task, j))
                for (int h = 0; h < s.dof - 3; ++h) {
                    const double jump = x[s.pitch_var(j + 1, h)] - x[s.pitch_var(j, h) + 1];
                    f += w * jump * jump;
                }
    return f;
}

void SpatialFormulation::eval_gradient(const double* x, double* grad) const {
    const Impl& s = *impl_;
    std::fill(grad, grad + num_variables(), 0.0);
    if (s.has_column) grad[s.column_var] = s.problem.column;
    for (int k = 0; k < s.dof - 1; ++k) grad[s.first_link + k] = 1.0;
    const double w = s.problem.margins.sweep_weight;
    const int m = static_cast<int>(s.task.trajectory.size());
    if (s.dof > 3)
        for (int j = 0; j + 1 < m; ++j)
            if (task::has_transition_after(s.task, j))
                for (int h = 0; h < s.dof - 3; ++h) {
                    const int a = s.pitch_var(j, h) + 1, b = s.pitch_var(j + 1, h);
                    const double jump = x[b] - x[a];
                    grad[b] += 2.0 * w * jump;
                    grad[a] -= 2.0 * w * jump;
                }
}

void SpatialFormulation::eval_constraints(const double* x, double* g) const {
    impl_->evaluate(x);
    std::copy(impl_->cached_g.begin(), impl_->cached_g.end(), g);
}

void SpatialFormulation::eval_jacobian(const double* x, double* values) const {
    impl_->evaluate(x);
    std::copy(impl_->cached_jac.begin(), impl_->cached_jac.end(), values);
}

kinematics::YawPitchDesign SpatialFormulation::design(const std::vector<double>& x) const {
    const Impl& s = *impl_;
    kinematics::YawPitchDesign d = s.problem.start;
    d.arm.base = Vec3(x[0], x[1], x[2]);
    d.arm.column = s.has_column ? x[static_cast<std::size_t>(s.column_var)] : 0.0;
    for (int k = 0; k < s.dof - 1; ++k)
        d.arm.links[static_cast<std::size_t>(k)] = x[static_cast<std::size_t>(s.first_link + k)];
    if (s.dof > 3)
        for (int j = 0; j < static_cast<int>(d.pitches.size()); ++j)
            for (int h = 0; h < s.dof - 3; ++h) {
                auto& hp = d.pitches[static_cast<std::size_t>(j)][static_cast<std::size_t>(h)];
                hp.start = x[static_cast<std::size_t>(s.pitch_var(j, h))];
                hp.end = x[static_cast<std::size_t>(s.pitch_var(j, h) + 1)];
            }
    return d;
}

std::vector<double> SpatialFormulation::variables(const kinematics::YawPitchDesign& d) const {
    const Impl& s = *impl_;
    std::vector<double> x(s.x0.size());
    for (int i = 0; i < 3; ++i) x[static_cast<std::size_t>(i)] = d.arm.base[i];
    if (s.has_column) x[static_cast<std::size_t>(s.column_var)] = d.arm.column;
    for (int k = 0; k < s.dof - 1; ++k)
        x[static_cast<std::size_t>(s.first_link + k)] = d.arm.links[static_cast<std::size_t>(k)];
    if (s.dof > 3)
        for (int j = 0; j < static_cast<int>(d.pitches.size()); ++j)
            for (int h = 0; h < s.dof - 3; ++h) {
                const auto& hp =
                    d.pitches[static_cast<std::size_t>(j)][static_cast<std::size_t>(h)];
                x[static_cast<std::size_t>(s.pitch_var(j, h))] = hp.start;
                x[static_cast<std::size_t>(s.pitch_var(j, h) + 1)] = hp.end;
            }
    return x;
}

}  // namespace modsynth::nlp
