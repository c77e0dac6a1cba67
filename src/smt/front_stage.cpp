#include <modsynth/smt/front_stage.h>

#include <z3++.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>

#include <modsynth/geometry/distance.h>
#include <modsynth/geometry/polygon.h>
#include <modsynth/geometry/primitive.h>
#include <modsynth/kinematics/chain_layout.h>
#include <modsynth/kinematics/clearance_rule.h>
#include <modsynth/run/stopwatch.h>
#include <modsynth/task/part.h>
#include <modsynth/task/strokes.h>
#include <modsynth/text/format.h>
#include <modsynth/text/option_check.h>

#include "part_literals.h"

namespace modsynth::smt {
namespace {

std::string decimal(double v) { return text::format("%.12f", v); }

double to_double(const z3::expr& e) {
    std::string s = e.get_decimal_string(12);
    if (!s.empty() && s.back() == '?') s.pop_back();
    return std::stod(s);
}

std::vector<geometry::Vec2> sample_points(const geometry::Primitive& p, int count) {
    std::vector<geometry::Vec2> out;
    const double len = geometry::length(p);
    for (int i = 0; i <= count; ++i) out.push_back(geometry::point_at(p, len * i / count));
    return out;
}

}  // namespace

bool FrontStageOptions::IsValid(std::string* error) const {
    return text::OptionCheck("FrontStageOptions", error)
        .greater("time_limit", time_limit, 0.0)
        .greater("refined_time_limit", refined_time_limit, 0.0)
        .at_least("refined_max_primitives", refined_max_primitives, 0)
        .at_least("samples_per_primitive", samples_per_primitive, 1)
        .at_least("encoded_points", encoded_points, 1)
        .greater("core_trial_seconds", core_trial_seconds, 0.0)
        .at_least("core_trial_factor", core_trial_factor, 1.0)
        .at_least("all_span_pairs", all_span_pairs, 0)
        .at_least("hull_probe", hull_probe, 1)
        .within("slack", slack, 0.0, 1e-3)
        .ok();
}

struct FrontStage::Impl {
    const task::Task task;  // a copy: callers may pass temporaries
    int dof;
    FrontStageOptions options;
    z3::context ctx;
    // Two solvers over one encoding. `solver` holds the reach-only
    // relaxation, which nlsat decides in milliseconds; `fine` adds the
    // refined families (inner radius, exact critical points), which can take
    // nlsat seconds even when switched off by a literal, so they live apart
    // and are given a budget.
    z3::solver solver;
    z3::solver fine;
    z3::expr bx, by;
    std::vector<z3::expr> r;
    z3::expr elbow;
    std::vector<z3::expr> regions;
    PartLiterals literals{ctx};
    bool refined_level = true;   // `fine` holds the encoding (small enough paths)
    bool unsat_refined = false;  // the last Unsat came from `fine`
    bool incomplete = false;     // encoding stopped at the deadline
    std::optional<z3::model> model;
    int blocked = 0;
    int samples = 1;  // intervals sampled per primitive

    Impl(const task::Task& t, int d, const FrontStageOptions& o)
        : task(t),
          dof(d),
          options(o),
          solver(z3::tactic(ctx, "qfnra-nlsat").mk_solver()),
          fine(z3::tactic(ctx, "qfnra-nlsat").mk_solver()),
          bx(ctx.real_const("base_x")),
          by(ctx.real_const("base_y")),
          elbow(ctx.bool_const("elbow_positive")) {
        // Core tracking must be on before the first assertion.
        set_timeout(solver, options.time_limit);
        set_timeout(fine, options.refined_time_limit);
        const int m = static_cast<int>(task.trajectory.size());
        refined_level = m <= options.refined_max_primitives;
        samples = std::clamp(options.encoded_points / std::max(1, m), 1,
                             std::max(1, options.samples_per_primitive));
        for (int k = 0; k < dof; ++k) {
            std::string name = "r";
            name += std::to_string(k + 1);  // (GCC 12 warns falsely on "r" + string)
            r.push_back(ctx.real_const(name.c_str()));
        }
        encode();
    }

