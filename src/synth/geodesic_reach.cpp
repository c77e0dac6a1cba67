#include <modsynth/synth/geodesic_reach.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <unordered_map>

#include <modsynth/geometry/distance.h>
#include <modsynth/geometry/tangents.h>

namespace modsynth::synth {
namespace {

using geometry::Vec2;
constexpr double kInf = std::numeric_limits<double>::infinity();

struct Node {
    Vec2 p;
    int disc;     // index into the discs, -1 for a free point
    int partner;  // the other end of this node's tangent segment (circle nodes), -1 if none
    char clear;   // that segment's visibility: unknown, clear or blocked
    bool exit;    // a way from the box may come straight here: free points and
                  // the four axis-extreme points of each circle
};

struct Bound {
    double length = kInf;
    std::vector<RouteStep> route;
};

// The visibility graph of the free space among the discs, with the free
// points given (path points, region corners) as extra nodes. Every node on
// a circle ends one tangent segment; the arcs between neighbouring nodes of
// a circle, and whether a segment is clear of the discs, are worked out
// only when a search first reaches them: most never are.
class Graph {
public:
    explicit Graph(const std::vector<NoGoDisc>& discs) : discs_(discs), circles_(discs.size()) {}

    int add(const Vec2& p, int disc, int partner = -1, bool exit = false) {
        nodes_.push_back({p, disc, partner, kUnknown, exit || disc < 0});
        if (disc >= 0) circles_[disc].nodes.push_back(static_cast<int>(nodes_.size()) - 1);
        return static_cast<int>(nodes_.size()) - 1;
    }

    // A straight segment is kept unless it clearly enters a disc: rounding
    // never removes a way that exists.
    bool blocked(const Vec2& a, const Vec2& b) const {
        const Vec2 lo = a.cwiseMin(b), hi = a.cwiseMax(b);
        for (const auto& d : discs_) {
            const double r = d.radius - kNoGoSlack;
            if (d.center.x() < lo.x() - r || d.center.x() > hi.x() + r || d.center.y() < lo.y() - r ||
                d.center.y() > hi.y() + r)
                continue;
            if (geometry::point_segment(d.center, a, b) < r) return true;
        }
        return false;
    }

    // A segment between two free points.
    void segment(int u, int v) {
        free_links_[u].push_back(v);
        free_links_[v].push_back(u);
    }

    int add_free(const Vec2& p) {
        const int u = add(p, -1);
        free_links_[u];
        return u;
    }

    // Tangent segments from a free point to every circle.
    void tangents_from(int u) {
        for (int i = 0; i < static_cast<int>(discs_.size()); ++i)
            for (const Vec2& t : geometry::tangent_points(nodes_[u].p, discs_[i].center, discs_[i].radius))
                free_links_[u].push_back(add(t, i, u));
    }

    void build_circles() {
        const int n = static_cast<int>(discs_.size());
        nodes_.reserve(static_cast<std::size_t>(4 * n * (n + 1)));
        for (int i = 0; i < n; ++i) {
            // The points where a way leaving a side of an axis-aligned box
            // at right angles first touches the circle.
            for (int k = 0; k < 4; ++k)
                add(discs_[i].center + discs_[i].radius * geometry::unit(k * geometry::kPi / 2), i, -1, true);
            for (int j = i + 1; j < n; ++j)
                for (const auto& t : geometry::bitangents(discs_[i].center, discs_[i].radius, discs_[j].center,
                                                          discs_[j].radius, kNoGoSlack)) {
                    const int a = static_cast<int>(nodes_.size());
                    add(t.from, i, a + 1);
                    add(t.to, j, a);
                }
        }
    }

