#include <modsynth/synth/initial_guess.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>

#include <modsynth/geometry/distance.h>
#include <modsynth/kinematics/chain_layout.h>
#include <modsynth/kinematics/clearance_rule.h>
#include <modsynth/kinematics/kinematics.h>
#include <modsynth/task/strokes.h>
#include <modsynth/text/option_check.h>

namespace modsynth::synth {
namespace {

using geometry::Vec2;

// At most options.max_points_per_primitive points a primitive, and the
// spacing widened when the whole path would need more than
// options.max_points.
std::vector<Vec2> path_points(const task::Task& task, double spacing,
                              const InitialGuessOptions& options) {
    double total = 0.0;
    for (const auto& p : task.trajectory) total += geometry::length(p);
    spacing = std::max(spacing, total / static_cast<double>(options.max_points));
    // Many primitives: their ends and critical points carry the shape.
    const double fewest = task.trajectory.size() > 1000 ? 1.0 : 4.0;
    std::vector<Vec2> pts;
    for (const auto& p : task.trajectory) {
        const double len = geometry::length(p);
        const int n =
            static_cast<int>(std::clamp(std::ceil(len / spacing), fewest,
                                        static_cast<double>(options.max_points_per_primitive)));
        for (int i = 0; i <= n; ++i) pts.push_back(geometry::point_at(p, len * i / n));
    }
    return pts;
}

// Worst margin of the distal pair (lengths a, c) turning about `origin`
// with the EE at p: reach, the refinement's smooth self-collision bound
// (height of p above the line of the first distal link) and obstacle
// clearance of both distal links; with three joints also the static link 1
// (base to origin) against the obstacles and the EE.
double pose_margin(const task::Task& task, const Vec2& base, const Vec2& origin, double a, double c,
                   int elbow, bool proximal, const Vec2& p) {
    const kinematics::ClearanceRule rule{task.robot.link_diameter};
    const double d = (p - origin).norm();
    const double reach = std::min(a + c - d, d - std::abs(a - c));
    if (reach <= 0.0) return reach;
    const auto ik = kinematics::inverse_two_link(origin, a, c, p, elbow);
    if (!ik) return 0.0;
    const Vec2 e = origin + a * geometry::unit(ik->phi1);
    double worst = std::abs(geometry::cross(e - origin, p - origin)) / a - rule.self_distance();
    if (proximal) worst = std::min(worst, rule.self_margin(p, base, origin));
    for (const auto& ob : task.obstacles) {
        worst = std::min({worst, rule.link_margin(ob, origin, e), rule.link_margin(ob, e, p)});
        if (proximal) worst = std::min(worst, rule.link_margin(ob, base, origin));
    }
    return worst;
}

// The worst margin over pts; or, once it falls below stop_below, some
// margin below stop_below (the scoring of that robot stops there).
double margin_at(const task::Task& task, const kinematics::Robot& robot,
                 const std::vector<Vec2>& pts,
                 double stop_below = -std::numeric_limits<double>::infinity()) {
    double worst = std::numeric_limits<double>::infinity();
    for (const Vec2& p : pts) {
        worst = std::min(worst, pose_margin(task, robot.base, robot.base, robot.link_lengths[0],
                                            robot.link_lengths[1], robot.elbow, false, p));
        if (worst < stop_below) break;
    }
    return worst;
}

// Three joints: chooses the proximal angle of each primitive (from `angles`
// candidates) to maximise the worst margin over the traces and the sweeps
// between them (a Viterbi pass). Returns the margin; fills proximal_angles.
double choose_proximal_angles(const task::Task& task, kinematics::Robot& robot,
                              const std::vector<std::vector<Vec2>>& per_primitive,
                              const InitialGuessOptions& options) {
    const int angles = options.proximal_angles;
    const int m = static_cast<int>(task.trajectory.size());
    const double a = robot.link_lengths[1], c = robot.link_lengths[2];
    constexpr double kNone = -std::numeric_limits<double>::infinity();
    auto theta = [&](int k) { return geometry::kTau * k / angles; };
    auto origin = [&](double q1) { return robot.distal_origin(q1); };
    std::vector<std::vector<double>> trace(m, std::vector<double>(angles, kNone));
    for (int j = 0; j < m; ++j) {
        for (int k = 0; k < angles; ++k) {
            double w = std::numeric_limits<double>::infinity();
            for (const Vec2& p : per_primitive[j]) {
                w = std::min(
                    w, pose_margin(task, robot.base, origin(theta(k)), a, c, robot.elbow, true, p));
                if (w < -options.hopeless_margin) break;  // hopeless: stop early
            }
            trace[j][k] = w;
        }
    }
    auto sweep = [&](int j, int ka, int kb) {
        const double from = theta(ka), delta = std::remainder(theta(kb) - from, geometry::kTau);
        const int steps =
            std::max(1, static_cast<int>(std::ceil(std::abs(delta) / options.sweep_step)));
        double w = std::numeric_limits<double>::infinity();
        for (int i = 1; i < steps; ++i)
            w = std::min(w, pose_margin(task, robot.base, origin(from + delta * i / steps), a, c,
                                        robot.elbow, true, task.trajectory[j].end));
        return w;
    };
    std::vector<std::vector<double>> best(m, std::vector<double>(angles, kNone));
    std::vector<std::vector<int>> from(m, std::vector<int>(angles, -1));
    best[0] = trace[0];
    for (int j = 1; j < m; ++j) {
        for (int kb = 0; kb < angles; ++kb) {
            if (trace[j][kb] < -options.hopeless_margin) continue;
            for (int ka = 0; ka < angles; ++ka) {
                const double bound = std::min(best[j - 1][ka], trace[j][kb]);
                if (bound <= best[j][kb]) continue;
                // Between strokes the arm travels freely: no sweep to score.
                const double v = task::has_transition_after(task, j - 1)
                                     ? std::min(bound, sweep(j - 1, ka, kb))
                                     : bound;
                if (v > best[j][kb]) best[j][kb] = v, from[j][kb] = ka;
            }
        }
    }
    int k = static_cast<int>(std::max_element(best[m - 1].begin(), best[m - 1].end()) -
                             best[m - 1].begin());
    const double margin = best[m - 1][k];
    robot.proximal_angles.assign(m, 0.0);
    for (int j = m - 1; j >= 0; --j) {
        robot.proximal_angles[j] = theta(std::max(k, 0));
        if (j > 0) k = from[j][std::max(k, 0)];
    }
    return margin;
}

}  // namespace

bool InitialGuessOptions::IsValid(std::string* error) const {
    return text::OptionCheck("InitialGuessOptions", error)
        .greater("scoring_spacing", scoring_spacing, 0.0)
        .at_least("max_points_per_primitive", max_points_per_primitive, 4)
        .at_least("max_points", max_points, 1)
        .at_least("candidates_two", candidates_two, 0)
        .at_least("candidates_three", candidates_three, 0)
        .at_least("candidates_three_detour", candidates_three_detour, 0)
        .at_least("proximal_angles", proximal_angles, 1)
        .greater("sweep_step", sweep_step, 0.0)
        .greater("proximal_spacing", proximal_spacing, 0.0)
        .at_least("max_proximal_points", max_proximal_points, 4)
        .at_least("hopeless_margin", hopeless_margin, 0.0)
        .at_least("distinct_distance", distinct_distance, 0.0)
        .at_least("coarse_primitives", coarse_primitives, 1)
        .ok();
}

double path_margin(const task::Task& task, const kinematics::Robot& robot, double spacing,
                   const InitialGuessOptions& options) {
    text::require_valid(options);
    return margin_at(task, robot, path_points(task, spacing, options));
}

namespace {

Vec2 uniform_in(std::mt19937& rng, const Vec2& lo, const Vec2& hi) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    return {lo.x() + u(rng) * (hi.x() - lo.x()), lo.y() + u(rng) * (hi.y() - lo.y())};
}

void search_region(const task::Task& task, const smt::Skeleton& skeleton,
                   const std::vector<Vec2>& pts, Vec2& lo, Vec2& hi) {
    if (skeleton.base_region >= 0) {
        lo = task.base_regions[skeleton.base_region].min;
        hi = task.base_regions[skeleton.base_region].max;
        return;
    }
    // No region: around the path, as far as the longest arm reaches.
    lo = hi = pts.front();
    for (const Vec2& p : pts) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    const double reach = skeleton.dof * task.robot.max_link_length;
    lo -= Vec2::Constant(reach);
    hi += Vec2::Constant(reach);
}

// Whether robot is within distinct_distance of one of `kept` in its base and
// every link length.
bool near_any(const std::vector<ScoredRobot>& kept, const kinematics::Robot& robot,
              double distinct_distance) {
    return std::any_of(kept.begin(), kept.end(), [&](const ScoredRobot& o) {
        if ((o.robot.base - robot.base).norm() >= distinct_distance) return false;
        for (std::size_t k = 0; k < robot.link_lengths.size(); ++k)
            if (std::abs(o.robot.link_lengths[k] - robot.link_lengths[k]) >= distinct_distance)
                return false;
        return true;
    });
}

bool sort_and_keep_distinct(std::vector<ScoredRobot>& all, int count, double distinct_distance) {
    std::stable_sort(all.begin(), all.end(), [](const ScoredRobot& a, const ScoredRobot& b) {
        const bool ca = a.margin >= 0.0, cb = b.margin >= 0.0;
        if (ca != cb) return ca;
        if (ca) return a.robot.total_length() < b.robot.total_length();
        return a.margin > b.margin;
    });
    // A second start near the first adds little.
    std::vector<ScoredRobot> out;
    for (const auto& c : all) {
        if (!near_any(out, c.robot, distinct_distance)) out.push_back(c);
        if (static_cast<int>(out.size()) >= count) break;
    }
    all = std::move(out);
    return !all.empty();
}

// Clear candidates rank by length alone (sort_and_keep_distinct): so walk
// them shortest first, score each only as far as telling clear from not
// (`until_unclear` may stop at its first unclear point), and stop at `count`
// distinct clear ones. Where clear candidates are common most of the
// scoring is saved; the choice is the same. Scoring stops at the deadline:
// the candidates scored by then are kept.
template <class UntilUnclear, class Whole>
std::vector<ScoredRobot> choose_candidates(std::vector<ScoredRobot> all, int count,
                                           double distinct_distance, run::Deadline deadline,
                                           UntilUnclear&& until_unclear, Whole&& whole) {
    const auto in_time = [&](std::size_t k) { return k % 16 != 0 || !deadline.expired(); };
    std::vector<std::size_t> order(all.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return all[a].robot.total_length() < all[b].robot.total_length();
    });
    std::vector<ScoredRobot> clear;
    std::vector<bool> partial(all.size(), false);
    std::size_t scored = 0;
    for (std::size_t i : order) {
        if (near_any(clear, all[i].robot, distinct_distance)) continue;
        if (!in_time(scored++)) break;
        all[i].margin = until_unclear(all[i].robot);
        if (all[i].margin < 0.0) {
            partial[i] = true;
            continue;
        }
        clear.push_back(all[i]);
        if (static_cast<int>(clear.size()) >= count) return clear;
    }
    // Too few are clear: the others rank by their worst margin, scored whole.
    for (std::size_t i = 0; i < all.size(); ++i)
        if ((std::isnan(all[i].margin) || partial[i]) && in_time(scored++))
            all[i].margin = whole(all[i].robot);
    std::erase_if(all, [](const ScoredRobot& c) { return std::isnan(c.margin); });
    sort_and_keep_distinct(all, count, distinct_distance);
    return all;
}