    double seconds_left() const { return options.deadline.remaining(); }
    bool expired() const { return options.deadline.expired(); }

    void set_timeout(z3::solver& s, double seconds) {
        smt::set_timeout(ctx, s, seconds, options.deadline);
    }

    // Constraints of the task itself (not guarded): go to both solvers.
    void add_both(const z3::expr& e) {
        solver.add(e);
        fine.add(e);
    }

    z3::expr num(double v) { return ctx.real_val(decimal(v).c_str()); }

    // A constraint family guarded by the literals of the task parts it uses.
    void require(std::initializer_list<task::TaskPart> parts, const z3::expr& e,
                 bool is_refined = false) {
        const z3::expr guarded = literals.guarded(parts, e);
        if (refined_level) fine.add(guarded);
        if (!is_refined) solver.add(guarded);
    }

    z3::expr dist2(const geometry::Vec2& p) {
        const z3::expr dx = num(p.x()) - bx, dy = num(p.y()) - by;
        return dx * dx + dy * dy;
    }

    // The reach r_1 + ... + r_n as a variable of its own: the reach atoms
    // then involve three variables (base and reach) instead of dof + 2,
    // which keeps nlsat's cell decomposition small.
    z3::expr reach() {
        z3::expr sum = r[0];
        for (int k = 1; k < dof; ++k) sum = sum + r[k];
        z3::expr R = ctx.real_const("reach");
        add_both(R == sum);
        return R;
    }

    void encode() {
        const auto& rs = task.robot;
        const auto diam = task::TaskPart::robot(task::RobotKey::LinkDiameter);
        const kinematics::ClearanceRule rule{rs.link_diameter};
        for (int k = 0; k < dof; ++k) {
            add_both(r[k] > 0);
            require({task::TaskPart::robot(task::RobotKey::MinLinkLength)},
                    r[k] >= num(rs.min_link_length - options.slack));
            require({task::TaskPart::robot(task::RobotKey::MaxLinkLength)},
                    r[k] <= num(rs.max_link_length + options.slack));
        }
        // The EE must stay a diameter away from the link before the last,
        // which it cannot do when the last link is shorter than that.
        require({diam}, r[dof - 1] >= num(rule.self_distance() - options.slack));

        if (!task.base_regions.empty()) {
            z3::expr_vector any(ctx);
            for (std::size_t k = 0; k < task.base_regions.size(); ++k) {
                const task::BaseRegion& b = task.base_regions[k];
                z3::expr in = ctx.bool_const(("in_region_" + std::to_string(k)).c_str());
                regions.push_back(in);
                add_both(z3::implies(in, bx >= num(b.min.x() - options.slack) &&
                                             bx <= num(b.max.x() + options.slack) &&
                                             by >= num(b.min.y() - options.slack) &&
                                             by <= num(b.max.y() + options.slack)));
                any.push_back(in);
            }
            require({task::TaskPart::base_regions()}, z3::mk_or(any));
        }

        for (std::size_t o = 0; o < task.obstacles.size(); ++o) {
            const task::Obstacle& ob = task.obstacles[o];
            const auto name = task::TaskPart::obstacle(static_cast<int>(o));
            const double need = rule.obstacle_distance(ob) - options.slack;
            // Link 1 starts at the base.
            require({name, diam}, dist2(ob.center) >= num(need * need));
            // The last link ends on the path.
            for (std::size_t j = 0; j < task.trajectory.size(); ++j) {
                if (geometry::point_primitive(ob.center, task.trajectory[j]) < need)
                    require({task::TaskPart::primitive(task, static_cast<int>(j)), name, diam},
                            ctx.bool_val(false));
            }
        }

        const z3::expr R = reach();
        for (std::size_t j = 0; j < task.trajectory.size(); ++j) {
            if (j % 64 == 0 && expired()) {
                incomplete = true;
                return;
            }
            encode_primitive(static_cast<int>(j), R);
        }
        encode_spans(R);
    }

