#include <modsynth/nlp/spatial_formulation.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <modsynth/geometry/primitive3.h>
#include <modsynth/kinematics/pose_rules.h>
#include <modsynth/task/spatial_strokes.h>
#include <modsynth/text/format.h>

namespace modsynth::nlp {
namespace {

using geometry::Vec3;
using kinematics::AD;
using kinematics::ArmPose;
using kinematics::PoseRule;
constexpr double kInf = std::numeric_limits<double>::infinity();

using P3 = kinematics::Point3<AD>;
using Part = kinematics::PosePart<AD>;

/// One point's rows: the family's pose limits first (their count is the
/// family's, the same at every point), then formats.md's rules.
struct Block {
    SpatialPoint point;
    Vec3 target = Vec3::Zero();
    std::vector<int> locals;  ///< global index of each local variable
    /// Local index of each free number at the two ends of the
    /// interpolation (start/end of the primitive, or the two sides of the
    /// join in a transition), and the fraction between them.
    std::vector<std::pair<int, int>> along_locals;
    double fraction = 0.0;
    int limits = 0;
    std::vector<PoseRule> rules;
    int first_row = 0;
    int first_entry = 0;
};

std::string where(const task::SpatialTask& task, const SpatialPoint& p) {
    if (p.transition)
        return text::format("the transition after %s at %.3f of its sweep",
                            task::part_name(task, p.primitive).c_str(), p.t);
    return text::format("%s at %.4f m", task::part_name(task, p.primitive).c_str(), p.s);
}

}  // namespace

struct SpatialFormulation::Impl {
    const task::SpatialTask& task;
    SpatialProblem problem;
    const kinematics::ArmModel& model;
    int values = 0;  ///< the shape's values
    int along = 0;   ///< free numbers per primitive end
    int first_along = 0;
    std::vector<double> lower, upper, x0;
    std::vector<Block> blocks;
    /// The design rows: their first row and first Jacobian entry.
    int first_design_row = 0;
    int first_design_entry = 0;
    std::vector<double> row_lower, row_upper;
    std::vector<std::string> labels;
    std::vector<Entry> structure;
    // The last evaluation, shared by eval_constraints and eval_jacobian.
    mutable std::vector<double> cached_x, cached_g, cached_jac;

    explicit Impl(const SpatialProblem& p) : task(*p.task), problem(p), model(*p.start.model) {}

    int along_var(int j, int h) const { return first_along + 2 * along * j + h; }