// The path as chords through every k-th end of each stroke's primitives,
// at most `most` a stroke (the stroke's own end always included); `chord`
// gets the chord each primitive of `task` starts on.
task::Task coarse_path(const task::Task& task, int most, std::vector<int>& chord) {
    task::Task coarse = task;
    coarse.trajectory.clear();
    coarse.stroke_starts.clear();
    chord.assign(task.trajectory.size(), 0);
    for (int s = 0; s < task::stroke_count(task); ++s) {
        const int first = task::stroke_first(task, s), last = task::stroke_last(task, s);
        const int n = last - first + 1;
        const int k = (n + most - 1) / most;
        if (task::has_strokes(task))
            coarse.stroke_starts.push_back(static_cast<int>(coarse.trajectory.size()));
        for (int i = 0; i < n; i += k) {
            const int to = std::min(n, i + k) - 1;
            for (int j = i; j <= to; ++j)
                chord[first + j] = static_cast<int>(coarse.trajectory.size());
            const Vec2 a = geometry::point_at(task.trajectory[first + i], 0.0);
            const Vec2 b = task.trajectory[first + to].end;
            // A closed primitive (a circle) stays itself: its chord is a point.
            coarse.trajectory.push_back((b - a).norm() > 1e-9 ? geometry::make_line(a, b)
                                                              : task.trajectory[first + i]);
        }
    }
    return coarse;
}

