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

namespace modsynth::smt {
namespace {

using geometry::Vec3;
using task::RobotKey;
using task::TaskPart;

const TaskPart kMinLink = TaskPart::robot(RobotKey::MinLinkLength);
const TaskPart kMaxLink = TaskPart::robot(RobotKey::MaxLinkLength);

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
        .at_least("axis_margin", axis_margin, 0.0)
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
    // are proofs); `pattern` those of the yaw column and pitch links.
    z3::solver relaxation;
    z3::solver pattern;
    std::vector<task::TaskPart> names;  // parts with an assumption literal, in creation order
    std::map<task::TaskPart, z3::expr> literal_of;
    std::vector<z3::expr> regions;          // the relaxation's region choices
    std::vector<z3::expr> pattern_regions;  // the pattern's
    z3::expr up, down, none;                // the pattern's column sign
    z3::expr bx, by, bz, column;
    std::vector<z3::expr> links;            // a_2, a_3 and the hand's sum
    std::vector<std::vector<Vec3>> points;  // sampled, per primitive
    int column_twist = 0;                   // +-1 when robot.twists allows the pattern
    std::string unknown;

    Impl(const task::SpatialTask& t, int d, const SpatialFrontStageOptions& o)
        : task(t),
          dof(d),
          options(o),
          relaxation(z3::tactic(ctx, "qfnra-nlsat").mk_solver()),
          pattern(z3::tactic(ctx, "qfnra-nlsat").mk_solver()),
          up(ctx.bool_const("column_up")),
          down(ctx.bool_const("column_down")),
          none(ctx.bool_const("column_none")),
          bx(ctx.real_const("base_x")),
          by(ctx.real_const("base_y")),
          bz(ctx.real_const("base_z")),
          column(ctx.real_const("d1")) {
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
        const auto& tw = task.robot.twists;
        const bool has_zero =
            std::any_of(tw.begin(), tw.end(), [](double a) { return is_angle(a, 0.0); });
        for (int sign : {1, -1})
            if (column_twist == 0 && has_zero && std::any_of(tw.begin(), tw.end(), [&](double a) {
                    return std::abs(a - sign * geometry::kPi / 2) <= 1e-9;
                }))
                column_twist = sign;
        encode_relaxation();
        if (column_twist != 0) encode_pattern();
    }

    double seconds_left() const { return options.deadline.remaining(); }
    bool expired() const { return options.deadline.expired(); }

    void set_timeout(z3::solver& s, double seconds) {
        z3::params p(ctx);
        p.set("unsat_core", true);
        const double ms = std::min({seconds, seconds_left(), 1e6}) * 1000.0;
        p.set("timeout", static_cast<unsigned>(std::max(1.0, ms)));
        s.set(p);
    }

    z3::expr num(double v) { return ctx.real_val(decimal(v).c_str()); }

    // The literal's name is the part's, so that SMT-LIB scripts read as the
    // task does; the part itself travels beside it.
    z3::expr literal(const task::TaskPart& part) {
        auto it = literal_of.find(part);
        if (it != literal_of.end()) return it->second;
        z3::expr l = ctx.bool_const(task::to_string(part).c_str());
        literal_of.emplace(part, l);
        names.push_back(part);
        return l;
    }

    void require(z3::solver& s, std::initializer_list<task::TaskPart> parts, const z3::expr& e) {
        z3::expr_vector guards(ctx);
        for (const auto& part : parts) guards.push_back(literal(part));
        s.add(z3::implies(z3::mk_and(guards), e));
    }

    z3::expr_vector assumptions() {
        z3::expr_vector a(ctx);
        for (const auto& n : names) a.push_back(literal_of.at(n));
        return a;
    }

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

    void encode_pattern() {
        pattern_regions = encode_regions(pattern, "pattern_region_");
        const auto& spec = task.robot;
        const double e = options.slack;
        const double lo = spec.min_link_length - e, hi = spec.max_link_length + e;
        // Exactly one column sign is assumed per skeleton.
        require(pattern, {kMinLink, kMaxLink},
                z3::implies(up, column >= num(lo) && column <= num(hi)) &&
                    z3::implies(down, column <= num(-lo) && column >= num(-hi)));
        pattern.add(z3::implies(none, column == 0));
        const int hands = dof - 3;
        for (int k = 0; k < 2; ++k) {
            links.push_back(ctx.real_const(("a" + std::to_string(k + 2)).c_str()));
            pattern.add(links.back() > 0);
            require(pattern, {kMinLink}, links.back() >= num(lo));
            require(pattern, {kMaxLink}, links.back() <= num(hi));
        }
        z3::expr hand = num(0.0);
        if (hands > 0) {
            hand = ctx.real_const("hand");
            require(pattern, {kMinLink}, hand >= num(hands * lo));
            require(pattern, {kMaxLink}, hand <= num(hands * hi));
            links.push_back(hand);
        }
        // The tool is part of the last link.
        if (spec.tool_length > 0.0)
            require(pattern, {TaskPart::robot(RobotKey::ToolLength)},
                    hands > 0 ? hand >= num(spec.tool_length + (hands - 1) * lo)
                              : links[1] >= num(spec.tool_length - e));
        const z3::expr sz = bz + column;
        const z3::expr outer = links[0] + links[1] + hand;
        const z3::expr inner_a = links[0] - links[1] - hand;
        const z3::expr inner_b = links[1] - links[0] - hand;
        const double axis = std::max(0.0, options.axis_margin - e);
        for (std::size_t j = 0; j < points.size(); ++j) {
            const TaskPart part = task::primitive_part(task, static_cast<int>(j));
            for (const Vec3& p : points[j]) {
                const z3::expr d2 = dist2(p, sz);
                require(pattern, {part}, d2 <= outer * outer + num(e));
                require(pattern, {part}, inner_a <= 0 || d2 >= inner_a * inner_a - num(e));
                require(pattern, {part}, inner_b <= 0 || d2 >= inner_b * inner_b - num(e));
                const z3::expr dx = num(p.x()) - bx, dy = num(p.y()) - by;
                require(pattern, {part}, dx * dx + dy * dy >= num(axis * axis));
            }
        }
    }

