#include <modsynth/explanation/wall_changes.h>
#include <modsynth/geometry/distance.h>
#include <modsynth/geometry/polygon.h>
#include <modsynth/prove/no_go.h>
#include <modsynth/text/format.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

namespace modsynth::explanation {
namespace {

using geometry::Vec2;
using prove::kNoGoSlack;
using prove::no_go_discs;
using prove::overlap;
using prove::path_points;
using prove::Proof;
using prove::prove_obstacle_infeasible;
using prove::RouteStep;

bool breaks(const task::Task& changed) { return !prove_obstacle_infeasible(changed).has_value(); }

std::string obstacle(int i) { return task::to_string(task::TaskPart::obstacle(i)); }

double ceil_mm(double metres) { return std::ceil(metres * 1000.0 - 1e-9) / 1000.0; }

std::vector<int> core_obstacles(const Proof& proof) {
    std::vector<int> out;
    for (const task::TaskPart& p : proof.core)
        if (p.kind() == task::TaskPart::Kind::Obstacle) out.push_back(p.index());
    return out;
}

// How far obstacle i lies from the straight way between a base region and
// the path point its wall (or detour) keeps out: the wall opens for an arm
// where it faces that way.
double off_the_way(const task::Task& task, const Proof& proof, int i) {
    const Vec2 c = task.obstacles[i].center;
    double near = 1e300;
    const auto way = [&](int region, const Vec2& point) {
        const auto& r = task.base_regions[region];
        near = std::min(near, geometry::point_segment(c, 0.5 * (r.min + r.max), point));
    };
    if (proof.separation)
        for (const auto& w : proof.separation->walls) way(w.base_region, w.point);
    if (proof.geodesic)
        for (const auto& d : proof.geodesic->detours) way(d.base_region, d.point);
    return near;
}

// The obstacle that faces the way from the base to the path first (taking
// one away elsewhere leaves the arm to reach round the rest), then the
// smallest: its removal is the least change.
std::vector<WallChange> removals(const task::Task& task, const Proof& proof, std::size_t most) {
    std::vector<int> order = core_obstacles(proof);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
        const double fa = std::round(off_the_way(task, proof, a) * 1000.0);
        const double fb = std::round(off_the_way(task, proof, b) * 1000.0);
        if (fa != fb) return fa < fb;
        return task.obstacles[a].radius < task.obstacles[b].radius;
    });
    std::vector<WallChange> out;
    for (int i : order) {
        if (out.size() >= most) break;
        task::Task t = task;
        t.obstacles.erase(t.obstacles.begin() + i);
        if (!breaks(t)) continue;
        out.push_back({task::TaskPart::obstacle(i),
                       "remove " + obstacle(i) +
                           text::format(" (radius %.3f m)", task.obstacles[i].radius) +
                           (proof.separation ? ": the wall opens" : ": the way around shortens"),
                       std::move(t)});
    }
    return out;
}

struct Pair {
    int i, j;
    double order;  // smaller first
};

// The pairs of overlapping no-go discs a gap could open between: the wall's
// neighbours (the shallowest overlap first), or for a detour every
// overlapping pair of the core, nearest the straight way first.
std::vector<Pair> gap_pairs(const task::Task& task, const Proof& proof) {
    std::vector<Pair> out;
    std::set<std::pair<int, int>> seen;
    const auto add = [&](int i, int j, double order) {
        if (seen.insert({std::min(i, j), std::max(i, j)}).second) out.push_back({i, j, order});
    };
    if (proof.separation) {
        for (const auto& w : proof.separation->walls)
            for (std::size_t k = 0; k < w.cycle.size(); ++k)
                add(w.cycle[k], w.cycle[(k + 1) % w.cycle.size()],
                    k < w.overlaps.size() ? w.overlaps[k] : 0.0);
    } else if (proof.geodesic) {
        const auto ids = core_obstacles(proof);
        const auto discs = no_go_discs(task, ids);
        for (std::size_t a = 0; a < discs.size(); ++a) {
            for (std::size_t b = a + 1; b < discs.size(); ++b) {
                if (overlap(discs[a], discs[b]) <= kNoGoSlack) continue;
                const Vec2 mid = 0.5 * (discs[a].center + discs[b].center);
                double near = 1e300;
                for (const auto& d : proof.geodesic->detours) {
                    const auto& r = task.base_regions[d.base_region];
                    near = std::min(near,
                                    geometry::point_segment(mid, 0.5 * (r.min + r.max), d.point));
                }
                add(ids[a], ids[b], near);
            }
        }
    }
    std::stable_sort(out.begin(), out.end(),
                     [](const Pair& a, const Pair& b) { return a.order < b.order; });
    return out;
}

