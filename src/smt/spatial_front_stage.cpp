#include <modsynth/smt/spatial_front_stage.h>

#include <z3++.h>

#include <algorithm>
#include <cmath>
#include <map>

#include <modsynth/geometry/primitive3.h>
#include <modsynth/geometry/vec.h>
#include <modsynth/task/part.h>
#include <modsynth/task/spatial_strokes.h>
#include <modsynth/text/format.h>
#include <modsynth/text/option_check.h>

#include "part_literals.h"

namespace modsynth::smt {
namespace {

using geometry::Vec3;
using task::RobotKey;
using task::TaskPart;

std::string decimal(double v) { return text::format("%.12f", v); }

double to_double(const z3::expr& e) {
    std::string s = e.get_decimal_string(12);
    if (!s.empty() && s.back() == '?') s.pop_back();
    return std::stod(s);
}

/// Within 1e-9 of one of the angles, modulo a full turn.
bool is_angle(double alpha, double target) {
    return std::abs(std::remainder(alpha - target, geometry::kTau)) <= 1e-9;
}

}  // namespace

bool SpatialFrontStageOptions::IsValid(std::string* error) const {
    return text::OptionCheck("SpatialFrontStageOptions", error)
        .greater("time_limit", time_limit, 0.0)
        .at_least("samples_per_primitive", samples_per_primitive, 1)
        .at_least("encoded_points", encoded_points, 1)
        .greater("height_tolerance", height_tolerance, 0.0)
        .greater("core_trial_seconds", core_trial_seconds, 0.0)
        .at_least("core_trial_factor", core_trial_factor, 1.0)
        .within("slack", slack, 0.0, 1e-3)
        .ok();
}

struct SpatialFrontStage::Impl {
    const task::SpatialTask task;  // a copy: callers may pass temporaries
    int dof;
    SpatialFrontStageOptions options;
    z3::context ctx;
    // `relaxation` holds the conditions for any chain (its unsat answers
    // are proofs); `pattern` those of one arm family's skeleton at a time.
    z3::solver relaxation;
    z3::solver pattern;
    PartLiterals literals{ctx};
    std::vector<z3::expr> regions;          // the relaxation's region choices
    std::vector<z3::expr> pattern_regions;  // the pattern's
    z3::expr bx, by, bz;
    std::vector<std::vector<Vec3>> points;  // sampled, per primitive
    std::vector<std::string> patterns;      // each one checked, as SMT-LIB
    std::string unknown;

    Impl(const task::SpatialTask& t, int d, const SpatialFrontStageOptions& o)
        : task(t),
          dof(d),
          options(o),
          relaxation(z3::tactic(ctx, "qfnra-nlsat").mk_solver()),
          pattern(z3::tactic(ctx, "qfnra-nlsat").mk_solver()),
          bx(ctx.real_const("base_x")),
          by(ctx.real_const("base_y")),
          bz(ctx.real_const("base_z")) {
        set_timeout(relaxation, options.time_limit);
        set_timeout(pattern, options.time_limit);
        const int m = static_cast<int>(task.trajectory.size());
        const int samples =
            std::clamp(options.encoded_points / std::max(1, m), 1, options.samples_per_primitive);
        for (const auto& p : task.trajectory) {
            std::vector<Vec3> v;
            const double len = geometry::length(p);
            for (int i = 0; i <= samples; ++i)
                v.push_back(geometry::point_at(p, len * i / samples));
            points.push_back(std::move(v));
        }
        encode_relaxation();
        pattern_regions = encode_regions(pattern, "pattern_region_");
    }

    double seconds_left() const { return options.deadline.remaining(); }
    bool expired() const { return options.deadline.expired(); }

    void set_timeout(z3::solver& s, double seconds) {
        smt::set_timeout(ctx, s, seconds, options.deadline);
    }

    z3::expr num(double v) { return ctx.real_val(decimal(v).c_str()); }

    void require(z3::solver& s, std::initializer_list<task::TaskPart> parts, const z3::expr& e) {
        s.add(literals.guarded(parts, e));
    }

    z3::expr_vector assumptions() const { return literals.all(); }

    /// The base in one of the task's boxes, when it has any.
    std::vector<z3::expr> encode_regions(z3::solver& s, const char* prefix) {
        std::vector<z3::expr> out;
        if (task.base_regions.empty()) return out;
        z3::expr_vector any(ctx);
        const double e = options.slack;
        for (std::size_t k = 0; k < task.base_regions.size(); ++k) {
            const geometry::Box3& b = task.base_regions[k];
            z3::expr in = ctx.bool_const((prefix + std::to_string(k)).c_str());
            s.add(z3::implies(in, bx >= num(b.min.x() - e) && bx <= num(b.max.x() + e) &&
                                      by >= num(b.min.y() - e) && by <= num(b.max.y() + e) &&
                                      bz >= num(b.min.z() - e) && bz <= num(b.max.z() + e)));
            out.push_back(in);
            any.push_back(in);
        }
        require(s, {TaskPart::base_regions()}, z3::mk_or(any));
        return out;
    }

    z3::expr dist2(const Vec3& p, const z3::expr& sz) {
        const z3::expr dx = num(p.x()) - bx, dy = num(p.y()) - by, dz = num(p.z()) - sz;
        return dx * dx + dy * dy + dz * dz;
    }