    Result check() {
        if (expired()) {
            unknown = "time limit reached";
            return Result::Unknown;
        }
        set_timeout(relaxation, options.time_limit);
        switch (relaxation.check(assumptions())) {
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

bool SpatialFrontStage::pattern_allowed() const { return impl_->column_twist != 0; }

std::vector<task::TaskPart> SpatialFrontStage::minimal_core() {
    Impl& m = *impl_;
    z3::solver& s = m.relaxation;
    if (m.expired()) return {};
    m.set_timeout(s, m.options.time_limit);
    const auto t0 = std::chrono::steady_clock::now();
    if (s.check(m.assumptions()) != z3::unsat) return {};
    const double trial_limit = std::min(
        m.options.time_limit,
        std::max(m.options.core_trial_seconds,
                 m.options.core_trial_factor *
                     std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()));
    const z3::expr_vector core = s.unsat_core();
    std::vector<z3::expr> kept;
    for (unsigned i = 0; i < core.size(); ++i) kept.push_back(core[i]);
    // Deletion: drop each literal whose absence keeps the conflict; an
    // undecided trial keeps it, so the core stays a conflict.
    for (std::size_t i = 0; i < kept.size() && !m.expired();) {
        m.set_timeout(s, trial_limit);
        z3::expr_vector trial(m.ctx);
        for (std::size_t k = 0; k < kept.size(); ++k)
            if (k != i) trial.push_back(kept[k]);
        if (s.check(trial) == z3::unsat) {
            const z3::expr_vector smaller = s.unsat_core();
            std::vector<z3::expr> next;
            for (std::size_t k = 0; k < kept.size(); ++k) {
                if (k == i) continue;
                for (unsigned c = 0; c < smaller.size(); ++c)
                    if (z3::eq(kept[k], smaller[c])) next.push_back(kept[k]);
            }
            kept = std::move(next);
            i = std::min(i, kept.size());
        } else {
            ++i;
        }
    }
    // In the order the literals were made (the task's order), not Z3's.
    std::vector<task::TaskPart> out;
    for (const auto& n : m.names)
        if (std::any_of(kept.begin(), kept.end(),
                        [&](const z3::expr& e) { return z3::eq(e, m.literal_of.at(n)); }))
            out.push_back(n);
    return out;
}

bool SpatialFrontStage::conflicts(const std::vector<task::TaskPart>& parts) {
    Impl& m = *impl_;
    if (m.expired()) return false;
    z3::expr_vector a(m.ctx);
    for (const auto& part : parts) {
        auto it = m.literal_of.find(part);
        if (it != m.literal_of.end()) a.push_back(it->second);
    }
    m.set_timeout(m.relaxation, m.options.time_limit);
    return m.relaxation.check(a) == z3::unsat;
}

std::vector<SpatialSkeleton> SpatialFrontStage::skeletons(int limit) {
    Impl& m = *impl_;
    std::vector<SpatialSkeleton> out;
    if (m.column_twist == 0) return out;
    const int regions =
        m.task.base_regions.empty() ? 1 : static_cast<int>(m.task.base_regions.size());
    for (int column : {1, -1, 0}) {
        for (int r = 0; r < regions && static_cast<int>(out.size()) < limit; ++r) {
            if (m.expired()) return out;
            z3::expr_vector a = m.assumptions();
            const z3::expr chosen = column > 0 ? m.up : column < 0 ? m.down : m.none;
            for (const z3::expr& sign : {m.up, m.down, m.none})
                a.push_back(z3::eq(sign, chosen) ? sign : !sign);
            if (!m.pattern_regions.empty())
                a.push_back(m.pattern_regions[static_cast<std::size_t>(r)]);
            m.set_timeout(m.pattern, m.options.time_limit);
            if (m.pattern.check(a) != z3::sat) continue;
            const z3::model model = m.pattern.get_model();
            auto value = [&](const z3::expr& e) { return to_double(model.eval(e, true)); };
            SpatialSkeleton sk;
            sk.dof = m.dof;
            sk.column_twist = m.column_twist;
            sk.column = column;
            sk.base_region = m.task.base_regions.empty() ? -1 : r;
            sk.base = Vec3(value(m.bx), value(m.by), value(m.bz));
            sk.column_length = value(m.column);
            sk.links = {value(m.links[0]), value(m.links[1])};
            // The hand's length, shared among its links.
            for (int h = 0; h < m.dof - 3; ++h) sk.links.push_back(value(m.links[2]) / (m.dof - 3));
            out.push_back(std::move(sk));
        }
    }
    return out;
}

std::string SpatialFrontStage::reason_unknown() const { return impl_->unknown; }

std::string SpatialFrontStage::smtlib() const {
    auto script = [&](z3::solver& s) {
        std::string text = s.to_smt2();
        const auto pos = text.rfind("(check-sat)");
        if (pos != std::string::npos) text.erase(pos);
        text += "(check-sat-assuming (";
        for (std::size_t i = 0; i < impl_->names.size(); ++i)
            text += (i ? " |" : "|") + task::to_string(impl_->names[i]) + "|";
        return text + "))\n";
    };
    return "; relaxation (any chain)\n" + script(impl_->relaxation) +
           "; pattern (yaw column, pitch links)\n" + script(impl_->pattern);
}

}  // namespace modsynth::smt