    // The shortest way from the box [lo, hi] to node s (A*, searching from s
    // towards the box; the distance to the box never overestimates). A way
    // leaves the box straight to a node, from the node's nearest box point
    // when that is clear: at a corner (a free node), or at right angles to a side
    // until it touches a circle where that circle runs parallel to the side
    // (an axis-extreme node). Stops early, with a bound above `enough` and no route,
    // once every way is known to be longer than `enough`.
    Bound from_box(int s, const Vec2& lo, const Vec2& hi, double enough) {
        std::vector<double> dist(nodes_.size(), kInf);
        std::vector<int> prev(nodes_.size(), -1), via(nodes_.size(), -1);
        using Item = std::pair<double, int>;
        std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
        const auto h = [&](int v) { return geometry::point_box(nodes_[v].p, lo, hi); };
        dist[s] = 0.0;
        queue.push({h(s), s});
        Bound best;
        int first = -1;
        Vec2 start = Vec2::Zero();
        const auto relax = [&](int u, int v, double length, int around) {
            const double d = dist[u] + length;
            if (d >= dist[v]) return;
            dist[v] = d;
            prev[v] = u;
            via[v] = around;
            queue.push({d + h(v), v});
        };
        const auto straight = [&](int u, int v) {
            // Free-point segments are checked every time: there are few.
            const Vec2 a = nodes_[u].p, b = nodes_[v].p;
            if (dist[u] + (a - b).norm() >= dist[v]) return;
            char& c = nodes_[v].disc >= 0 ? nodes_[v].clear : nodes_[u].disc >= 0 ? nodes_[u].clear : scratch_;
            if (&c == &scratch_ || c == kUnknown) c = blocked(a, b) ? kBlocked : kClear;
            if (c == kClear) relax(u, v, (a - b).norm(), -1);
        };
        while (!queue.empty()) {
            const auto [key, u] = queue.top();
            queue.pop();
            if (key >= best.length) break;
            if (key > enough) {
                best.length = key;
                best.route.clear();
                return best;
            }
            if (key > dist[u] + h(u)) continue;
            const Node& n = nodes_[u];
            const Vec2 foot = geometry::nearest_in_box(n.p, lo, hi);
            const double total = dist[u] + (n.p - foot).norm();
            if (n.exit && total < best.length && !blocked(foot, n.p)) {
                best.length = total;
                first = u;
                start = foot;
            }
            if (n.disc < 0) {
                for (int v : free_links_[u]) straight(u, v);
                continue;
            }
            if (n.partner >= 0) {
                // The segment's visibility is kept on both of its ends.
                Node& m = nodes_[n.partner];
                if (n.clear == kUnknown && m.clear == kUnknown) {
                    const char c = blocked(n.p, m.p) ? kBlocked : kClear;
                    nodes_[u].clear = c;
                    if (m.disc >= 0) m.clear = c;
                }
                const char c = nodes_[u].clear != kUnknown ? nodes_[u].clear : m.clear;
                if (c == kClear) relax(u, n.partner, (n.p - m.p).norm(), -1);
            }
            const Circle& c = circle(n.disc);
            const int k = c.position.at(u);
            const int count = static_cast<int>(c.order.size());
            const double r = discs_[n.disc].radius;
            if (c.free[k]) relax(u, c.order[(k + 1) % count], r * c.gap[k], n.disc);
            const int before = (k + count - 1) % count;
            if (c.free[before]) relax(u, c.order[before], r * c.gap[before], n.disc);
        }
        if (first < 0) return best;
        best.route.push_back({start, -1});
        if ((nodes_[first].p - start).norm() > 0.0) best.route.push_back({nodes_[first].p, -1});
        for (int v = first; prev[v] >= 0; v = prev[v]) {
            const int around = via[v];
            best.route.push_back({nodes_[prev[v]].p, around < 0 ? -1 : discs_[around].obstacle});
        }
        return best;
    }

    const std::vector<Node>& nodes() const { return nodes_; }

private:
    enum : char { kUnknown, kClear, kBlocked };

    struct Circle {
        std::vector<int> nodes;           // as added
        bool ready = false;
        std::vector<int> order;           // by angle
        std::unordered_map<int, int> position;  // node -> index in order
        std::vector<double> gap;          // angle from order[k] to order[k+1]
        std::vector<char> free;           // whether that arc is clear of other discs
    };

    // The arcs between neighbouring nodes of circle i, and which of them no
    // other disc covers.
    const Circle& circle(int i) {
        Circle& c = circles_[i];
        if (c.ready) return c;
        c.ready = true;
        const NoGoDisc& me = discs_[i];
        struct Cover {
            double mid, half;
        };
        std::vector<Cover> covers;
        bool all = false;
        for (int j = 0; j < static_cast<int>(discs_.size()); ++j) {
            if (j == i || overlap(me, discs_[j]) <= kNoGoSlack) continue;
            const Vec2 v = discs_[j].center - me.center;
            const double d = v.norm();
            if (d + me.radius <= discs_[j].radius - kNoGoSlack) all = true;
            if (d + discs_[j].radius <= me.radius || d == 0.0) continue;
            const double cos_h = (me.radius * me.radius + d * d - discs_[j].radius * discs_[j].radius) / (2 * me.radius * d);
            covers.push_back({std::atan2(v.y(), v.x()), std::acos(std::clamp(cos_h, -1.0, 1.0))});
        }
        std::vector<std::pair<double, int>> around;
        for (int u : c.nodes) {
            const Vec2 v = nodes_[u].p - me.center;
            around.push_back({std::atan2(v.y(), v.x()), u});
        }
        std::sort(around.begin(), around.end());
        for (std::size_t k = 0; k < around.size(); ++k) {
            c.position[around[k].second] = static_cast<int>(k);
            c.order.push_back(around[k].second);
            const double a = around[k].first;
            const double b = k + 1 < around.size() ? around[k + 1].first : around[0].first + geometry::kTau;
            const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
            c.gap.push_back(b - a);
            c.free.push_back(!all && std::all_of(covers.begin(), covers.end(), [&](const Cover& cv) {
                const double gap = std::abs(std::remainder(mid - cv.mid, geometry::kTau));
                return gap >= half + cv.half - 1e-9;
            }));
        }
        return c;
    }

