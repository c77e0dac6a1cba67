#include <modsynth/synth/proximal_plan.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <modsynth/geometry/distance.h>
#include <modsynth/geometry/primitive.h>
#include <modsynth/kinematics/clearance_rule.h>
#include <modsynth/kinematics/kinematics.h>
#include <modsynth/task/strokes.h>
#include <modsynth/text/format.h>
#include <modsynth/text/option_check.h>

namespace modsynth::synth {
namespace {

using geometry::Vec2;
constexpr double kInf = std::numeric_limits<double>::infinity();

// The worst margin of one pose: the distal pair (a, c) hinged at `origin`
// with the tool at p on the robot's branch, link 1 from the base to origin.
// Reach; the tool's height above the line of link 2, which also keeps the
// pair off its straight and folded poses, where the branch could change;
// the tool against link 1; every link against every obstacle.
double pose_margin(const task::Task& task, const kinematics::Robot& robot, const Vec2& origin,
                   const Vec2& p) {
    const double a = robot.link_lengths[1], c = robot.link_lengths[2];
    const double d = (p - origin).norm();
    double worst = std::min(a + c - d, d - std::abs(a - c));
    if (worst <= 0.0) return worst;
    const auto ik = kinematics::inverse_two_link(origin, a, c, p, robot.elbow);
    if (!ik) return 0.0;
    const kinematics::ClearanceRule rule{robot.link_diameter};
    const Vec2 e = origin + a * geometry::unit(ik->phi1);
    worst = std::min(worst,
                     std::abs(geometry::cross(e - origin, p - origin)) / a - rule.self_distance());
    worst = std::min(worst, rule.self_margin(p, robot.base, origin));
    for (const auto& ob : task.obstacles)
        worst = std::min({worst, rule.link_margin(ob, robot.base, origin),
                          rule.link_margin(ob, origin, e), rule.link_margin(ob, e, p)});
    return worst;
}

// Lower envelope of f[k] + step * (distance from k), the distance counted
// along the circle of A angles but never across an angle that is not
// `open`: the cheapest way to every angle from any other of its open run.
// `from` gets the angle each value came from.
void sweep_envelope(std::vector<double>& f, std::vector<int>& from, const std::vector<char>& open,
                    double step) {
    const int A = static_cast<int>(f.size());
    for (int k = 0; k < A; ++k) from[k] = k;
    int cut = -1;
    for (int k = 0; k < A && cut < 0; ++k)
        if (!open[k]) cut = k;
    // With every angle open, two laps each way carry any value round the
    // circle the short way; otherwise one lap from the cut, in both
    // directions, stops at each closed angle.
    const int laps = cut < 0 ? 2 * A : A;
    const int first = cut < 0 ? 0 : cut;
    for (int i = 1; i <= laps; ++i) {
        const int k = (first + i) % A, prev = (first + i - 1) % A;
        if (!open[k] || !open[prev]) continue;
        if (f[prev] + step < f[k]) f[k] = f[prev] + step, from[k] = from[prev];
    }
    for (int i = 1; i <= laps; ++i) {
        const int k = ((first - i) % A + A) % A, prev = ((first - i + 1) % A + A) % A;
        if (!open[k] || !open[prev]) continue;
        if (f[prev] + step < f[k]) f[k] = f[prev] + step, from[k] = from[prev];
    }
}

}  // namespace

bool ProximalPlanOptions::IsValid(std::string* error) const {
    return text::OptionCheck("ProximalPlanOptions", error)
        .within("angles", angles, 8, 1 << 16)
        .greater("spacing", spacing, 0.0)
        .at_least("margin", margin, 0.0)
        .at_least("wanted_clearance", wanted_clearance, 0.0)
        .at_least("clearance_weight", clearance_weight, 0.0)
        .at_least("guesses", guesses, 0)
        .ok();
}

ProximalPlan plan_proximal_angles(const task::Task& task, const kinematics::Robot& design,
                                  const ProximalPlanOptions& options, run::Deadline deadline) {
    text::require_valid(options);
    if (design.dof() != 3)
        throw std::invalid_argument("plan_proximal_angles: the design must have 3 joints");
    const int A = options.angles;
    const int m = static_cast<int>(task.trajectory.size());
    const double step = design.link_lengths[0] * geometry::kTau / A;  // elbow travel per angle
    std::vector<Vec2> origin(A);
    for (int k = 0; k < A; ++k) origin[k] = design.distal_origin(geometry::kTau * k / A);
    const auto penalty = [&](double margin) {
        return options.clearance_weight *
               std::max(0.0, options.margin + options.wanted_clearance - margin);
    };

    ProximalPlan plan;
    // end[k]: the margin at the end of the primitive before, link 1 at
    // angle k; within a stroke it is where the next one starts.
    std::vector<double> end(A), last(A), best(A, kInf), next(A);
    std::vector<int> from(A);
    std::vector<char> open(A);
    // Per node: the angle of the primitive before, and the node's margin.
    std::vector<int> back(static_cast<std::size_t>(m) * A, -1);
    std::vector<float> margin(static_cast<std::size_t>(m) * A, 0.0f);
    // Per primitive: a closed angle of the transition before it (-1: none),
    // from which the sweeps' distances along their open run are counted.
    std::vector<int> cut(m, -1);
    auto blocked = [&](int j, const std::string& why) {
        plan.blocked_primitive = j;
        plan.message = why;
        return plan;
    };
    for (int j = 0; j < m; ++j) {
        if (deadline.expired()) return blocked(j, "the time limit");
        const geometry::Primitive& prim = task.trajectory[j];
        const bool continues = j > 0 && task::has_transition_after(task, j - 1);
        // Where primitive j may start, and at what cost so far.
        if (j == 0) {
            std::fill(next.begin(), next.end(), 0.0);
            for (int k = 0; k < A; ++k) from[k] = k;
        } else if (continues) {
            for (int k = 0; k < A; ++k) {
                open[k] = end[k] >= options.margin;
                if (!open[k] && cut[j] < 0) cut[j] = k;
            }
            next = best;
            sweep_envelope(next, from, open, step);
        } else {
            // A new stroke: the arm travels there freely.
            const int k0 =
                static_cast<int>(std::min_element(best.begin(), best.end()) - best.begin());
            std::fill(next.begin(), next.end(), best[k0]);
            std::fill(from.begin(), from.end(), k0);
        }
        const double len = geometry::length(prim);
        const int n = std::max(1, static_cast<int>(std::ceil(len / options.spacing)));
        std::vector<Vec2> pts;
        for (int i = continues ? 1 : 0; i <= n; ++i)
            pts.push_back(geometry::point_at(prim, len * i / n));
        bool any = false, any_trace = false;
        for (int k = 0; k < A; ++k) {
            // The end first: the next transition needs it whatever the trace.
            const double e = pose_margin(task, design, origin[k], pts.back());
            double w = std::min(e, continues ? end[k] : kInf);
            for (std::size_t i = 0; i + 1 < pts.size() && w >= options.margin; ++i)
                w = std::min(w, pose_margin(task, design, origin[k], pts[i]));
            last[k] = e;
            const bool clear = w >= options.margin;
            any_trace = any_trace || clear;
            if (!clear || next[k] == kInf) {
                best[k] = kInf;
                continue;
            }
            best[k] = next[k] + penalty(w);
            back[static_cast<std::size_t>(j) * A + k] = from[k];
            margin[static_cast<std::size_t>(j) * A + k] = static_cast<float>(w);
            any = true;
        }
        end.swap(last);
        if (!any)
            return blocked(
                j, any_trace
                       ? "no transition into " + task::part_name(task, j) + " keeps the links clear"
                       : "no proximal angle traces " + task::part_name(task, j) + " clear");
    }
    int k = static_cast<int>(std::min_element(best.begin(), best.end()) - best.begin());
    plan.angles.assign(m, 0.0);
    plan.margin = kInf;
    for (int j = m - 1; j >= 0; --j) {
        const std::size_t node = static_cast<std::size_t>(j) * A + k;
        plan.angles[j] = geometry::kTau * k / A;
        plan.margin = std::min(plan.margin, static_cast<double>(margin[node]));
        const int prev = back[node];
        if (j > 0 && prev != k && task::has_transition_after(task, j - 1)) {
            ++plan.moves;
            // The motion sweeps the short way round; the plan's sweep went
            // along its open run, which is the same way only when shorter
            // than half a turn.
            const auto along = [&](int x) { return cut[j] < 0 ? x : ((x - cut[j]) % A + A) % A; };
            int d = std::abs(along(prev) - along(k));
            if (cut[j] < 0) d = std::min(d, A - d);
            if (2 * d >= A)
                return blocked(j,
                               "the proximal link would turn half a turn or more in the "
                               "transition into " +
                                   task::part_name(task, j));
        }
        k = prev;
    }
    plan.found = true;
    return plan;
}

}  // namespace modsynth::synth
