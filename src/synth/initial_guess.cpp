#include <modsynth/synth/initial_guess.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include <modsynth/geometry/distance.h>
#include <modsynth/kinematics/kinematics.h>

namespace modsynth::synth {
namespace {

using geometry::Vec2;

std::vector<Vec2> path_points(const task::Task& task, double spacing) {
    std::vector<Vec2> pts;
    for (const auto& p : task.trajectory) {
        const double len = geometry::length(p);
        const int n = std::max(4, static_cast<int>(std::ceil(len / spacing)));
        for (int i = 0; i <= n; ++i) pts.push_back(geometry::point_at(p, len * i / n));
    }
    return pts;
}

double margin_at(const task::Task& task, const kinematics::Robot& robot, const std::vector<Vec2>& pts) {
    const double r1 = robot.link_lengths[0], r2 = robot.link_lengths[1];
    const double diam = task.robot.link_diameter;
    double worst = std::numeric_limits<double>::infinity();
    for (const Vec2& p : pts) {
        const double d = (p - robot.base).norm();
        const double reach = std::min(r1 + r2 - d, d - std::abs(r1 - r2));
        if (reach <= 0.0) {
            worst = std::min(worst, reach);
            continue;
        }
        const auto ik = kinematics::inverse_two_link(robot.base, r1, r2, p, robot.elbow);
        if (!ik) {
            worst = std::min(worst, 0.0);
            continue;
        }
        const Vec2 e = robot.base + r1 * geometry::unit(ik->phi1);
        // The smooth self-collision bound the refinement uses: height of p
        // above the line of link 1.
        worst = std::min(worst, std::abs(geometry::cross(e - robot.base, p - robot.base)) / r1 - diam);
        for (const auto& ob : task.obstacles) {
            const double need = ob.radius + diam / 2;
            worst = std::min({worst, geometry::point_segment(ob.center, robot.base, e) - need,
                              geometry::point_segment(ob.center, e, p) - need});
        }
    }
    return worst;
}

}  // namespace

double path_margin(const task::Task& task, const kinematics::Robot& robot, double spacing) {
    return margin_at(task, robot, path_points(task, spacing));
}

std::vector<ScoredRobot> initial_guesses(const task::Task& task, const smt::Skeleton& skeleton,
                                         int count, unsigned seed) {
    const auto pts = path_points(task, 0.02);
    const double lo = task.robot.min_link_length, hi = task.robot.max_link_length;
    Vec2 bmin, bmax;
    if (skeleton.base_region >= 0) {
        bmin = task.base_regions[skeleton.base_region].min;
        bmax = task.base_regions[skeleton.base_region].max;
    } else {
        // No region: around the path, as far as the longest arm reaches.
        bmin = bmax = pts.front();
        for (const Vec2& p : pts) bmin = bmin.cwiseMin(p), bmax = bmax.cwiseMax(p);
        bmin -= Vec2::Constant(hi);
        bmax += Vec2::Constant(hi);
    }
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
        all.push_back({robot, margin_at(task, robot, pts)});
    };
    if (skeleton.link_lengths.size() == 2)
        consider(skeleton.base, skeleton.link_lengths[0], skeleton.link_lengths[1]);
    constexpr int kCandidates = 600;
    for (int i = 0; i < kCandidates; ++i) {
        const Vec2 base(bmin.x() + u(rng) * (bmax.x() - bmin.x()), bmin.y() + u(rng) * (bmax.y() - bmin.y()));
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
    std::stable_sort(all.begin(), all.end(), [](const ScoredRobot& a, const ScoredRobot& b) {
        const bool ca = a.margin >= 0.0, cb = b.margin >= 0.0;
        if (ca != cb) return ca;
        if (ca) return a.robot.total_length() < b.robot.total_length();
        return a.margin > b.margin;
    });
    // Keep candidates that differ: a second start near the first adds little.
    std::vector<ScoredRobot> out;
    for (const auto& c : all) {
        const bool distinct = std::none_of(out.begin(), out.end(), [&](const ScoredRobot& o) {
            return (o.robot.base - c.robot.base).norm() < 0.02 &&
                   std::abs(o.robot.link_lengths[0] - c.robot.link_lengths[0]) < 0.02 &&
                   std::abs(o.robot.link_lengths[1] - c.robot.link_lengths[1]) < 0.02;
        });
        if (distinct) out.push_back(c);
        if (static_cast<int>(out.size()) >= count) break;
    }
    return out;
}

}  // namespace modsynth::synth