    const std::vector<NoGoDisc>& discs_;
    std::vector<Node> nodes_;
    std::vector<Circle> circles_;
    std::unordered_map<int, std::vector<int>> free_links_;
    char scratch_ = kUnknown;
};

bool box_free(const std::vector<NoGoDisc>& discs, const Vec2& lo, const Vec2& hi) {
    for (const auto& d : discs)
        if (geometry::point_box(d.center, lo, hi) < d.radius) return false;
    return true;
}

double reach(const task::Task& task) {
    return *std::max_element(task.robot.dof.begin(), task.robot.dof.end()) * task.robot.max_link_length;
}

std::optional<GeodesicWitness> prove(const task::Task& task, const std::vector<int>& obstacles,
                                     const std::vector<std::vector<PathPoint>>& per_region, bool with_route) {
    if (task.base_regions.empty() || obstacles.empty()) return std::nullopt;
    const std::vector<NoGoDisc> discs = no_go_discs(task, obstacles);
    for (const auto& r : task.base_regions)
        if (!box_free(discs, r.min, r.max)) return std::nullopt;
    Graph g(discs);
    g.build_circles();
    std::vector<int> point_node;
    std::vector<PathPoint> points;
    for (const auto& list : per_region)
        for (const auto& q : list) {
            const bool seen = std::any_of(points.begin(), points.end(),
                                          [&](const PathPoint& o) { return o.point == q.point; });
            if (!seen && free_point(discs, q.point)) {
                points.push_back(q);
                point_node.push_back(g.add_free(q.point));
            }
        }
    for (const auto& r : task.base_regions)
        for (const Vec2& c : {r.min, Vec2{r.max.x(), r.min.y()}, r.max, Vec2{r.min.x(), r.max.y()}})
            g.add_free(c);
    const int circle_nodes = static_cast<int>(g.nodes().size());
    for (int u = 0; u < circle_nodes; ++u) {
        if (g.nodes()[u].disc >= 0) continue;
        for (int v = 0; v < u; ++v)
            if (g.nodes()[v].disc < 0) g.segment(u, v);
        g.tangents_from(u);
    }
    const double limit = reach(task);
    const double margin = 1e-9 * (1.0 + limit);
    GeodesicWitness out;
    out.reach = limit;
    out.obstacles = obstacles;
    out.detours.resize(task.base_regions.size());
    std::vector<bool> proved(task.base_regions.size(), false);
    for (std::size_t k = 0; k < points.size(); ++k) {
        for (std::size_t r = 0; r < task.base_regions.size(); ++r) {
            const bool listed = std::any_of(per_region[r].begin(), per_region[r].end(),
                                            [&](const PathPoint& q) { return q.point == points[k].point; });
            if (proved[r] || !listed) continue;
            Bound b = g.from_box(point_node[k], task.base_regions[r].min, task.base_regions[r].max,
                                 with_route ? kInf : limit + margin);
            if (b.length > limit + margin) {
                proved[r] = true;
                out.detours[r] = {static_cast<int>(r), points[k].primitive, points[k].point, b.length, std::move(b.route)};
            }
        }
    }
    if (!std::all_of(proved.begin(), proved.end(), [](bool p) { return p; })) return std::nullopt;
    return out;
}

}  // namespace

double geodesic_distance(const std::vector<NoGoDisc>& discs, const Vec2& lo, const Vec2& hi, const Vec2& p,
                         std::vector<RouteStep>* route) {
    Graph g(discs);
    g.build_circles();
    std::vector<int> free{g.add_free(p)};
    for (const Vec2& c : {lo, Vec2{hi.x(), lo.y()}, hi, Vec2{lo.x(), hi.y()}}) free.push_back(g.add_free(c));
    for (std::size_t k = 0; k < free.size(); ++k) {
        for (std::size_t m = 0; m < k; ++m) g.segment(free[k], free[m]);
        g.tangents_from(free[k]);
    }
    const int target = free[0];
    Bound b = g.from_box(target, lo, hi, kInf);
    if (route) *route = std::move(b.route);
    return b.length;
}

std::optional<GeodesicWitness> prove_geodesic_reach(const task::Task& task, const std::vector<int>& obstacles,
                                                    bool with_route) {
    const std::vector<PathPoint> all = path_points(task);
    return prove(task, obstacles, std::vector<std::vector<PathPoint>>(task.base_regions.size(), all), with_route);
}

std::optional<GeodesicWitness> prove_geodesic_reach(const task::Task& task, const std::vector<int>& obstacles,
                                                    const std::vector<PathPoint>& points, bool with_route) {
    std::vector<std::vector<PathPoint>> per_region;
    for (const auto& q : points) per_region.push_back({q});
    return prove(task, obstacles, per_region, with_route);
}

}  // namespace modsynth::synth
