#include "witness_checker.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <set>

namespace modsynth::testing {
namespace {

using geometry::Vec2;

double no_go(const task::Task& t, int i) {
    return t.obstacles.at(i).radius + t.robot.link_diameter / 2;
}

double seg_dist(const Vec2& p, const Vec2& a, const Vec2& b) {
    const Vec2 d = b - a;
    const double l2 = d.squaredNorm();
    const double u = l2 == 0 ? 0.0 : std::clamp((p - a).dot(d) / l2, 0.0, 1.0);
    return (a + u * d - p).norm();
}

// Parity of crossings of the ray from p in a fixed odd direction with the
// closed polygon: odd means the polygon winds an odd number of times.
int ray_parity(const std::vector<Vec2>& poly, const Vec2& p) {
    const Vec2 dir(std::cos(0.7316), std::sin(0.7316));
    int crossings = 0;
    for (std::size_t k = 0; k < poly.size(); ++k) {
        const Vec2 a = poly[k] - p, b = poly[(k + 1) % poly.size()] - p;
        const double den = dir.x() * (b - a).y() - dir.y() * (b - a).x();
        if (den == 0) continue;
        const double t = (a.x() * (b - a).y() - a.y() * (b - a).x()) / den;  // along the ray
        const double s = (a.x() * dir.y() - a.y() * dir.x()) / den;          // along the edge
        if (t > 0 && s >= 0 && s < 1) ++crossings;
    }
    return crossings % 2;
}

double on_path(const task::Task& t, int j, const Vec2& p) {
    const auto& prim = t.trajectory.at(j);
    // Dense sampling is enough to tell "on it" (the witness points are
    // starts, middles and ends).
    double best = 1e300;
    const double len = geometry::length(prim);
    for (int i = 0; i <= 2000; ++i)
        best = std::min(best, (geometry::point_at(prim, len * i / 2000) - p).norm());
    return best;
}

bool free_of(const task::Task& t, const std::vector<int>& obstacles, const Vec2& a, const Vec2& b,
             double slack) {
    for (int i : obstacles)
        if (seg_dist(t.obstacles.at(i).center, a, b) < no_go(t, i) - slack) return false;
    return true;
}

std::vector<int> every(const task::Task& t) {
    std::vector<int> out;
    for (int i = 0; i < static_cast<int>(t.obstacles.size()); ++i) out.push_back(i);
    return out;
}

}  // namespace

std::string check_separation_witness(const task::Task& t, const prove::SeparationWitness& w) {
    if (w.walls.size() != t.base_regions.size()) return "not one wall per base region";
    for (const auto& wall : w.walls) {
        const std::string at = "wall of base_regions[" + std::to_string(wall.base_region) + "]: ";
        const auto& c = wall.cycle;
        if (c.size() < 3) return at + "fewer than 3 obstacles";
        if (std::set<int>(c.begin(), c.end()).size() != c.size()) return at + "an obstacle repeats";
        if (wall.overlaps.size() != c.size()) return at + "overlaps do not match the cycle";
        std::vector<Vec2> poly;
        for (std::size_t k = 0; k < c.size(); ++k) {
            if (c[k] < 0 || c[k] >= static_cast<int>(t.obstacles.size()))
                return at + "no such obstacle";
            const int a = c[k], b = c[(k + 1) % c.size()];
            const double depth =
                no_go(t, a) + no_go(t, b) - (t.obstacles[a].center - t.obstacles[b].center).norm();
            if (depth <= 0)
                return at + "obstacles " + std::to_string(a) + " and " + std::to_string(b) +
                       " do not overlap";
            if (std::abs(depth - wall.overlaps[k]) > 1e-9) return at + "overlap misreported";
            poly.push_back(t.obstacles[a].center);
        }
        if (on_path(t, wall.primitive, wall.point) > 1e-6)
            return at + "the point is not on its primitive";
        for (int i : c)
            if ((wall.point - t.obstacles[i].center).norm() <= no_go(t, i))
                return at + "the path point is inside the wall";
        const int pq = ray_parity(poly, wall.point);
        const auto& r = t.base_regions.at(wall.base_region);
        constexpr int kGrid = 60;
        for (int ix = 0; ix <= kGrid; ++ix) {
            for (int iy = 0; iy <= kGrid; ++iy) {
                const Vec2 b(r.min.x() + (r.max.x() - r.min.x()) * ix / kGrid,
                             r.min.y() + (r.max.y() - r.min.y()) * iy / kGrid);
                const bool blocked = std::any_of(c.begin(), c.end(), [&](int i) {
                    return (b - t.obstacles[i].center).norm() < no_go(t, i);
                });
                if (!blocked && ray_parity(poly, b) == pq)
                    return at + "a free base position is on the path's side";
            }
        }
    }
    return "";
}

double roadmap_distance(const task::Task& t, const task::BaseRegion& region, const Vec2& p,
                        int per_circle, const std::vector<int>& among) {
    const std::vector<int> obstacles = among.empty() ? every(t) : among;
    std::vector<Vec2> pts{p};
    const std::size_t first_region = pts.size();
    for (int ix = 0; ix <= 4; ++ix)
        for (int iy = 0; iy <= 4; ++iy)
            pts.push_back({region.min.x() + (region.max.x() - region.min.x()) * ix / 4,
                           region.min.y() + (region.max.y() - region.min.y()) * iy / 4});
    const std::size_t last_region = pts.size();
    for (int i : obstacles) {
        // The circumscribed polygon: its sides stay outside the circle.
        const double r = no_go(t, i) / std::cos(geometry::kPi / per_circle) * (1 + 1e-6) + 1e-7;
        for (int k = 0; k < per_circle; ++k) {
            const double a = geometry::kTau * (k + 0.5) / per_circle;
            pts.push_back(t.obstacles[i].center + r * Vec2(std::cos(a), std::sin(a)));
        }
    }
    const std::size_t n = pts.size();
    std::vector<double> dist(n, std::numeric_limits<double>::infinity());
    std::vector<bool> done(n, false);
    dist[0] = 0;
    // Dense Dijkstra: visibility tested when an edge is first relaxed.
    for (std::size_t step = 0; step < n; ++step) {
        std::size_t u = n;
        for (std::size_t v = 0; v < n; ++v)
            if (!done[v] && (u == n || dist[v] < dist[u])) u = v;
        if (u == n || !std::isfinite(dist[u])) break;
        if (u >= first_region && u < last_region) return dist[u];
        done[u] = true;
        for (std::size_t v = 0; v < n; ++v) {
            if (done[v]) continue;
            const double d = dist[u] + (pts[u] - pts[v]).norm();
            if (d < dist[v] && free_of(t, obstacles, pts[u], pts[v], 0.0)) dist[v] = d;
        }
    }
    return std::numeric_limits<double>::infinity();
}

std::string check_geodesic_witness(const task::Task& t, const prove::GeodesicWitness& w) {
    const int links = *std::max_element(t.robot.dof.begin(), t.robot.dof.end());
    if (std::abs(w.reach - links * t.robot.max_link_length) > 1e-12) return "reach misreported";
    if (w.detours.size() != t.base_regions.size()) return "not one detour per base region";
    for (int i : w.obstacles)
        if (i < 0 || i >= static_cast<int>(t.obstacles.size())) return "no such obstacle";
    for (const auto& d : w.detours) {
        const std::string at = "detour of base_regions[" + std::to_string(d.base_region) + "]: ";
        const auto& r = t.base_regions.at(d.base_region);
        if (d.lower_bound <= w.reach) return at + "the bound is within reach";
        if (on_path(t, d.primitive, d.point) > 1e-6)
            return at + "the point is not on its primitive";
        if (d.route.size() < 2) return at + "no route";
        if (!r.contains(d.route.front().point, 1e-9))
            return at + "the route does not start in the region";
        if ((d.route.back().point - d.point).norm() > 1e-9)
            return at + "the route does not end at the point";
        double length = 0;
        for (std::size_t k = 1; k < d.route.size(); ++k) {
            const Vec2 a = d.route[k - 1].point, b = d.route[k].point;
            const int o = d.route[k].around;
            if (o < 0) {
                if (!free_of(t, w.obstacles, a, b, 1e-7))
                    return at + "a straight step enters an obstacle";
                length += (b - a).norm();
                continue;
            }
            const Vec2 c = t.obstacles.at(o).center;
            const double rad = no_go(t, o);
            if (std::abs((a - c).norm() - rad) > 1e-7 || std::abs((b - c).norm() - rad) > 1e-7)
                return at + "an arc step leaves its circle";
            const double from = std::atan2((a - c).y(), (a - c).x());
            const double sweep =
                std::remainder(std::atan2((b - c).y(), (b - c).x()) - from, geometry::kTau);
            for (int i = 0; i <= 16; ++i) {
                const Vec2 q = c + rad * Vec2(std::cos(from + sweep * i / 16),
                                              std::sin(from + sweep * i / 16));
                if (!free_of(t, w.obstacles, q, q, 1e-7))
                    return at + "an arc step runs inside another obstacle";
            }
            length += rad * std::abs(sweep);
        }
        if (std::abs(length - d.lower_bound) > 1e-6 * (1 + length))
            return at + "the route is not as long as the bound";
        // Falsification: no way the roadmap finds may be shorter.
        const double found = roadmap_distance(t, r, d.point, 48, w.obstacles);
        if (found < d.lower_bound - 1e-9) return at + "the roadmap found a shorter way";
    }
    return "";
}

}  // namespace modsynth::testing
