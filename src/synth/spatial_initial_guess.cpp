#include <modsynth/synth/spatial_initial_guess.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include <modsynth/geometry/distance3.h>
#include <modsynth/geometry/obstacle3.h>
#include <modsynth/geometry/primitive3.h>
#include <modsynth/kinematics/yaw_pitch_pose.h>
#include <modsynth/task/spatial_strokes.h>
#include <modsynth/text/option_check.h>

namespace modsynth::synth {
namespace {

using geometry::Vec3;
constexpr double kInf = std::numeric_limits<double>::infinity();

struct ScoringPoint {
    int primitive = 0;
    double u = 0.0;  ///< fraction along the primitive
    Vec3 p = Vec3::Zero();
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
            stroke.push_back({j, u, geometry::point_at(prim, u * len)});
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
    Scorer(const task::SpatialTask& task, const nlp::SpatialMargins& margins, int column)
        : task_(task), m_(margins), has_column_(column != 0) {}

    /// The worst margin of the pose at target p, or below `cutoff` as soon
    /// as one is.
    double pose_margin(const kinematics::YawPitchShape<double>& shape, const Vec3& p,
                       kinematics::IkBranch branch, const std::vector<double>& pitches,
                       double cutoff) const {
        const auto pose = kinematics::yaw_pitch_pose(shape, p, branch, pitches);
        const double a2 = shape.links[0], a3 = shape.links[1];
        double worst = (m_.elbow_cos - std::abs(pose.elbow_cos)) * std::min(a2, a3);
        worst = std::min(worst, pose.axis_distance - m_.axis);
        if (worst < cutoff) return worst;
        const auto segs = kinematics::pose_segments(pose, has_column_);
        const double d = task_.robot.link_diameter;
        const int n = static_cast<int>(segs.size());
        for (int k = 0; k < n && worst >= cutoff; ++k) {
            const auto& [a, b] = segs[static_cast<std::size_t>(k)];
            for (int l = k + 2; l < n; ++l) {
                const auto& [c, e] = segs[static_cast<std::size_t>(l)];
                worst = std::min(worst, geometry::segment_segment(a, b, c, e) - d - m_.self);
            }
            if (k + 1 < n)
                worst = std::min(worst,
                                 geometry::point_segment(pose.points.back(), a, b) - d - m_.self);
        }
        if (worst < cutoff || task_.obstacles.empty()) return worst;
        for (const auto& part :
             kinematics::pose_clearance_parts(segs, d / 2.0, task_.robot.tool_length)) {
            const auto& [a, b] = segs[static_cast<std::size_t>(part.segment)];
            const Vec3 from = a + part.from * (b - a), to = a + part.to * (b - a);
            for (const auto& o : task_.obstacles) {
                worst =
                    std::min(worst, geometry::segment_gap(from, to, o) - d / 2.0 - m_.clearance);
                if (worst < cutoff) return worst;
            }
        }
        return worst;
    }

private:
    const task::SpatialTask& task_;
    const nlp::SpatialMargins& m_;
    bool has_column_;
};

kinematics::YawPitchShape<double> shape_of(const kinematics::YawPitchArm& arm) {
    return {arm.base, arm.column, arm.links, arm.column_twist};
}

/// A stroke's worst margin with given branch and hand pitches, stopping
/// below `cutoff`.
double stroke_margin(const Scorer& scorer, const kinematics::YawPitchDesign& d,
                     const std::vector<ScoringPoint>& points, kinematics::IkBranch branch,
                     double cutoff) {
    const auto shape = shape_of(d.arm);
    double worst = kInf;
    for (const ScoringPoint& sp : points) {
        worst = std::min(worst, scorer.pose_margin(shape, sp.p, branch,
                                                   d.hand_pitches_at(sp.primitive, sp.u), cutoff));
        if (worst < cutoff) break;
    }
    return worst;
}

constexpr kinematics::IkBranch kBranches[] = {{1, 1}, {1, -1}, {-1, 1}, {-1, -1}};

/// Chooses each stroke's branch (and hand pitch, with four or more joints)
/// for the best margin; returns the design's worst margin, which is below
/// `cutoff` when it gave up early.
double choose_branches(const task::SpatialTask& task, const Scorer& scorer,
                       kinematics::YawPitchDesign& d,
                       const std::vector<std::vector<ScoringPoint>>& strokes,
                       const std::vector<double>& pitch_grid, double cutoff) {
    const int hands = d.hand_links();
    const int m = static_cast<int>(task.trajectory.size());
    d.branches.assign(strokes.size(), kBranches[0]);
    if (hands > 0) d.pitches.assign(static_cast<std::size_t>(m), {});
    double worst = kInf;
    for (std::size_t s = 0; s < strokes.size(); ++s) {
        double best = -kInf;
        kinematics::IkBranch best_branch = kBranches[0];
        double best_pitch = 0.0;
        const std::vector<double> no_pitch{0.0};
        for (double pitch : hands > 0 ? pitch_grid : no_pitch) {
            if (hands > 0)
                for (int j = task::stroke_first(task, static_cast<int>(s));
                     j <= task::stroke_last(task, static_cast<int>(s)); ++j)
                    d.pitches[static_cast<std::size_t>(j)].assign(static_cast<std::size_t>(hands),
                                                                  {pitch, pitch});
            for (const auto& branch : kBranches) {
                const double v =
                    stroke_margin(scorer, d, strokes[s], branch, std::max(best, cutoff));
                if (v > best) best = v, best_branch = branch, best_pitch = pitch;
            }
        }
        d.branches[s] = best_branch;
        if (hands > 0)
            for (int j = task::stroke_first(task, static_cast<int>(s));
                 j <= task::stroke_last(task, static_cast<int>(s)); ++j)
                d.pitches[static_cast<std::size_t>(j)].assign(static_cast<std::size_t>(hands),
                                                              {best_pitch, best_pitch});
        worst = std::min(worst, best);
        if (worst < cutoff) break;
    }
    return worst;
}

double chain_length(const kinematics::YawPitchArm& arm) {
    double l = std::abs(arm.column);
    for (double a : arm.links) l += a;
    return l;
}

bool near(const kinematics::YawPitchDesign& a, const kinematics::YawPitchDesign& b, double tol) {
    if ((a.arm.base - b.arm.base).norm() > tol || std::abs(a.arm.column - b.arm.column) > tol)
        return false;
    for (std::size_t k = 0; k < a.arm.links.size(); ++k)
        if (std::abs(a.arm.links[k] - b.arm.links[k]) > tol) return false;
    return true;
}

}  // namespace

bool SpatialGuessOptions::IsValid(std::string* error) const {
    return text::OptionCheck("SpatialGuessOptions", error)
        .greater("scoring_spacing", scoring_spacing, 0.0)
        .at_least("max_points", max_points, 2)
        .at_least("candidates", candidates, 1)
        .at_least("hand_pitches", hand_pitches, 1)
        .at_least("max_pitch", max_pitch, 0.0)
        .at_least("distinct_distance", distinct_distance, 0.0)
        .ok();
}

double design_margin(const task::SpatialTask& task, const kinematics::YawPitchDesign& design,
                     int column, const nlp::SpatialMargins& margins, double spacing,
                     int max_points) {
    const Scorer scorer(task, margins, column);
    const auto strokes = scoring_points(task, spacing, max_points);
    double worst = kInf;
    for (std::size_t s = 0; s < strokes.size(); ++s)
        worst =
            std::min(worst, stroke_margin(scorer, design, strokes[s], design.branches[s], -kInf));
    return worst;
}

std::vector<ScoredDesign> spatial_initial_guesses(const task::SpatialTask& task,
                                                  const smt::SpatialSkeleton& skeleton, int count,
                                                  unsigned seed, const nlp::SpatialMargins& margins,
                                                  const run::Deadline& deadline,
                                                  const SpatialGuessOptions& options) {
    text::require_valid(options);
    const auto& spec = task.robot;
    const double lo = spec.min_link_length, hi = spec.max_link_length;
    const int n = skeleton.dof;
    const int hands = n - 3;
    const auto strokes = scoring_points(task, options.scoring_spacing, options.max_points);
    // A few points per stroke give the reach the links are drawn for.
    std::vector<Vec3> probe;
    Vec3 pmin = Vec3::Constant(kInf), pmax = Vec3::Constant(-kInf);
    for (const auto& stroke : strokes)
        for (std::size_t i = 0; i < stroke.size();
             i += std::max<std::size_t>(1, stroke.size() / 48)) {
            probe.push_back(stroke[i].p);
            pmin = pmin.cwiseMin(stroke[i].p);
            pmax = pmax.cwiseMax(stroke[i].p);
        }
    geometry::Box3 box;
    if (skeleton.base_region >= 0) {
        box = task.base_regions[static_cast<std::size_t>(skeleton.base_region)];
    } else {
        const Vec3 grow = Vec3::Constant(std::min(hi, 1.0));
        box = {pmin - grow, pmax + grow};
    }
    std::vector<double> pitch_grid;
    for (int i = 0; i < options.hand_pitches; ++i)
        pitch_grid.push_back(options.hand_pitches == 1
                                 ? 0.0
                                 : -options.max_pitch +
                                       2.0 * options.max_pitch * i / (options.hand_pitches - 1));

    std::mt19937 rng(seed * 7919u + static_cast<unsigned>(skeleton.column + 2) * 131u +
                     static_cast<unsigned>(skeleton.base_region + 2) * 17u +
                     static_cast<unsigned>(n) * 7u);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<kinematics::YawPitchDesign> drawn;
    for (int c = 0; c < options.candidates; ++c) {
        kinematics::YawPitchDesign d;
        d.link_diameter = spec.link_diameter;
        d.arm.column_twist = skeleton.column_twist;
        for (int i = 0; i < 3; ++i) d.arm.base[i] = box.min[i] + u(rng) * (box.max[i] - box.min[i]);
        if (skeleton.column != 0) {
            const double sign = skeleton.column;
            // Half the draws aim the shoulder at the path's heights.
            double mag = lo + u(rng) * (hi - lo);
            if (c % 2 == 1) {
                const double z = pmin.z() - 0.2 + u(rng) * (pmax.z() - pmin.z() + 0.4);
                const double want = sign * (z - d.arm.base.z());
                if (want >= lo && want <= hi) mag = want;
            }
            d.arm.column = sign * mag;
        }
        const Vec3 shoulder = d.arm.shoulder();
        double far = 0.0, close = kInf;
        for (const Vec3& p : probe) {
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
        d.arm.links = {std::clamp(0.5 * (sum + diff), lo, hi),
                       std::clamp(0.5 * (sum - diff), lo, hi)};
        for (double a : hand_links) d.arm.links.push_back(a);
        d.arm.links.back() = std::max(d.arm.links.back(), std::min(hi, spec.tool_length));
        drawn.push_back(std::move(d));
    }
    // Shortest first: the first clear ones are the answer.
    std::stable_sort(drawn.begin(), drawn.end(), [](const auto& a, const auto& b) {
        return chain_length(a.arm) < chain_length(b.arm);
    });
    const Scorer scorer(task, margins, skeleton.column);
    std::vector<ScoredDesign> clear, unclear;
    for (std::size_t i = 0; i < drawn.size(); ++i) {
        if (i % 16 == 0 && deadline.expired()) break;
        auto& d = drawn[i];
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
        const double margin = choose_branches(task, scorer, d, strokes, pitch_grid, cutoff);
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
