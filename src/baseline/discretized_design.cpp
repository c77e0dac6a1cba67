#include <modsynth/baseline/discretized_design.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <modsynth/geometry/primitive.h>
#include <modsynth/kinematics/chain_layout.h>
#include <modsynth/kinematics/clearance_rule.h>
#include <modsynth/kinematics/kinematics.h>
#include <modsynth/nlp/bilinear.h>
#include <modsynth/nlp/solver.h>
#include <modsynth/run/deadline.h>
#include <modsynth/text/option_check.h>

namespace modsynth::baseline {
namespace {

using geometry::Vec2;
using nlp::Quadratic;
using namespace nlp::bilinear;

// One start of the program: a base region (-1: none) and the elbow sign of
// each consecutive link pair.
struct Start {
    int region = -1;
    std::vector<int> elbows;
};

struct Built {
    nlp::QuadraticProgram program;
    int base_x = -1, base_y = -1;
    std::vector<int> r;
    // joints[k][i]: variables of joint i + 1 (between link i + 1 and i + 2) at point k.
    std::vector<std::vector<std::pair<int, int>>> joints;
};

Vec2 start_base(const task::Task& task, int region, const std::vector<PathSample>& points) {
    if (region >= 0) {
        const task::BaseRegion& b = task.base_regions[region];
        return 0.5 * (b.min + b.max);
    }
    Vec2 c = Vec2::Zero();
    for (const PathSample& p : points) c += p.point;
    return c / static_cast<double>(points.size());
}

// The initial pose at p: with three joints link 1 turned off the line to p
// by a fixed angle, then the distal pair towards p on its requested side.
std::vector<Vec2> start_joints(const Vec2& base, const std::vector<double>& r,
                               const std::vector<int>& elbows, const Vec2& p, double turn) {
    const int n = static_cast<int>(r.size());
    std::vector<Vec2> joints;
    Vec2 origin = base;
    if (n == 3) {
        const Vec2 d = p - base;
        const double toward = std::atan2(d.y(), d.x());
        origin = base + r[0] * geometry::unit(toward - turn * elbows[0]);
        joints.push_back(origin);
    }
    joints.push_back(kinematics::elbow_towards(origin, r[n - 2], r[n - 1], p, elbows.back()));
    return joints;
}

std::string where(int k) { return "point " + std::to_string(k); }

Built build(const task::Task& task, const std::vector<PathSample>& points, int dof,
            const Start& start, const DesignOptions& options) {
    Built m;
    nlp::QuadraticProgram& qp = m.program;
    const task::RobotSpec& spec = task.robot;
    const kinematics::ClearanceRule rule{spec.link_diameter};
    const Vec2 b0 = start_base(task, start.region, points);
    double bx_lo = -nlp::kInfinity, bx_hi = nlp::kInfinity, by_lo = -nlp::kInfinity,
           by_hi = nlp::kInfinity;
    if (start.region >= 0) {
        const task::BaseRegion& reg = task.base_regions[start.region];
        bx_lo = reg.min.x(), bx_hi = reg.max.x(), by_lo = reg.min.y(), by_hi = reg.max.y();
    }
    m.base_x = qp.add_variable(bx_lo, bx_hi, b0.x(), "base.x");
    m.base_y = qp.add_variable(by_lo, by_hi, b0.y(), "base.y");
    const Point base = variable(m.base_x, m.base_y, b0);

    double reach = 0.0;
    for (const PathSample& p : points) reach = std::max(reach, (p.point - b0).norm());
    const double share = !kinematics::has_proximal_link(dof) ? options.start_reach_share_two
                                                             : options.start_reach_share_three;
    std::vector<double> r0(dof,
                           std::clamp(share * reach, spec.min_link_length, spec.max_link_length));
    Quadratic objective;
    for (int i = 0; i < dof; ++i) {
        m.r.push_back(qp.add_variable(spec.min_link_length, spec.max_link_length, r0[i],
                                      "r" + std::to_string(i + 1)));
        objective.add(m.r.back(), 1.0);
    }

    std::vector<Point> previous;
    for (int k = 0; k < static_cast<int>(points.size()); ++k) {
        const Vec2& p = points[k].point;
        std::vector<Point> chain{base};
        std::vector<std::pair<int, int>> ids;
        for (const Vec2& j0 : start_joints(b0, r0, start.elbows, p, options.start_turn)) {
            chain.push_back(
                new_point(qp, "joint " + std::to_string(chain.size()) + " " + where(k), j0));
            ids.push_back({chain.back().x.terms[0].first, chain.back().y.terms[0].first});
        }
        chain.push_back(constant(p));
        m.joints.push_back(ids);
        for (int i = 0; i < dof; ++i)
            add_link(qp, chain[i], chain[i + 1], m.r[i], std::to_string(i + 1) + " " + where(k));
        // Elbow consistency: each consecutive pair bends to its side or is straight.
        for (int i = 1; i < dof; ++i)
            qp.add_constraint(
                scaled(cross(chain[i - 1], chain[i], chain[i + 1]), start.elbows[i - 1]), 0.0,
                nlp::kInfinity, "elbow " + std::to_string(i) + " " + where(k));
        for (int i = 0; i < dof; ++i) {
            for (int o = 0; o < static_cast<int>(task.obstacles.size()); ++o) {
                const task::Obstacle& ob = task.obstacles[o];
                add_keep_apart(qp, chain[i], chain[i + 1], constant(ob.center),
                               rule.obstacle_distance(ob) + options.clearance_margin,
                               "link " + std::to_string(i + 1) + " to obstacles[" +
                                   std::to_string(o) + "], " + where(k));
            }
            if (i + 1 < dof)
                add_keep_apart(qp, chain[i], chain[i + 1], chain.back(),
                               rule.self_distance() + options.self_margin,
                               "EE to link " + std::to_string(i + 1) + ", " + where(k));
        }
        if (!previous.empty()) {
            for (int i = 1; i < dof; ++i)
                add_scaled(objective, squared_distance(previous[i], chain[i]),
                           options.smoothness_weight);
        }
        previous = chain;
    }
    qp.set_objective(objective);
    qp.finalize();
    return m;
}

std::vector<Start> starts(const task::Task& task, int dof) {
    std::vector<Start> out;
    for (int region : task::base_region_choices(task)) {
        for (int pattern = 0; pattern < (1 << (dof - 1)); ++pattern) {
            Start s{region, {}};
            for (int i = 0; i < dof - 1; ++i) s.elbows.push_back((pattern >> i) & 1 ? -1 : 1);
            out.push_back(s);
        }
    }
    return out;
}

std::vector<double> pose_from(const Built& m, const std::vector<double>& x, int k, const Vec2& p) {
    std::vector<Vec2> chain{{x[m.base_x], x[m.base_y]}};
    for (const auto& [ix, iy] : m.joints[k]) chain.push_back({x[ix], x[iy]});
    chain.push_back(p);
    std::vector<double> q;
    double previous = 0.0;
    for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
        const Vec2 d = chain[i + 1] - chain[i];
        const double phi = std::atan2(d.y(), d.x());
        q.push_back(i == 0 ? phi : std::remainder(phi - previous, geometry::kTau));
        previous = phi;
    }
    return q;
}

}  // namespace