    // Two points of the path are never farther apart than twice the reach.
    // Implied by the reach atoms (triangle inequality), so the relaxation is
    // unchanged, but linear in the reach: without a base region nlsat finds
    // such conflicts at once instead of decomposing the whole plane.
    void encode_spans(const z3::expr& R) {
        const int m = static_cast<int>(task.trajectory.size());
        std::vector<std::vector<geometry::Vec2>> pts;
        for (const auto& p : task.trajectory) pts.push_back(sample_points(p, samples));
        if (m > options.all_span_pairs) {
            encode_farthest_spans(R, pts);
            return;
        }
        for (int j = 0; j < m; ++j) {
            for (int k = j; k < m; ++k) {
                double span = 0.0;
                for (const auto& a : pts[j])
                    for (const auto& b : pts[k]) span = std::max(span, (a - b).norm());
                const auto pj = task::TaskPart::primitive(task, j);
                const auto pk = task::TaskPart::primitive(task, k);
                if (j == k) {
                    require({pj}, 2 * R >= num(span - options.slack));
                } else {
                    require({pj, pk}, 2 * R >= num(span - options.slack));
                }
            }
        }
    }

    // One span per primitive: to the primitive owning the hull vertex
    // farthest from it. The widest pair of the path is among these.
    void encode_farthest_spans(const z3::expr& R,
                               const std::vector<std::vector<geometry::Vec2>>& pts) {
        std::vector<geometry::Vec2> all;
        for (const auto& v : pts) all.insert(all.end(), v.begin(), v.end());
        std::vector<geometry::Vec2> hull = geometry::convex_hull(all);
        const std::size_t hull_probe = static_cast<std::size_t>(options.hull_probe);
        if (hull.size() > hull_probe) {
            std::vector<geometry::Vec2> probe;
            for (std::size_t i = 0; i < hull_probe; ++i)
                probe.push_back(hull[i * hull.size() / hull_probe]);
            hull = std::move(probe);
        }
        // Which primitive a hull vertex came from.
        std::vector<int> owner;
        for (const auto& h : hull) {
            int found = 0;
            double best = 1e300;
            for (std::size_t j = 0; j < pts.size(); ++j)
                for (const auto& a : pts[j])
                    if ((a - h).squaredNorm() < best)
                        best = (a - h).squaredNorm(), found = static_cast<int>(j);
            owner.push_back(found);
        }
        for (std::size_t j = 0; j < pts.size(); ++j) {
            if (j % 64 == 0 && expired()) {
                incomplete = true;
                return;
            }
            double span = 0.0;
            int partner = static_cast<int>(j);
            for (std::size_t h = 0; h < hull.size(); ++h)
                for (const auto& a : pts[j])
                    if ((a - hull[h]).norm() > span)
                        span = (a - hull[h]).norm(), partner = owner[h];
            const auto pj = task::TaskPart::primitive(task, static_cast<int>(j));
            if (partner == static_cast<int>(j)) {
                require({pj}, 2 * R >= num(span - options.slack));
            } else {
                require({pj, task::TaskPart::primitive(task, partner)},
                        2 * R >= num(span - options.slack));
            }
        }
    }

