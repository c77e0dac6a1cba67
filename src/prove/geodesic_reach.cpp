#include <modsynth/geometry/distance.h>
#include <modsynth/geometry/tangents.h>
#include <modsynth/prove/geodesic_reach.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <queue>
#include <unordered_map>

namespace modsynth::prove {
namespace {

using geometry::Vec2;
constexpr double kInf = std::numeric_limits<double>::infinity();

struct Node {
    Vec2 p;
    int disc;     // index into the discs, -1 for a free point
    int partner;  // the other end of this node's tangent segment (circle nodes), -1 if none
    int segment;  // that segment's index into the blocker lists
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
// a circle, and which discs block a segment, are worked out only when a
// search first reaches them: most never are. Searches may leave out some of
// the discs (`leave_out`): what they blocked is kept by blocker, so trying
// a proof without an obstacle costs one search, not a new graph.
class Graph {
public:
    explicit Graph(std::vector<NoGoDisc> discs)
        : discs_(std::move(discs)), circles_(discs_.size()), gone_(discs_.size(), 0) {}

    const std::vector<NoGoDisc>& discs() const { return discs_; }

    void leave_out(const std::vector<char>& gone) { gone_ = gone; }

    int add(const Vec2& p, int disc, int partner = -1, bool exit = false, int segment = -1) {
        nodes_.push_back({p, disc, partner, segment, exit || disc < 0});
        if (disc >= 0) circles_[disc].nodes.push_back(static_cast<int>(nodes_.size()) - 1);
        return static_cast<int>(nodes_.size()) - 1;
    }

    // The discs a straight segment enters. A segment is kept unless it
    // clearly enters one: rounding never removes a way that exists.
    std::vector<int> blockers(const Vec2& a, const Vec2& b) const {
        std::vector<int> out;
        const Vec2 lo = a.cwiseMin(b), hi = a.cwiseMax(b);
        for (int i = 0; i < static_cast<int>(discs_.size()); ++i) {
            const auto& d = discs_[i];
            const double r = d.radius - kNoGoSlack;
            if (d.center.x() < lo.x() - r || d.center.x() > hi.x() + r ||
                d.center.y() < lo.y() - r || d.center.y() > hi.y() + r)
                continue;
            if (geometry::point_segment(d.center, a, b) < r) out.push_back(i);
        }
        return out;
    }

    bool blocked(const Vec2& a, const Vec2& b) const {
        for (int i : blockers(a, b))
            if (!gone_[i]) return true;
        return false;
    }

    // A segment between two free points.
    void segment(int u, int v) {
        const int id = new_segment();
        free_links_[u].push_back({v, id});
        free_links_[v].push_back({u, id});
    }

    int add_free(const Vec2& p) {
        const int u = add(p, -1);
        free_links_[u];
        return u;
    }

    // Tangent segments from a free point to every circle.
    void tangents_from(int u) {
        for (int i = 0; i < static_cast<int>(discs_.size()); ++i)
            for (const Vec2& t :
                 geometry::tangent_points(nodes_[u].p, discs_[i].center, discs_[i].radius))
                free_links_[u].push_back(
                    {add(t, i, u, false, new_segment()), nodes_.back().segment});
    }