std::vector<ScoredRobot> three_link_guesses(const task::Task& task, const smt::Skeleton& skeleton,
                                            int count, unsigned seed, run::Deadline deadline,
                                            const InitialGuessOptions& options) {
    const auto pts = path_points(task, options.scoring_spacing, options);
    std::vector<std::vector<Vec2>> per_primitive;
    double span = 0.0;
    for (const auto& prim : task.trajectory) {
        const double len = geometry::length(prim);
        // Capped: the span below is quadratic in it.
        const int n =
            static_cast<int>(std::clamp(std::ceil(len / options.proximal_spacing), 4.0,
                                        static_cast<double>(options.max_proximal_points)));
        per_primitive.emplace_back();
        for (int i = 0; i <= n; ++i)
            per_primitive.back().push_back(geometry::point_at(prim, len * i / n));
        for (const Vec2& a : per_primitive.back())
            for (const Vec2& b : per_primitive.back()) span = std::max(span, (a - b).norm());
    }
    Vec2 lo, hi;
    search_region(task, skeleton, pts, lo, hi);
    const double lmin = task.robot.min_link_length, lmax = task.robot.max_link_length;
    std::mt19937 rng(seed * 7919u + static_cast<unsigned>(skeleton.elbow + 2) * 131u +
                     static_cast<unsigned>(skeleton.base_region + 1));
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<ScoredRobot> all;
    auto consider = [&](std::mt19937& gen, auto&& links) {
        kinematics::Robot robot;
        robot.base = uniform_in(gen, lo, hi);
        robot.link_diameter = task.robot.link_diameter;
        robot.elbow = skeleton.elbow;
        double far = 0.0;
        for (const Vec2& p : pts) far = std::max(far, (p - robot.base).norm());
        robot.link_lengths = links(far);
        all.push_back({robot, std::numeric_limits<double>::quiet_NaN()});
    };
    for (int i = 0; i < options.candidates_three; ++i) {
        consider(rng, [&](double far) {
            // The distal pair must cover each primitive from one point; the
            // whole arm must reach the farthest point.
            const double distal =
                std::max(span / 2.0 * (1.1 + 0.6 * u(rng)), 0.6 * far * u(rng)) + 0.02;
            const double a = std::clamp(distal * (0.35 + 0.3 * u(rng)), lmin, lmax);
            const double c = std::clamp(distal - a, lmin, lmax);
            const double r1 = std::clamp((far - (a + c) * (0.5 + 0.4 * u(rng))), lmin, lmax);
            return std::vector<double>{r1, a, c};
        });
    }
    // A stream of its own, so that the compact candidates stay as they were.
    std::mt19937 detour(seed * 104729u + static_cast<unsigned>(skeleton.elbow + 2) * 17u +
                        static_cast<unsigned>(skeleton.base_region + 1));
    for (int i = 0; i < options.candidates_three_detour; ++i) {
        consider(detour, [&](double far) {
            const double r1 = std::clamp(far * (0.2 + u(detour)), lmin, lmax);
            const double a = std::clamp(far * (0.3 + 2.0 * u(detour)), lmin, lmax);
            const double c = std::clamp(far * (0.3 + 2.0 * u(detour)), lmin, lmax);
            return std::vector<double>{r1, a, c};
        });
    }
    const auto score = [&](kinematics::Robot& robot) {
        return choose_proximal_angles(task, robot, per_primitive, options);
    };
    return choose_candidates(std::move(all), count, options.distinct_distance, deadline, score,
                             score);
}

}  // namespace