std::vector<WallChange> widenings(const task::Task& task, const Proof& proof, std::size_t most) {
    const double tube = task.robot.link_diameter;
    const double wanted = tube + kGapMargin;
    std::vector<WallChange> out;
    for (const Pair& p : gap_pairs(task, proof)) {
        if (out.size() >= most) break;
        const auto& a = task.obstacles[p.i];
        const auto& b = task.obstacles[p.j];
        const double dist = (b.center - a.center).norm();
        const double gap = dist - a.radius - b.radius;  // < 0 when the obstacles overlap
        const double apart = ceil_mm(wanted - gap);     // centres this much further apart
        const std::string head = "widen the gap between " + obstacle(p.i) + " and " +
                                 obstacle(p.j) + text::format(" to at least %.3f m", gap + apart) +
                                 (gap < 0.0 ? text::format(" (now they overlap by %.3f m", -gap)
                                            : text::format(" (now %.3f m", gap)) +
                                 text::format("; the tube is %.4f m thick)", tube);
        const Vec2 u = dist > 0.0 ? Vec2((b.center - a.center) / dist) : Vec2(1.0, 0.0);
        // Moving the second obstacle away, the first away, or shrinking both.
        task::Task t = task;
        t.obstacles[p.j].center += apart * u;
        if (breaks(t)) {
            out.push_back(
                {task::TaskPart::obstacle(p.j),
                 head + text::format(": move %s %.3f m", obstacle(p.j).c_str(), apart) +
                     text::format(" further from %s, to (%.3f, %.3f)", obstacle(p.i).c_str(),
                                  t.obstacles[p.j].center.x(), t.obstacles[p.j].center.y()),
                 std::move(t)});
            continue;
        }
        t = task;
        t.obstacles[p.i].center -= apart * u;
        if (breaks(t)) {
            out.push_back(
                {task::TaskPart::obstacle(p.i),
                 head + text::format(": move %s %.3f m", obstacle(p.i).c_str(), apart) +
                     text::format(" further from %s, to (%.3f, %.3f)", obstacle(p.j).c_str(),
                                  t.obstacles[p.i].center.x(), t.obstacles[p.i].center.y()),
                 std::move(t)});
            continue;
        }
        const double shrink = ceil_mm(apart / 2.0);
        if (a.radius - shrink < 0.001 || b.radius - shrink < 0.001) continue;
        t = task;
        t.obstacles[p.i].radius -= shrink;
        t.obstacles[p.j].radius -= shrink;
        if (breaks(t)) {
            out.push_back({task::TaskPart::obstacle(p.i),
                           head + text::format(": make both radii %.3f m smaller", shrink),
                           std::move(t)});
        }
    }
    return out;
}

/// The region moved (same size) so that its centre is at c.
task::Task region_moved(const task::Task& task, std::size_t k, const Vec2& c) {
    task::Task t = task;
    auto& r = t.base_regions[k];
    const Vec2 half = 0.5 * (r.max - r.min);
    r.min = c - half;
    r.max = c + half;
    return t;
}

// A point of the route polyline at distance s from its start (arcs taken as
// chords: the point is only a candidate, the proof re-checks the move).
Vec2 along(const std::vector<RouteStep>& route, double s) {
    for (std::size_t k = 1; k < route.size(); ++k) {
        const Vec2 a = route[k - 1].point, b = route[k].point;
        const double l = (b - a).norm();
        if (s <= l && l > 0.0) return a + (s / l) * (b - a);
        s -= l;
    }
    return route.back().point;
}

std::vector<WallChange> moves(const task::Task& task, const Proof& proof, std::size_t most) {
    // Candidate centres and what they are, best first.
    std::vector<std::pair<Vec2, std::string>> targets;
    const auto points = path_points(task);
    Vec2 centroid = Vec2::Zero();
    for (const auto& p : points) centroid += p.point;
    if (!points.empty()) centroid /= static_cast<double>(points.size());
    if (proof.separation) {
        for (const auto& w : proof.separation->walls) {
            std::vector<Vec2> poly;
            for (int i : w.cycle) poly.push_back(task.obstacles[i].center);
            const bool around_path = geometry::winding_number(poly, w.point) != 0;
            const std::string where = around_path ? "inside the wall, with the path"
                                                  : "outside the wall, on the path's side";
            targets.push_back({centroid, where});
            if (around_path) {
                Vec2 middle = Vec2::Zero();
                for (const Vec2& c : poly) middle += c;
                targets.push_back({middle / static_cast<double>(poly.size()), where});
            }
            targets.push_back({0.5 * (centroid + w.point), where});
            targets.push_back({w.point, where});
        }
    } else if (proof.geodesic) {
        const double reach = proof.geodesic->reach;
        for (const auto& d : proof.geodesic->detours) {
            double length = 0.0;
            for (std::size_t k = 1; k < d.route.size(); ++k)
                length += (d.route[k].point - d.route[k - 1].point).norm();
            for (double share : {0.5, 0.3, 0.7, 0.9})
                targets.push_back({along(d.route, std::max(0.0, length - share * reach)),
                                   "on the detour, " + text::format("%.2f m", share * reach) +
                                       " from trajectory[" + std::to_string(d.primitive) +
                                       "] the way around"});
        }
        targets.push_back({centroid, "beside the path"});
    }
    std::vector<WallChange> out;
    for (const auto& [c, where] : targets) {
        if (out.size() >= most) break;
        // The region nearest the target moves.
        std::size_t k = 0;
        double best = 1e300;
        for (std::size_t r = 0; r < task.base_regions.size(); ++r) {
            const auto& b = task.base_regions[r];
            const double d = geometry::point_box(c, b.min, b.max);
            if (d < best) best = d, k = r;
        }
        const Vec2 at(std::round(c.x() * 1000.0) / 1000.0, std::round(c.y() * 1000.0) / 1000.0);
        task::Task t = region_moved(task, k, at);
        if (!breaks(t)) continue;
        const auto& r = t.base_regions[k];
        out.push_back({task::TaskPart::base_regions(),
                       "move " + task::to_string(task::TaskPart::base_region(static_cast<int>(k))) +
                           text::format(" to [%.3f, %.3f] x", r.min.x(), r.max.x()) +
                           text::format(" [%.3f, %.3f]", r.min.y(), r.max.y()) + " (" + where + ")",
                       std::move(t)});
    }
    return out;
}

}  // namespace

std::vector<std::vector<WallChange>> wall_changes(const task::Task& task, const Proof& proof,
                                                  std::size_t per_kind) {
    return {removals(task, proof, per_kind), widenings(task, proof, per_kind),
            moves(task, proof, per_kind)};
}

}  // namespace modsynth::explanation