    void encode_primitive(int j, const z3::expr& R) {
        const geometry::Primitive& p = task.trajectory[j];
        const auto name = task::TaskPart::primitive(task, j);
        const auto diam = task::TaskPart::robot(task::RobotKey::LinkDiameter);
        const kinematics::ClearanceRule rule{task.robot.link_diameter};
        const double d2 = rule.self_distance() * rule.self_distance() - options.slack;
        const auto pts = sample_points(p, samples);
        // A line's closest point to the base is an end or the foot of the
        // perpendicular, which the exact clause below covers: the inner
        // atoms at its other samples would only repeat it.
        bool exact_closest = false;
        switch (p.kind) {
            case geometry::PrimitiveKind::Line:
                exact_closest = true;
                break;
            case geometry::PrimitiveKind::Arc:
            case geometry::PrimitiveKind::Circle:
                break;
        }
        for (std::size_t i = 0; i < pts.size(); ++i) {
            const z3::expr dv = dist2(pts[i]);
            require({name}, dv <= R * R + num(options.slack));
            const bool end = i == 0 || i + 1 == pts.size();
            if (!kinematics::has_proximal_link(dof) && (end || !exact_closest)) {
                require({name}, dv + num(options.slack) >= (r[0] - r[1]) * (r[0] - r[1]), true);
                require({name, diam}, dv >= num(d2), true);
            }
        }
        // Only necessary conditions for *any* robot of this joint count may
        // enter: an unsat answer is reported as a proof. (With three joints
        // modsynth keeps the proximal link still during a primitive, but a
        // general arm need not, so that restriction stays out of here.)
        if (kinematics::has_proximal_link(dof)) return;
        switch (p.kind) {
            case geometry::PrimitiveKind::Line: {
                // Exact critical point of a line: if the foot of the perpendicular
                // from the base lies inside the segment, it is the closest point.
                const geometry::Vec2 d = p.end - p.start;
                const z3::expr t =
                    (bx - num(p.start.x())) * num(d.x()) + (by - num(p.start.y())) * num(d.y());
                const z3::expr cr =
                    num(d.x()) * (by - num(p.start.y())) - num(d.y()) * (bx - num(p.start.x()));
                const double l2 = d.squaredNorm();
                // A clause, not a Boolean per line naming the interior case: the
                // same condition, but nlsat no longer branches on one more
                // variable per line (with 70 lines the refined check ran out of
                // its budget instead of answering in a fraction of a second).
                const z3::expr outside = t <= 0 || t >= num(l2);
                require({name},
                        outside ||
                            cr * cr + num(options.slack) >= (r[0] - r[1]) * (r[0] - r[1]) * num(l2),
                        true);
                require({name, diam}, outside || cr * cr >= num(d2 * l2), true);
                break;
            }
            case geometry::PrimitiveKind::Circle: {
                // Exact for a circle of radius rc about c: the farthest point is
                // |b - c| + rc away, the closest ||b - c| - rc|. Written in
                // D = |b - c|^2 alone: no variable for |b - c| and no Boolean
                // for "inside", which nlsat would have to decide per circle.
                const z3::expr D = dist2(p.center);
                const double rc = p.radius;
                const z3::expr far = R + num(options.slack - rc);
                require({name}, far >= 0 && D <= far * far, true);
                // ||b - c| - rc| >= g, for g > 0: outside by g or inside by g.
                const auto gap_at_least = [&](const z3::expr& g) {
                    return D >= (num(rc) + g) * (num(rc) + g) ||
                           (g <= num(rc) && D <= (num(rc) - g) * (num(rc) - g));
                };
                const z3::expr e = r[0] - r[1];
                for (const z3::expr& g : {e - num(options.slack), -e - num(options.slack)})
                    require({name}, g <= 0 || gap_at_least(g), true);
                const double self = rule.self_distance() - 2 * options.slack;
                if (self > 0) require({name, diam}, gap_at_least(num(self)), true);
                break;
            }
            case geometry::PrimitiveKind::Arc:
                break;  // sampled points only
        }
    }