    void encode_relaxation() {
        regions = encode_regions(relaxation, "in_region_");
        // No EE of n joints gets farther from its base than the sum of
        // |a_k| + |d_k|.
        const double reach = dof * 2.0 * task.robot.max_link_length + options.slack;
        for (std::size_t j = 0; j < points.size(); ++j) {
            const TaskPart part = task::primitive_part(task, static_cast<int>(j));
            for (const Vec3& p : points[j])
                require(relaxation,
                        {part, TaskPart::robot(RobotKey::MaxLinkLength),
                         TaskPart::robot(RobotKey::Dof)},
                        dist2(p, bz) <= num(reach * reach));
        }
        // With every twist 0 or pi, every joint axis is vertical: the EE
        // stays at the base's height plus sum +-d_k.
        const auto& tw = task.robot.twists;
        if (std::all_of(tw.begin(), tw.end(),
                        [](double a) { return is_angle(a, 0.0) || is_angle(a, geometry::kPi); })) {
            const z3::expr h = ctx.real_const("ee_height");
            const double tol = options.height_tolerance + options.slack;
            for (std::size_t j = 0; j < points.size(); ++j) {
                const TaskPart part = task::primitive_part(task, static_cast<int>(j));
                for (const Vec3& p : points[j])
                    require(relaxation, {part, TaskPart::robot(RobotKey::Twists)},
                            h - num(p.z()) <= num(tol) && num(p.z()) - h <= num(tol));
            }
        }
    }

    z3::expr translate(const smt::Term::Node& t) {
        using Op = smt::Term::Op;
        switch (t.op) {
            case Op::Constant:
                return num(t.value);
            case Op::Variable:
                return ctx.real_const(t.name.c_str());
            case Op::Add:
                return translate(*t.a) + translate(*t.b);
            case Op::Sub:
                return translate(*t.a) - translate(*t.b);
            case Op::Mul:
                return translate(*t.a) * translate(*t.b);
            case Op::Neg:
                return -translate(*t.a);
        }
        return num(0.0);
    }

    z3::expr translate(const smt::Condition::Node& c) {
        using Op = smt::Condition::Op;
        switch (c.op) {
            case Op::Le:
                return translate(*c.left) <= translate(*c.right);
            case Op::Ge:
                return translate(*c.left) >= translate(*c.right);
            case Op::Eq:
                return translate(*c.left) == translate(*c.right);
            case Op::And:
                return translate(*c.a) && translate(*c.b);
            case Op::Or:
                return translate(*c.a) || translate(*c.b);
            case Op::Not:
                return !translate(*c.a);
            case Op::Boolean:
                return ctx.bool_const(c.name.c_str());
            case Op::True:
                return ctx.bool_val(true);
        }
        return ctx.bool_val(true);
    }

    Result check() {
        if (expired()) {
            unknown = "time limit reached";
            return Result::Unknown;
        }
        set_timeout(relaxation, options.time_limit);
        switch (smt::check(ctx, relaxation, assumptions(), options.deadline)) {
            case z3::sat:
                return Result::Sat;
            case z3::unsat:
                return Result::Unsat;
            default:
                unknown = relaxation.reason_unknown();
                return Result::Unknown;
        }
    }
};

SpatialFrontStage::SpatialFrontStage(const task::SpatialTask& task, int dof,
                                     const SpatialFrontStageOptions& options)
    : impl_((text::require_valid(options), std::make_unique<Impl>(task, dof, options))) {}

SpatialFrontStage::~SpatialFrontStage() = default;

SpatialFrontStage::Result SpatialFrontStage::check() { return impl_->check(); }

std::vector<task::TaskPart> SpatialFrontStage::minimal_core() {
    Impl& m = *impl_;
    const CoreBudget budget{m.options.time_limit, m.options.core_trial_seconds,
                            m.options.core_trial_factor};
    return m.literals.parts_of(
        smt::minimal_core(m.ctx, m.relaxation, m.assumptions(), budget, m.options.deadline));
}

bool SpatialFrontStage::conflicts(const std::vector<task::TaskPart>& parts) {
    Impl& m = *impl_;
    if (m.expired()) return false;
    m.set_timeout(m.relaxation, m.options.time_limit);
    return smt::check(m.ctx, m.relaxation, m.literals.of(parts), m.options.deadline) == z3::unsat;
}

const std::vector<std::vector<geometry::Vec3>>& SpatialFrontStage::sampled_points() const {
    return impl_->points;
}

std::optional<std::vector<double>> SpatialFrontStage::pattern_holds(const Pattern& p,
                                                                    int base_region) {
    Impl& m = *impl_;
    if (m.expired()) return std::nullopt;
    m.pattern.push();
    for (const auto& g : p.conditions) {
        const z3::expr e = m.translate(g.condition.node());
        if (g.parts.empty()) {
            m.pattern.add(e);
        } else {
            z3::expr_vector guards(m.ctx);
            for (const auto& part : g.parts) guards.push_back(m.literals.literal(part));
            m.pattern.add(z3::implies(z3::mk_and(guards), e));
        }
    }
    if (m.patterns.size() < 64) m.patterns.push_back(m.literals.script(m.pattern));
    z3::expr_vector a = m.assumptions();
    if (base_region >= 0 && !m.pattern_regions.empty())
        a.push_back(m.pattern_regions[static_cast<std::size_t>(base_region)]);
    m.set_timeout(m.pattern, m.options.time_limit);
    std::optional<std::vector<double>> out;
    if (smt::check(m.ctx, m.pattern, a, m.options.deadline) == z3::sat) {
        const z3::model model = m.pattern.get_model();
        out.emplace();
        for (const std::string& name : p.reported)
            out->push_back(to_double(model.eval(m.ctx.real_const(name.c_str()), true)));
    }
    m.pattern.pop();
    return out;
}

std::string SpatialFrontStage::reason_unknown() const { return impl_->unknown; }

std::string SpatialFrontStage::smtlib() const {
    std::string out = "; relaxation (any chain)\n" + impl_->literals.script(impl_->relaxation);
    for (const std::string& p : impl_->patterns) out += "; an arm family's pattern\n" + p;
    return out;
}

}  // namespace modsynth::smt
