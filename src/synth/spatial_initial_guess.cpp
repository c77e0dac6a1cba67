#include <modsynth/synth/spatial_initial_guess.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <random>

#include <modsynth/arms/pointing.h>
#include <modsynth/geometry/primitive3.h>
#include <modsynth/kinematics/pose_rules.h>
#include <modsynth/task/spatial_strokes.h>
#include <modsynth/text/option_check.h>

namespace modsynth::synth {
namespace {

using geometry::Vec3;
using kinematics::PoseRule;
constexpr double kInf = std::numeric_limits<double>::infinity();

struct ScoringPoint {
    int primitive = 0;
    double u = 0.0;  ///< fraction along the primitive
    Vec3 p = Vec3::Zero();
    std::optional<task::WantedTool> tool;  ///< which way the tool points there
};

/// Points every `spacing` m (wider past max_points), per stroke, in an
/// order that visits the path coarsely first, so that an unclear candidate
/// is usually caught within its first few points.
std::vector<std::vector<ScoringPoint>> scoring_points(const task::SpatialTask& task, double spacing,
                                                      int max_points) {
    double total = 0.0;
    for (const auto& p : task.trajectory) total += geometry::length(p);
    spacing = std::max(spacing, total / std::max(1, max_points));
    std::vector<std::vector<ScoringPoint>> out(static_cast<std::size_t>(task::stroke_count(task)));
    for (int j = 0; j < static_cast<int>(task.trajectory.size()); ++j) {
        const auto& prim = task.trajectory[static_cast<std::size_t>(j)];
        const double len = geometry::length(prim);
        const int n = std::max(2, static_cast<int>(std::ceil(len / spacing)));
        auto& stroke = out[static_cast<std::size_t>(task::stroke_of(task, j))];
        for (int i = 0; i <= n; ++i) {
            const double u = static_cast<double>(i) / n;
            const Vec3 p = geometry::point_at(prim, u * len);
            stroke.push_back({j, u, p, task::wanted_tool(task, j, p)});
        }
    }
    for (auto& stroke : out) {
        std::vector<ScoringPoint> ordered;
        for (std::size_t stride : {16u, 4u, 1u})
            for (std::size_t i = 0; i < stroke.size(); i += stride)
                if (stride == 16 || i % (stride * 4) != 0) ordered.push_back(stroke[i]);
        stroke = std::move(ordered);
    }
    return out;
}

/// How each margin is measured, per pose.
class Scorer {
public:
    Scorer(const task::SpatialTask& task, const nlp::SpatialMargins& margins)
        : task_(task), m_(margins) {}