    void build();
    void add_block(const SpatialPoint& point, const std::vector<double>& x);
    void add_design_rows();
    std::vector<AD> local_values(const Block& b, const double* x) const;
    ArmPose<AD> pose(const Block& b, const std::vector<AD>& v) const;
    void evaluate(const double* x) const;
};

void SpatialFormulation::Impl::build() {
    const kinematics::ArmDesign& d = problem.start;
    const FamilyBounds& f = problem.family;
    values = static_cast<int>(d.shape.values.size());
    along = model.along_count(d.dof(), d.shape.variant);
    const int m = static_cast<int>(task.trajectory.size());
    if (static_cast<int>(f.values.size()) != values ||
        static_cast<int>(f.length_weights.size()) != values ||
        static_cast<int>(d.branches.size()) != task::stroke_count(task) ||
        (along > 0 && static_cast<int>(d.along.size()) != m))
        throw std::invalid_argument("SpatialFormulation: the start design does not fit the task");
    for (int i = 0; i < 3; ++i) {
        lower.push_back(problem.base_box ? problem.base_box->min[i] : -kInf);
        upper.push_back(problem.base_box ? problem.base_box->max[i] : kInf);
        x0.push_back(d.shape.base[i]);
    }
    for (int k = 0; k < values; ++k) {
        lower.push_back(f.values[static_cast<std::size_t>(k)].first);
        upper.push_back(f.values[static_cast<std::size_t>(k)].second);
        x0.push_back(d.shape.values[static_cast<std::size_t>(k)]);
    }
    first_along = static_cast<int>(x0.size());
    if (along > 0) {
        for (int j = 0; j < m; ++j) {
            const auto& v = d.along[static_cast<std::size_t>(j)];
            if (static_cast<int>(v.size()) != 2 * along)
                throw std::invalid_argument(
                    "SpatialFormulation: the start design's free numbers do not fit the task");
            for (double a : v) {
                lower.push_back(f.along.first);
                upper.push_back(f.along.second);
                x0.push_back(a);
            }
        }
    }
    for (std::size_t i = 0; i < x0.size(); ++i) x0[i] = std::clamp(x0[i], lower[i], upper[i]);
    for (const SpatialPoint& p : problem.points) add_block(p, x0);
    add_design_rows();
}

void SpatialFormulation::Impl::add_block(const SpatialPoint& point, const std::vector<double>& x) {
    Block b;
    b.point = point;
    const geometry::Primitive3& prim = task.trajectory[static_cast<std::size_t>(point.primitive)];
    const double length = geometry::length(prim);
    b.target = point.transition ? geometry::end_point(prim) : geometry::point_at(prim, point.s);
    for (int i = 0; i < first_along; ++i) b.locals.push_back(i);
    if (along > 0) {
        b.fraction = point.transition ? point.t : (length > 0.0 ? point.s / length : 0.0);
        for (int h = 0; h < along; ++h) {
            // A primitive's start value and end value; across a join the end
            // of this primitive and the start of the next.
            const int from = point.transition ? along_var(point.primitive, along + h)
                                              : along_var(point.primitive, h);
            const int to = point.transition ? along_var(point.primitive + 1, h)
                                            : along_var(point.primitive, along + h);
            b.along_locals.push_back(
                {static_cast<int>(b.locals.size()), static_cast<int>(b.locals.size()) + 1});
            b.locals.push_back(from);
            b.locals.push_back(to);
        }
    }
    if (static_cast<int>(b.locals.size()) > kinematics::kMaxLocalVariables)
        throw std::invalid_argument("SpatialFormulation: a point depends on more than " +
                                    std::to_string(kinematics::kMaxLocalVariables) + " variables");
    // Which rows: every pose limit and self-collision rule; the obstacles
    // near the chain at the start.
    const auto v = local_values(b, x.data());
    const ArmPose<AD> ps = pose(b, v);
    const std::string at = where(task, point);
    const double diameter = task.robot.link_diameter;
    const auto& mg = problem.margins;
    const int first = static_cast<int>(row_lower.size());
    auto add = [&](double lo, double hi, std::string label) {
        row_lower.push_back(lo);
        row_upper.push_back(hi);
        labels.push_back(std::move(label) + " at " + at);
    };
    for (const auto& limit : ps.limits) add(limit.lower, limit.upper, limit.what);
    b.limits = static_cast<int>(ps.limits.size());
    const int segments = static_cast<int>(ps.points.size()) - 1;
    const auto link = [&](int k) { return ps.links[static_cast<std::size_t>(k)]; };
    for (const PoseRule& r : kinematics::self_rules(segments)) {
        b.rules.push_back(r);
        add(diameter + mg.self, kInf,
            r.kind == PoseRule::Kind::SegmentsApart
                ? text::format("links %d and %d apart", link(r.a), link(r.b))
                : text::format("EE away from link %d", link(r.a)));
    }
    const auto parts = kinematics::pose_clearance_parts(ps, diameter / 2.0, task.robot.tool_length);
    for (const Part& part : parts) {
        for (int o = 0; o < static_cast<int>(task.obstacles.size()); ++o) {
            const PoseRule r{PoseRule::Kind::Clearance, part.segment, o};
            if (kinematics::rule_value(r, ps, parts, task.obstacles).value() > mg.near) continue;
            b.rules.push_back(r);
            add(diameter / 2.0 + mg.clearance, kInf,
                text::format("clearance of link %d to obstacles[%d]", link(part.segment), o));
        }
    }
    b.first_row = first;
    b.first_entry = static_cast<int>(structure.size());
    const int rows = static_cast<int>(row_lower.size()) - first;
    for (int r = 0; r < rows; ++r)
        for (int var : b.locals) structure.push_back({b.first_row + r, var});
    blocks.push_back(std::move(b));
}

void SpatialFormulation::Impl::add_design_rows() {
    first_design_row = static_cast<int>(row_lower.size());
    first_design_entry = static_cast<int>(structure.size());
    for (const kinematics::DesignRow& r : problem.family.rows) {
        const int row = static_cast<int>(row_lower.size());
        row_lower.push_back(r.lower);
        row_upper.push_back(r.upper);
        labels.push_back(r.what);
        for (int i = 0; i < first_along; ++i) structure.push_back({row, i});
    }
}

std::vector<AD> SpatialFormulation::Impl::local_values(const Block& b, const double* x) const {
    const int n = static_cast<int>(b.locals.size());
    std::vector<AD> v;
    v.reserve(b.locals.size());
    for (int i = 0; i < n; ++i) v.emplace_back(x[b.locals[static_cast<std::size_t>(i)]], n, i);
    return v;
}

ArmPose<AD> SpatialFormulation::Impl::pose(const Block& b, const std::vector<AD>& v) const {
    kinematics::ArmShape<AD> shape;
    shape.dof = problem.start.dof();
    shape.variant = problem.start.shape.variant;
    shape.base = P3(v[0], v[1], v[2]);
    shape.values.assign(v.begin() + 3, v.begin() + first_along);
    std::vector<AD> numbers;
    for (const auto& [from, to] : b.along_locals)
        numbers.push_back(v[static_cast<std::size_t>(from)] +
                          (v[static_cast<std::size_t>(to)] - v[static_cast<std::size_t>(from)]) *
                              AD(b.fraction));
    kinematics::PoseTarget<AD> target;
    target.point = P3(AD(b.target.x()), AD(b.target.y()), AD(b.target.z()));
    const int branch =
        problem.start.branches[static_cast<std::size_t>(task::stroke_of(task, b.point.primitive))];
    return model.pose(shape, target, branch, numbers, problem.margins.pose());
}

void SpatialFormulation::Impl::evaluate(const double* x) const {
    const std::size_t nv = x0.size();
    if (!cached_x.empty() && std::equal(cached_x.begin(), cached_x.end(), x)) return;
    cached_x.assign(x, x + nv);
    cached_g.assign(row_lower.size(), 0.0);
    cached_jac.assign(structure.size(), 0.0);
    for (const Block& b : blocks) {
        const auto v = local_values(b, x);
        const ArmPose<AD> ps = pose(b, v);
        const auto parts = kinematics::pose_clearance_parts(ps, task.robot.link_diameter / 2.0,
                                                            task.robot.tool_length);
        int entry = b.first_entry;
        const int rows = b.limits + static_cast<int>(b.rules.size());
        for (int r = 0; r < rows; ++r) {
            const AD value = r < b.limits ? ps.limits[static_cast<std::size_t>(r)].value
                                          : kinematics::rule_value(
                                                b.rules[static_cast<std::size_t>(r - b.limits)], ps,
                                                parts, task.obstacles);
            double g = value.value();
            // A non-finite value (a vanished part) is reported as satisfied
            // with no derivative; Ipopt would stop at a NaN.
            const bool finite = std::isfinite(g);
            if (!finite) g = 1e3;
            cached_g[static_cast<std::size_t>(b.first_row + r)] = g;
            const auto& d = value.derivatives();
            for (int i = 0; i < static_cast<int>(b.locals.size()); ++i, ++entry) {
                const double dv = finite && i < d.size() ? d[i] : 0.0;
                cached_jac[static_cast<std::size_t>(entry)] = std::isfinite(dv) ? dv : 0.0;
            }
        }
    }
    int entry = first_design_entry;
    for (std::size_t r = 0; r < problem.family.rows.size(); ++r) {
        const kinematics::DesignRow& row = problem.family.rows[r];
        double g = 0.0;
        for (int i = 0; i < first_along; ++i, ++entry) {
            const double c = i < 3 ? row.base[i]
                                   : (static_cast<std::size_t>(i - 3) < row.values.size()
                                          ? row.values[static_cast<std::size_t>(i - 3)]
                                          : 0.0);
            g += c * x[i];
            cached_jac[static_cast<std::size_t>(entry)] = c;
        }
        cached_g[static_cast<std::size_t>(first_design_row) + r] = g;
    }
}

SpatialFormulation::SpatialFormulation(const SpatialProblem& problem)
    : impl_((problem.task == nullptr || problem.start.model == nullptr)
                ? throw std::invalid_argument("SpatialFormulation: no task or no arm family")
                : std::make_unique<Impl>(problem)) {
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
    for (int k = 0; k < s.values; ++k)
        f += s.problem.family.length_weights[static_cast<std::size_t>(k)] * x[3 + k];
    const double w = s.problem.margins.sweep_weight;
    const int m = static_cast<int>(s.task.trajectory.size());
    for (int j = 0; j + 1 < m && s.along > 0; ++j)
        if (task::has_transition_after(s.task, j))
            for (int h = 0; h < s.along; ++h) {
                const double jump = x[s.along_var(j + 1, h)] - x[s.along_var(j, s.along + h)];
                f += w * jump * jump;
            }
    return f;
}

void SpatialFormulation::eval_gradient(const double* x, double* grad) const {
    const Impl& s = *impl_;
    std::fill(grad, grad + num_variables(), 0.0);
    for (int k = 0; k < s.values; ++k)
        grad[3 + k] = s.problem.family.length_weights[static_cast<std::size_t>(k)];
    const double w = s.problem.margins.sweep_weight;
    const int m = static_cast<int>(s.task.trajectory.size());
    for (int j = 0; j + 1 < m && s.along > 0; ++j)
        if (task::has_transition_after(s.task, j))
            for (int h = 0; h < s.along; ++h) {
                const int a = s.along_var(j, s.along + h), b = s.along_var(j + 1, h);
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

kinematics::ArmDesign SpatialFormulation::design(const std::vector<double>& x) const {
    const Impl& s = *impl_;
    kinematics::ArmDesign d = s.problem.start;
    d.shape.base = Vec3(x[0], x[1], x[2]);
    for (int k = 0; k < s.values; ++k)
        d.shape.values[static_cast<std::size_t>(k)] = x[static_cast<std::size_t>(3 + k)];
    if (s.along > 0)
        for (std::size_t j = 0; j < d.along.size(); ++j)
            for (int h = 0; h < 2 * s.along; ++h)
                d.along[j][static_cast<std::size_t>(h)] =
                    x[static_cast<std::size_t>(s.along_var(static_cast<int>(j), h))];
    return d;
}

std::vector<double> SpatialFormulation::variables(const kinematics::ArmDesign& d) const {
    const Impl& s = *impl_;
    std::vector<double> x(s.x0.size());
    for (int i = 0; i < 3; ++i) x[static_cast<std::size_t>(i)] = d.shape.base[i];
    for (int k = 0; k < s.values; ++k)
        x[static_cast<std::size_t>(3 + k)] = d.shape.values[static_cast<std::size_t>(k)];
    if (s.along > 0)
        for (std::size_t j = 0; j < d.along.size(); ++j)
            for (int h = 0; h < 2 * s.along; ++h)
                x[static_cast<std::size_t>(s.along_var(static_cast<int>(j), h))] =
                    d.along[j][static_cast<std::size_t>(h)];
    return x;
}

}  // namespace modsynth::nlp