    void build_circles() {
        const int n = static_cast<int>(discs_.size());
        nodes_.reserve(static_cast<std::size_t>(4 * n * (n + 1)));
        for (int i = 0; i < n; ++i) {
            // The points where a way leaving a side of an axis-aligned box
            // at right angles first touches the circle.
            for (int k = 0; k < 4; ++k)
                add(discs_[i].center + discs_[i].radius * geometry::unit(k * geometry::kPi / 2), i,
                    -1, true);
            for (int j = i + 1; j < n; ++j)
                for (const auto& t :
                     geometry::bitangents(discs_[i].center, discs_[i].radius, discs_[j].center,
                                          discs_[j].radius, kNoGoSlack)) {
                    const int a = static_cast<int>(nodes_.size());
                    const int id = new_segment();
                    add(t.from, i, a + 1, false, id);
                    add(t.to, j, a, false, id);
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
        std::unordered_map<int, std::vector<int>>& exits = exits_[{lo.x(), lo.y(), hi.x(), hi.y()}];
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
            if (d >= dist[v] || (nodes_[v].disc >= 0 && gone_[nodes_[v].disc])) return;
            dist[v] = d;
            prev[v] = u;
            via[v] = around;
            queue.push({d + h(v), v});
        };
        const auto straight = [&](int u, int v, int id) {
            const Vec2 a = nodes_[u].p, b = nodes_[v].p;
            if (dist[u] + (a - b).norm() >= dist[v]) return;
            if (clear(id, a, b)) relax(u, v, (a - b).norm(), -1);
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
            if (n.exit && total < best.length && all_gone(cached(exits, u, foot, n.p))) {
                best.length = total;
                first = u;
                start = foot;
            }
            if (n.disc < 0) {
                for (const auto& [v, id] : free_links_[u]) straight(u, v, id);
                continue;
            }
            if (n.partner >= 0) straight(u, n.partner, n.segment);
            const Circle& c = circle(n.disc);
            const int k = c.position.at(u);
            const int count = static_cast<int>(c.order.size());
            const double r = discs_[n.disc].radius;
            if (all_gone(c.covered[k])) relax(u, c.order[(k + 1) % count], r * c.gap[k], n.disc);
            const int before = (k + count - 1) % count;
            if (all_gone(c.covered[before])) relax(u, c.order[before], r * c.gap[before], n.disc);
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
    int new_segment() {
        segment_blockers_.emplace_back();
        segment_known_.push_back(0);
        return static_cast<int>(segment_blockers_.size()) - 1;
    }

    bool all_gone(const std::vector<int>& discs) const {
        for (int i : discs)
            if (!gone_[i]) return false;
        return true;
    }

    bool clear(int id, const Vec2& a, const Vec2& b) {
        if (!segment_known_[id]) {
            segment_blockers_[id] = blockers(a, b);
            segment_known_[id] = 1;
        }
        return all_gone(segment_blockers_[id]);
    }

    const std::vector<int>& cached(std::unordered_map<int, std::vector<int>>& cache, int u,
                                   const Vec2& a, const Vec2& b) const {
        auto it = cache.find(u);
        if (it == cache.end()) it = cache.emplace(u, blockers(a, b)).first;
        return it->second;
    }

    struct Circle {
        std::vector<int> nodes;  // as added
        bool ready = false;
        std::vector<int> order;                 // by angle
        std::unordered_map<int, int> position;  // node -> index in order
        std::vector<double> gap;                // angle from order[k] to order[k+1]
        std::vector<std::vector<int>> covered;  // the other discs that cover some of that arc
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
            int disc;
        };
        std::vector<Cover> covers;
        std::vector<int> all;  // discs that hold the whole circle
        for (int j = 0; j < static_cast<int>(discs_.size()); ++j) {
            if (j == i || overlap(me, discs_[j]) <= kNoGoSlack) continue;
            const Vec2 v = discs_[j].center - me.center;
            const double d = v.norm();
            if (d + me.radius <= discs_[j].radius - kNoGoSlack) all.push_back(j);
            if (d + discs_[j].radius <= me.radius || d == 0.0) continue;
            const double cos_h =
                (me.radius * me.radius + d * d - discs_[j].radius * discs_[j].radius) /
                (2 * me.radius * d);
            covers.push_back(
                {std::atan2(v.y(), v.x()), std::acos(std::clamp(cos_h, -1.0, 1.0)), j});
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
            const double b =
                k + 1 < around.size() ? around[k + 1].first : around[0].first + geometry::kTau;
            const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
            c.gap.push_back(b - a);
            std::vector<int> by = all;
            for (const Cover& cv : covers)
                if (std::abs(std::remainder(mid - cv.mid, geometry::kTau)) < half + cv.half - 1e-9)
                    by.push_back(cv.disc);
            c.covered.push_back(std::move(by));
        }
        return c;
    }

    std::vector<NoGoDisc> discs_;
    std::vector<Node> nodes_;
    std::vector<Circle> circles_;
    std::vector<char> gone_;
    std::unordered_map<int, std::vector<std::pair<int, int>>>
        free_links_;  // node -> (node, segment)
    std::vector<std::vector<int>> segment_blockers_;
    std::vector<char> segment_known_;
    std::map<std::array<double, 4>, std::unordered_map<int, std::vector<int>>>
        exits_;  // box -> node -> blockers
};

bool box_free(const std::vector<NoGoDisc>& discs, const Vec2& lo, const Vec2& hi) {
    for (const auto& d : discs)
        if (geometry::point_box(d.center, lo, hi) < d.radius) return false;
    return true;
}

}  // namespace

struct GeodesicProver::Impl {
    const task::Task& task;
    std::vector<int> obstacles;
    Graph graph;
    std::vector<PathPoint> points;  // every path point, once
    std::vector<int> point_node;
};

GeodesicProver::GeodesicProver(const task::Task& task, const std::vector<int>& obstacles)
    : impl_(new Impl{task, obstacles, Graph(no_go_discs(task, obstacles)), {}, {}}) {
    Graph& g = impl_->graph;
    g.build_circles();
    for (const auto& q : path_points(task)) {
        const bool seen = std::any_of(impl_->points.begin(), impl_->points.end(),
                                      [&](const PathPoint& o) { return o.point == q.point; });
        if (seen) continue;
        impl_->points.push_back(q);
        impl_->point_node.push_back(g.add_free(q.point));
    }
    for (const auto& r : task.base_regions)
        for (const Vec2& c : {r.min, Vec2{r.max.x(), r.min.y()}, r.max, Vec2{r.min.x(), r.max.y()}})
            g.add_free(c);
    const int count = static_cast<int>(g.nodes().size());
    for (int u = 0; u < count; ++u) {
        if (g.nodes()[u].disc >= 0) continue;
        for (int v = 0; v < u; ++v)
            if (g.nodes()[v].disc < 0) g.segment(u, v);
        g.tangents_from(u);
    }
}

GeodesicProver::~GeodesicProver() = default;

std::optional<GeodesicWitness> GeodesicProver::prove(const std::vector<int>& among, bool with_route,
                                                     const std::vector<PathPoint>& only) const {
    const task::Task& task = impl_->task;
    if (task.base_regions.empty() || among.empty()) return std::nullopt;
    Graph& g = impl_->graph;
    std::vector<char> gone(impl_->obstacles.size(), 1);
    for (int i : among) {
        const auto at = std::find(impl_->obstacles.begin(), impl_->obstacles.end(), i);
        if (at == impl_->obstacles.end())
            throw std::invalid_argument("obstacle not given to the prover");
        gone[at - impl_->obstacles.begin()] = 0;
    }
    g.leave_out(gone);
    std::vector<NoGoDisc> discs;
    for (std::size_t k = 0; k < gone.size(); ++k)
        if (!gone[k]) discs.push_back(g.discs()[k]);
    for (const auto& r : task.base_regions)
        if (!box_free(discs, r.min, r.max)) return std::nullopt;
    const double limit = task.robot.longest_arm();
    const double margin = 1e-9 * (1.0 + limit);
    GeodesicWitness out;
    out.reach = limit;
    out.obstacles = among;
    std::sort(out.obstacles.begin(), out.obstacles.end());
    out.detours.resize(task.base_regions.size());
    for (std::size_t r = 0; r < task.base_regions.size(); ++r) {
        bool proved = false;
        for (std::size_t k = 0; k < impl_->points.size() && !proved; ++k) {
            const PathPoint& q = impl_->points[k];
            const bool listed =
                only.empty() || std::any_of(only.begin(), only.end(),
                                            [&](const PathPoint& o) { return o.point == q.point; });
            if (!listed || !free_point(discs, q.point)) continue;
            Bound b = g.from_box(impl_->point_node[k], task.base_regions[r].min,
                                 task.base_regions[r].max, with_route ? kInf : limit + margin);
            if (b.length > limit + margin) {
                proved = true;
                out.detours[r] = {static_cast<int>(r), q.primitive, q.point, b.length,
                                  std::move(b.route)};
            }
        }
        if (!proved) return std::nullopt;
    }
    return out;
}

double geodesic_distance(const std::vector<NoGoDisc>& discs, const Vec2& lo, const Vec2& hi,
                         const Vec2& p, std::vector<RouteStep>* route) {
    Graph g(discs);
    g.build_circles();
    std::vector<int> free{g.add_free(p)};
    for (const Vec2& c : {lo, Vec2{hi.x(), lo.y()}, hi, Vec2{lo.x(), hi.y()}})
        free.push_back(g.add_free(c));
    for (std::size_t k = 0; k < free.size(); ++k) {
        for (std::size_t m = 0; m < k; ++m) g.segment(free[k], free[m]);
        g.tangents_from(free[k]);
    }
    const int target = free[0];
    Bound b = g.from_box(target, lo, hi, kInf);
    if (route) *route = std::move(b.route);
    return b.length;
}

std::optional<GeodesicWitness> prove_geodesic_reach(const task::Task& task,
                                                    const std::vector<int>& obstacles,
                                                    bool with_route) {
    return GeodesicProver(task, obstacles).prove(obstacles, with_route);
}

}  // namespace modsynth::prove