    Skeleton skeleton() {
        assert(model.has_value());  // only after a Sat check
        const z3::model& m = *model;
        Skeleton s;
        s.dof = dof;
        s.base = geometry::Vec2(to_double(m.eval(bx, true)), to_double(m.eval(by, true)));
        for (const auto& rk : r) s.link_lengths.push_back(to_double(m.eval(rk, true)));
        s.elbow = m.eval(elbow, true).is_true() ? 1 : -1;
        for (std::size_t k = 0; k < regions.size(); ++k) {
            if (m.eval(regions[k], true).is_true()) {
                s.base_region = static_cast<int>(k);
                break;
            }
        }
        return s;
    }

    z3::expr_vector assumptions() const { return literals.all(); }

    FrontStage::Result check() {
        if (incomplete || expired()) return Result::Unknown;
        set_timeout(solver, options.time_limit);
        const z3::check_result coarse = smt::check(ctx, solver, assumptions(), options.deadline);
        if (coarse != z3::sat) {
            unsat_refined = false;
            return coarse == z3::unsat ? Result::Unsat : Result::Unknown;
        }
        model = solver.get_model();
        if (kinematics::has_proximal_link(dof) || !refined_level || expired())
            return Result::Sat;  // no refined families for these joint counts or this size
        // Once a skeleton is blocked an unsat answer proves nothing, and the
        // coarse model names the next skeleton as well.
        if (blocked > 0 && !options.refine_after_block) return Result::Sat;
        set_timeout(fine, std::min(options.time_limit, options.refined_time_limit));
        const z3::check_result refined = smt::check(ctx, fine, assumptions(), options.deadline);
        if (refined == z3::unsat) {
            unsat_refined = true;
            return Result::Unsat;
        }
        if (refined == z3::sat) model = fine.get_model();
        return Result::Sat;  // an undecided refined level leaves the coarse model
    }
};

FrontStage::FrontStage(const task::Task& task, int dof, const FrontStageOptions& options)
    : impl_((text::require_valid(options), std::make_unique<Impl>(task, dof, options))) {}

FrontStage::~FrontStage() = default;

FrontStage::Result FrontStage::check() { return impl_->check(); }

Skeleton FrontStage::skeleton() const { return impl_->skeleton(); }

void FrontStage::block(const Skeleton& s) {
    Impl& m = *impl_;
    z3::expr same = s.elbow > 0 ? m.elbow : !m.elbow;
    if (s.base_region >= 0) same = same && m.regions[s.base_region];
    m.add_both(!same);
    ++m.blocked;
}

bool FrontStage::exhausted_by_blocking() const { return impl_->blocked > 0; }

std::vector<task::TaskPart> FrontStage::minimal_core() {
    Impl& m = *impl_;
    z3::solver& s = m.unsat_refined ? m.fine : m.solver;
    const CoreBudget budget{m.unsat_refined ? m.options.refined_time_limit : m.options.time_limit,
                            m.options.core_trial_seconds, m.options.core_trial_factor};
    return m.literals.parts_of(
        smt::minimal_core(m.ctx, s, m.assumptions(), budget, m.options.deadline));
}

bool FrontStage::conflicts(const std::vector<task::TaskPart>& parts) {
    Impl& m = *impl_;
    const z3::expr_vector a = m.literals.of(parts);
    if (m.incomplete || m.expired()) return false;
    m.set_timeout(m.solver, m.options.time_limit);
    if (smt::check(m.ctx, m.solver, a, m.options.deadline) == z3::unsat) return true;
    if (kinematics::has_proximal_link(m.dof) || !m.refined_level) return false;
    m.set_timeout(m.fine, std::min(m.options.time_limit, m.options.refined_time_limit));
    return smt::check(m.ctx, m.fine, a, m.options.deadline) == z3::unsat;
}

std::string FrontStage::smtlib() const {
    return impl_->literals.script(impl_->refined_level ? impl_->fine : impl_->solver);
}

std::string FrontStage::reason_unknown() const {
    if (impl_->incomplete) return "time limit reached while encoding";
    if (impl_->expired()) return "time limit reached";
    return impl_->solver.reason_unknown();
}

}  // namespace modsynth::smt