    /// The worst margin of the pose at target p, or below `cutoff` as soon
    /// as one is.
    double pose_margin(const kinematics::ArmDesign& d, const Vec3& p,
                       const std::optional<task::WantedTool>& tool, int branch,
                       const std::vector<double>& along, double cutoff) const {
        kinematics::PoseTarget<double> target;
        target.point = p;
        if (tool) {
            target.tool_axis = tool->direction;
            target.tool_tolerance = tool->tolerance;
        }
        auto pose = d.model->pose(d.shape, target, branch, along, m_.pose());
        kinematics::add_tool_limit(pose, target, m_.tool_share);
        double worst = kInf;
        for (const auto& l : pose.limits)
            worst = std::min(worst, std::min(l.value - l.lower, l.upper - l.value) * l.scale);
        if (worst < cutoff) return worst;
        const double dia = task_.robot.link_diameter;
        const int segments = static_cast<int>(pose.points.size()) - 1;
        const std::vector<kinematics::PosePart<double>> none;
        for (const PoseRule& r : kinematics::self_rules(segments)) {
            worst = std::min(
                worst, kinematics::rule_value(r, pose, none, task_.obstacles) - dia - m_.self);
            if (worst < cutoff) return worst;
        }
        if (task_.obstacles.empty()) return worst;
        const auto parts =
            kinematics::pose_clearance_parts(pose, dia / 2.0, task_.robot.tool_length);
        for (const auto& part : parts) {
            for (int o = 0; o < static_cast<int>(task_.obstacles.size()); ++o) {
                const PoseRule r{PoseRule::Kind::Clearance, part.segment, o};
                worst = std::min(worst, kinematics::rule_value(r, pose, parts, task_.obstacles) -
                                            dia / 2.0 - m_.clearance);
                if (worst < cutoff) return worst;
            }
        }
        return worst;
    }

private:
    const task::SpatialTask& task_;
    const nlp::SpatialMargins& m_;
};

/// A stroke's worst margin with a given branch and free numbers, stopping
/// below `cutoff`.
double stroke_margin(const Scorer& scorer, const kinematics::ArmDesign& d,
                     const std::vector<ScoringPoint>& points, int branch, double cutoff) {
    double worst = kInf;
    for (const ScoringPoint& sp : points) {
        worst = std::min(worst, scorer.pose_margin(d, sp.p, sp.tool, branch,
                                                   d.along_at(sp.primitive, sp.u), cutoff));
        if (worst < cutoff) break;
    }
    return worst;
}

/// Chooses each stroke's branch (and free numbers, where the family has
/// them) for the best margin; returns the design's worst margin, which is
/// below `cutoff` when it gave up early.
double choose_branches(const task::SpatialTask& task, const Scorer& scorer,
                       kinematics::ArmDesign& d,
                       const std::vector<std::vector<ScoringPoint>>& strokes,
                       const std::vector<std::vector<double>>& grid, const arms::AlongPins& pins,
                       double cutoff) {
    const int branches = d.model->branch_count(d.dof());
    const bool free = !grid.front().empty();
    d.branches.assign(strokes.size(), 0);
    if (free) d.along.assign(task.trajectory.size(), {});
    const auto set_along = [&](int s, const std::vector<double>& v) {
        std::vector<double> both = v;
        both.insert(both.end(), v.begin(), v.end());
        for (int j = task::stroke_first(task, s); j <= task::stroke_last(task, s); ++j)
            d.along[static_cast<std::size_t>(j)] = both;
        arms::pin_along(pins, task, d.along, s, s);
    };
    double worst = kInf;
    for (std::size_t s = 0; s < strokes.size(); ++s) {
        double best = -kInf;
        int best_branch = 0;
        std::size_t best_numbers = 0;
        for (std::size_t g = 0; g < grid.size(); ++g) {
            if (free) set_along(static_cast<int>(s), grid[g]);
            for (int branch = 0; branch < branches; ++branch) {
                const double v =
                    stroke_margin(scorer, d, strokes[s], branch, std::max(best, cutoff));
                if (v > best) best = v, best_branch = branch, best_numbers = g;
            }
        }
        d.branches[s] = best_branch;
        if (free) set_along(static_cast<int>(s), grid[best_numbers]);
        worst = std::min(worst, best);
        if (worst < cutoff) break;
    }
    return worst;
}

bool near(const kinematics::ArmDesign& a, const kinematics::ArmDesign& b, double tol) {
    if ((a.shape.base - b.shape.base).norm() > tol) return false;
    for (std::size_t k = 0; k < a.shape.values.size(); ++k)
        if (std::abs(a.shape.values[k] - b.shape.values[k]) > tol) return false;
    return true;
}

}  // namespace

bool SpatialGuessOptions::IsValid(std::string* error) const {
    return text::OptionCheck("SpatialGuessOptions", error)
        .greater("scoring_spacing", scoring_spacing, 0.0)
        .at_least("max_points", max_points, 2)
        .at_least("candidates", candidates, 1)
        .at_least("distinct_distance", distinct_distance, 0.0)
        .ok();
}

double chain_length(const kinematics::ArmDesign& design) { return design.chain().total_length(); }

double design_margin(const task::SpatialTask& task, const kinematics::ArmDesign& design,
                     const nlp::SpatialMargins& margins, double spacing, int max_points) {
    const Scorer scorer(task, margins);
    const auto strokes = scoring_points(task, spacing, max_points);
    double worst = kInf;
    for (std::size_t s = 0; s < strokes.size(); ++s)
        worst =
            std::min(worst, stroke_margin(scorer, design, strokes[s], design.branches[s], -kInf));
    return worst;
}

std::vector<ScoredDesign> spatial_initial_guesses(const task::SpatialTask& task,
                                                  const arms::Skeleton& skeleton, int count,
                                                  unsigned seed, const nlp::SpatialMargins& margins,
                                                  const run::Deadline& deadline,
                                                  const SpatialGuessOptions& options) {
    text::require_valid(options);
    const arms::Family& family = *skeleton.family;
    const auto strokes = scoring_points(task, options.scoring_spacing, options.max_points);
    // A few points per stroke give the reach the links are drawn for.
    arms::DrawContext context{task, skeleton.dof,         skeleton.variant,     {},
                              {},   Vec3::Constant(kInf), Vec3::Constant(-kInf)};
    for (const auto& stroke : strokes)
        for (std::size_t i = 0; i < stroke.size();
             i += std::max<std::size_t>(1, stroke.size() / 48)) {
            context.probe.push_back(stroke[i].p);
            context.path_min = context.path_min.cwiseMin(stroke[i].p);
            context.path_max = context.path_max.cwiseMax(stroke[i].p);
        }
    if (skeleton.base_region >= 0) {
        context.base_box = task.base_regions[static_cast<std::size_t>(skeleton.base_region)];
    } else {
        const Vec3 grow = Vec3::Constant(std::min(task.robot.max_link_length, 1.0));
        context.base_box = {context.path_min - grow, context.path_max + grow};
    }
    const auto grid = family.along_grid(skeleton.dof, skeleton.variant);
    const auto pins = arms::along_pins(family, task, skeleton.dof, skeleton.variant);

    std::mt19937 rng(seed * 7919u + static_cast<unsigned>(skeleton.variant + 2) * 131u +
                     static_cast<unsigned>(skeleton.base_region + 2) * 17u +
                     static_cast<unsigned>(skeleton.dof) * 7u);
    std::vector<kinematics::ArmDesign> drawn;
    for (int c = 0; c < options.candidates; ++c) {
        auto shape = family.draw(context, rng, c);
        if (!shape) continue;
        kinematics::ArmDesign d;
        d.model = &family;
        d.shape = std::move(*shape);
        d.link_diameter = task.robot.link_diameter;
        drawn.push_back(std::move(d));
    }
    // Shortest first: the first clear ones are the answer.
    std::vector<std::pair<double, std::size_t>> order;
    for (std::size_t i = 0; i < drawn.size(); ++i) order.push_back({chain_length(drawn[i]), i});
    std::stable_sort(order.begin(), order.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    const Scorer scorer(task, margins);
    std::vector<ScoredDesign> clear, unclear;
    for (std::size_t n = 0; n < order.size(); ++n) {
        if (n % 16 == 0 && deadline.expired()) break;
        auto& d = drawn[order[n].second];
        if (std::any_of(clear.begin(), clear.end(), [&](const ScoredDesign& s) {
                return near(s.design, d, options.distinct_distance);
            }))
            continue;
        // Below the worst of the unclear ones kept, a candidate is of no use.
        double cutoff = -kInf;
        if (!clear.empty())
            cutoff = 0.0;
        else if (static_cast<int>(unclear.size()) >= count)
            cutoff = unclear.back().margin;
        const double margin = choose_branches(task, scorer, d, strokes, grid, pins, cutoff);
        if (margin >= 0.0) {
            clear.push_back({d, margin});
            if (static_cast<int>(clear.size()) >= count) break;
        } else if (margin >= cutoff && clear.empty()) {
            unclear.push_back({d, margin});
            std::stable_sort(unclear.begin(), unclear.end(),
                             [](const auto& a, const auto& b) { return a.margin > b.margin; });
            if (static_cast<int>(unclear.size()) > count) unclear.pop_back();
        }
    }
    for (auto& s : unclear) {
        if (static_cast<int>(clear.size()) >= count) break;
        clear.push_back(std::move(s));
    }
    return clear;
}

}  // namespace modsynth::synth
