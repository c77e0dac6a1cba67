#include <modsynth/geometry/distance.h>
#include <modsynth/geometry/polygon.h>
#include <modsynth/prove/no_go.h>
#include <modsynth/prove/separation.h>

#include <algorithm>
#include <array>
#include <queue>

namespace modsynth::prove {
namespace {

using geometry::Vec2;

// Region cells are split this many times at most where the wall crosses a
// region: beyond that the region is not proved separated.
constexpr int kMaxDepth = 7;
constexpr std::size_t kTriedPoints = 3;

// Whether segments ab and cd cross at a point interior to both (signs of
// orientations; touching counts as not crossing, and the result is only a
// guide: every wall found is checked with winding numbers).
bool crosses(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
    const double d1 = geometry::cross(b - a, c - a), d2 = geometry::cross(b - a, d - a);
    const double d3 = geometry::cross(d - c, a - c), d4 = geometry::cross(d - c, b - c);
    return ((d1 > 0) != (d2 > 0)) && d1 != 0 && d2 != 0 && ((d3 > 0) != (d4 > 0)) && d3 != 0 &&
           d4 != 0;
}

struct Edge {
    int to;
    int parity;  // 1 when the segment between the centres crosses the probe
};

// The shortest closed walk with odd parity, as node indices; it is a simple
// cycle (a repeated node would split it into two shorter walks, one odd).
std::vector<int> shortest_odd_cycle(const std::vector<std::vector<Edge>>& adj) {
    const int n = static_cast<int>(adj.size());
    // Components of the doubled graph first (one pass): a node lies on an
    // odd closed walk exactly when both its copies share a component, so the
    // shortest-walk searches below run only where there is one.
    std::vector<int> component(2 * n, -1);
    for (int root = 0; root < 2 * n; ++root) {
        if (component[root] >= 0) continue;
        std::vector<int> stack{root};
        component[root] = root;
        while (!stack.empty()) {
            const int u = stack.back();
            stack.pop_back();
            for (const Edge& e : adj[u / 2]) {
                const int v = 2 * e.to + ((u % 2) ^ e.parity);
                if (component[v] < 0) component[v] = root, stack.push_back(v);
            }
        }
    }
    std::vector<int> best;
    std::vector<int> dist(2 * n), parent(2 * n);
    for (int s = 0; s < n; ++s) {
        if (component[2 * s] != component[2 * s + 1]) continue;
        std::fill(dist.begin(), dist.end(), -1);
        std::queue<int> queue;
        dist[2 * s] = 0;
        queue.push(2 * s);
        while (!queue.empty()) {
            const int u = queue.front();
            queue.pop();
            if (u == 2 * s + 1) break;
            if (!best.empty() && dist[u] + 1 >= static_cast<int>(best.size())) break;
            for (const Edge& e : adj[u / 2]) {
                const int v = 2 * e.to + ((u % 2) ^ e.parity);
                if (dist[v] >= 0) continue;
                dist[v] = dist[u] + 1;
                parent[v] = u;
                queue.push(v);
            }
        }
        if (dist[2 * s + 1] < 0 ||
            (!best.empty() && dist[2 * s + 1] >= static_cast<int>(best.size())))
            continue;
        best.clear();
        for (int v = 2 * s + 1; v != 2 * s; v = parent[v]) best.push_back(v / 2);
        std::reverse(best.begin(), best.end());
    }
    return best;
}

std::vector<Vec2> centres(const task::Task& task, const std::vector<int>& cycle) {
    std::vector<Vec2> out;
    for (int i : cycle) out.push_back(task.obstacles.at(i).center);
    return out;
}

double polygon_box(const std::vector<Vec2>& poly, const Vec2& lo, const Vec2& hi) {
    double d = 1e300;
    for (std::size_t k = 0; k < poly.size(); ++k)
        d = std::min(d, geometry::segment_box(poly[k], poly[(k + 1) % poly.size()], lo, hi));
    return d;
}

// Every point of the cell [lo, hi] is either inside a disc of the wall or on
// the other side of the polygon from the path point (winding number `wq`).
bool cell_separated(const std::vector<Vec2>& poly, const std::vector<NoGoDisc>& discs, int wq,
                    const Vec2& lo, const Vec2& hi, int depth, int& budget) {
    if (--budget < 0) return false;
    const std::array<Vec2, 4> corners{lo, Vec2{hi.x(), lo.y()}, hi, Vec2{lo.x(), hi.y()}};
    for (const auto& d : discs) {
        // A disc is convex: holding the corners, it holds the cell.
        if (std::all_of(corners.begin(), corners.end(), [&](const Vec2& c) {
                return (c - d.center).norm() < d.radius - kNoGoSlack;
            }))
            return true;
    }
    if (polygon_box(poly, lo, hi) > kNoGoSlack)
        return geometry::winding_number(poly, 0.5 * (lo + hi)) != wq;
    if (depth == 0) return false;
    const Vec2 m = 0.5 * (lo + hi);
    return cell_separated(poly, discs, wq, lo, m, depth - 1, budget) &&
           cell_separated(poly, discs, wq, {m.x(), lo.y()}, {hi.x(), m.y()}, depth - 1, budget) &&
           cell_separated(poly, discs, wq, m, hi, depth - 1, budget) &&
           cell_separated(poly, discs, wq, {lo.x(), m.y()}, {m.x(), hi.y()}, depth - 1, budget);
}

std::optional<Wall> find_wall(const task::Task& task, const std::vector<NoGoDisc>& discs,
                              int region, const PathPoint& q) {
    const auto& r = task.base_regions[region];
    const Vec2 b = 0.5 * (r.min + r.max);
    const int n = static_cast<int>(discs.size());
    // First every overlap; then, if the shortest wall crosses the region
    // and does not settle it, only overlaps clear of the region.
    for (const bool clear_of_region : {false, true}) {
        std::vector<std::vector<Edge>> adj(n);
        for (int i = 0; i < n; ++i) {
            for (int j = i + 1; j < n; ++j) {
                if (overlap(discs[i], discs[j]) <= kNoGoSlack) continue;
                if (clear_of_region && geometry::segment_box(discs[i].center, discs[j].center,
                                                             r.min, r.max) <= kNoGoSlack)
                    continue;
                const int parity = crosses(discs[i].center, discs[j].center, q.point, b) ? 1 : 0;
                adj[i].push_back({j, parity});
                adj[j].push_back({i, parity});
            }
        }
        const std::vector<int> cycle = shortest_odd_cycle(adj);
        if (cycle.size() < 3) continue;
        Wall w;
        w.base_region = region;
        w.primitive = q.primitive;
        w.point = q.point;
        for (std::size_t k = 0; k < cycle.size(); ++k) {
            w.cycle.push_back(discs[cycle[k]].obstacle);
            w.overlaps.push_back(overlap(discs[cycle[k]], discs[cycle[(k + 1) % cycle.size()]]));
        }
        if (wall_separates(task, w)) return w;
    }
    return std::nullopt;
}

}  // namespace

bool wall_separates(const task::Task& task, const Wall& wall) {
    if (wall.cycle.size() < 3 || wall.base_region < 0 ||
        wall.base_region >= static_cast<int>(task.base_regions.size()))
        return false;
    const std::vector<NoGoDisc> discs = no_go_discs(task, wall.cycle);
    for (std::size_t k = 0; k < discs.size(); ++k)
        if (overlap(discs[k], discs[(k + 1) % discs.size()]) <= kNoGoSlack) return false;
    // The path point must be free, hence off the polygon (which the discs hold).
    if (!free_point(discs, wall.point)) return false;
    const std::vector<Vec2> poly = centres(task, wall.cycle);
    const int wq = geometry::winding_number(poly, wall.point);
    const auto& r = task.base_regions[wall.base_region];
    int budget = 20000;
    return cell_separated(poly, discs, wq, r.min, r.max, kMaxDepth, budget);
}

std::optional<SeparationWitness> prove_separation(const task::Task& task,
                                                  const std::vector<int>& obstacles) {
    if (task.base_regions.empty() || obstacles.size() < 3) return std::nullopt;
    const std::vector<NoGoDisc> discs = no_go_discs(task, obstacles);
    std::vector<PathPoint> points;
    for (const auto& q : path_points(task))
        if (free_point(discs, q.point)) points.push_back(q);
    SeparationWitness out;
    for (int region = 0; region < static_cast<int>(task.base_regions.size()); ++region) {
        std::optional<Wall> best;
        // When the path keeps out of the discs, one point is as good as
        // another (the path is connected); a few are tried in case it does not.
        for (std::size_t k = 0; k < points.size() && k < kTriedPoints && !best; ++k)
            best = find_wall(task, discs, region, points[k]);
        if (!best) return std::nullopt;
        out.walls.push_back(std::move(*best));
    }
    return out;
}

}  // namespace modsynth::prove