std::vector<ScoredRobot> initial_guesses(const task::Task& task, const smt::Skeleton& skeleton,
                                         int count, unsigned seed, run::Deadline deadline,
                                         const InitialGuessOptions& options) {
    text::require_valid(options);
    if (kinematics::has_proximal_link(skeleton.dof)) {
        bool long_stroke = false;
        for (int s = 0; s < task::stroke_count(task); ++s)
            long_stroke = long_stroke || task::stroke_last(task, s) - task::stroke_first(task, s) >=
                                             options.coarse_primitives;
        if (!long_stroke) return three_link_guesses(task, skeleton, count, seed, deadline, options);
        std::vector<int> chord;
        const task::Task coarse = coarse_path(task, options.coarse_primitives, chord);
        auto guesses = three_link_guesses(coarse, skeleton, count, seed, deadline, options);
        for (ScoredRobot& g : guesses) {
            std::vector<double> angles(task.trajectory.size());
            for (std::size_t j = 0; j < angles.size(); ++j)
                angles[j] = g.robot.proximal_angles.at(chord[j]);
            g.robot.proximal_angles = std::move(angles);
        }
        return guesses;
    }
    const auto pts = path_points(task, options.scoring_spacing, options);
    const double lo = task.robot.min_link_length, hi = task.robot.max_link_length;
    Vec2 bmin, bmax;
    search_region(task, skeleton, pts, bmin, bmax);
    std::mt19937 rng(seed * 7919u + static_cast<unsigned>(skeleton.elbow + 2) * 31u +
                     static_cast<unsigned>(skeleton.base_region + 1));
    std::uniform_real_distribution<double> u(0.0, 1.0);

    std::vector<ScoredRobot> all;
    auto consider = [&](const Vec2& base, double r1, double r2) {
        if (!(r1 >= lo && r1 <= hi && r2 >= lo && r2 <= hi)) return;
        kinematics::Robot robot;
        robot.base = base;
        robot.link_lengths = {r1, r2};
        robot.link_diameter = task.robot.link_diameter;
        robot.elbow = skeleton.elbow;
        all.push_back({robot, std::numeric_limits<double>::quiet_NaN()});
    };
    if (skeleton.link_lengths.size() == 2)
        consider(skeleton.base, skeleton.link_lengths[0], skeleton.link_lengths[1]);
    for (int i = 0; i < options.candidates_two && (i % 16 != 0 || !deadline.expired()); ++i) {
        const Vec2 base(bmin.x() + u(rng) * (bmax.x() - bmin.x()),
                        bmin.y() + u(rng) * (bmax.y() - bmin.y()));
        double far = 0.0, near = std::numeric_limits<double>::infinity();
        for (const auto& prim : task.trajectory) {
            const auto cp = geometry::critical_points(prim, base);
            far = std::max(far, cp.farthest.distance);
            near = std::min(near, cp.closest.distance);
        }
        // Links that reach the farthest point with some spare and whose
        // difference keeps the closest point outside the inner circle.
        const double sum = far * (1.02 + 0.5 * u(rng)) + 0.01;
        const double diff = (2.0 * u(rng) - 1.0) * std::max(0.0, near - 0.01);
        consider(base, 0.5 * (sum + diff), 0.5 * (sum - diff));
    }
    return choose_candidates(
        std::move(all), count, options.distinct_distance, deadline,
        [&](const kinematics::Robot& robot) { return margin_at(task, robot, pts, 0.0); },
        [&](const kinematics::Robot& robot) { return margin_at(task, robot, pts); });
}

}  // namespace modsynth::synth