std::vector<PathSample> equidistant_points(const task::Task& task, int count) {
    if (count < 2) throw std::invalid_argument("the discretized design needs at least 2 points");
    std::vector<double> lengths;
    double total = 0.0;
    for (const auto& prim : task.trajectory) {
        lengths.push_back(geometry::length(prim));
        total += lengths.back();
    }
    std::vector<PathSample> out;
    std::size_t j = 0;
    double before = 0.0;  // path length before primitive j
    for (int k = 0; k < count; ++k) {
        const double target = total * k / (count - 1);
        while (j + 1 < lengths.size() && before + lengths[j] < target) before += lengths[j++];
        const double s = std::clamp(target - before, 0.0, lengths[j]);
        out.push_back({static_cast<int>(j), s, geometry::point_at(task.trajectory[j], s)});
    }
    return out;
}

nlp::QuadraticProgram design_program(const task::Task& task, const std::vector<PathSample>& points,
                                     int dof, int region, const std::vector<int>& elbows,
                                     const DesignOptions& options) {
    text::require_valid(options);
    if (static_cast<int>(elbows.size()) != dof - 1)
        throw std::invalid_argument(
            "a design program needs one elbow sign per consecutive link pair");
    return build(task, points, dof, Start{region, elbows}, options).program;
}

bool DesignOptions::IsValid(std::string* error) const {
    return text::OptionCheck("DesignOptions", error)
        .at_least("time_limit", time_limit, 0.0)
        .at_least("smoothness_weight", smoothness_weight, 0.0)
        .at_least("clearance_margin", clearance_margin, 0.0)
        .at_least("self_margin", self_margin, 0.0)
        .greater("start_reach_share_two", start_reach_share_two, 0.0)
        .greater("start_reach_share_three", start_reach_share_three, 0.0)
        .within("start_turn", start_turn, -geometry::kPi, geometry::kPi)
        .greater("feasibility_tolerance", feasibility_tolerance, 0.0)
        .nested("solver", solver)
        .ok();
}

PointDesign design_for_points(const task::Task& task, const std::vector<PathSample>& points,
                              const DesignOptions& options) {
    text::require_valid(options);
    const run::Deadline deadline = run::Deadline::in(options.time_limit);
    PointDesign best;
    std::vector<int> dofs = task.robot.dof;
    std::sort(dofs.begin(), dofs.end());
    int solves = 0;
    for (int dof : dofs) {
        double best_objective = nlp::kInfinity;
        for (const Start& start : starts(task, dof)) {
            const double left = deadline.remaining();
            if (left <= 0.0) break;
            const Built m = build(task, points, dof, start, options);
            nlp::SolverOptions solver = options.solver;
            solver.time_limit = left;
            const nlp::SolverResult result = nlp::minimize(m.program, solver);
            ++solves;
            if (!result.usable() ||
                m.program.infeasibility(result.x.data()) > options.feasibility_tolerance)
                continue;
            if (result.objective >= best_objective) continue;
            best_objective = result.objective;
            best.found = true;
            best.robot = {};
            best.robot.base = Vec2(result.x[m.base_x], result.x[m.base_y]);
            for (int r : m.r) best.robot.link_lengths.push_back(result.x[r]);
            best.robot.link_diameter = task.robot.link_diameter;
            best.robot.elbow = start.elbows.back();
            best.elbows = start.elbows;
            best.poses.clear();
            for (int k = 0; k < static_cast<int>(points.size()); ++k)
                best.poses.push_back(pose_from(m, result.x, k, points[k].point));
        }
        if (best.found) break;
    }
    best.nlp_solves = solves;
    if (!best.found) {
        best.message = "no robot with " + std::to_string(dofs.front()) +
                       (dofs.size() > 1 ? " to " + std::to_string(dofs.back()) : std::string()) +
                       " joints reaches all " + std::to_string(points.size()) +
                       " points from the starts tried (" + std::to_string(solves) + " solves)";
        if (deadline.expired()) best.message += "; time limit reached";
    }
    return best;
}

}  // namespace modsynth::baseline
