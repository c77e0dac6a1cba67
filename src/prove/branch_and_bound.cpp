#include <modsynth/geometry/distance.h>
#include <modsynth/geometry/distance_contractor.h>
#include <modsynth/geometry/interval.h>
#include <modsynth/geometry/primitive.h>
#include <modsynth/prove/branch_and_bound.h>
#include <modsynth/prove/no_go.h>
#include <modsynth/run/stopwatch.h>
#include <modsynth/text/option_check.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace modsynth::prove {
namespace {

using geometry::Interval;
using geometry::IntervalPoint;
using geometry::Vec2;

constexpr int kReach = -1;  // a range refuted by the distance constraints alone

struct Point {
    int primitive = 0;
    Vec2 p = Vec2::Zero();
};

// The design variables of a box.
struct Design {
    Interval bx, by, r1, r2;
    double width() const { return std::max({bx.width(), by.width(), r1.width(), r2.width()}); }
    bool is_empty() const {
        return bx.is_empty() || by.is_empty() || r1.is_empty() || r2.is_empty();
    }
};

Interval& var(Design& d, int v) {
    switch (v) {
        case 0:
            return d.bx;
        case 1:
            return d.by;
        case 2:
            return d.r1;
        default:
            return d.r2;
    }
}

Design hull(const Design& a, const Design& b) {
    if (a.is_empty()) return b;
    return {geometry::hull(a.bx, b.bx), geometry::hull(a.by, b.by), geometry::hull(a.r1, b.r1),
            geometry::hull(a.r2, b.r2)};
}

Design intersect(const Design& a, const Design& b) {
    return {geometry::intersect(a.bx, b.bx), geometry::intersect(a.by, b.by),
            geometry::intersect(a.r1, b.r1), geometry::intersect(a.r2, b.r2)};
}

Design empty_design() {
    const Interval e = Interval::empty();
    return {e, e, e, e};
}

struct Node {
    Design d;
    std::vector<std::vector<Interval>> ranges;  ///< theta ranges alive, per point
    std::vector<char> used;                     ///< obstacles (by position) that refuted
};

// Whether every segment from a point of box a to a point of box b (each
// given as its x and y ranges) passes within `need` of c: when the line
// through c across the way from a to b has all of a on one side, all of b
// on the other, and every segment between their corners crosses it within
// `need` of c, so does every segment between the boxes (their union's
// convex hull meets the line in the hull of those crossings).
bool every_segment_hits(const IntervalPoint& a, const IntervalPoint& b, const Vec2& c,
                        double need) {
    const Vec2 ac(a.x.mid(), a.y.mid());
    const Vec2 bc(b.x.mid(), b.y.mid());
    const Vec2 way = bc - ac;
    const double n = way.norm();
    if (n <= 0.0) return false;
    const Vec2 d = way / n;
    const Vec2 across = geometry::perp(d);
    const Vec2 ca[] = {{a.x.lo, a.y.lo}, {a.x.hi, a.y.lo}, {a.x.lo, a.y.hi}, {a.x.hi, a.y.hi}};
    const Vec2 cb[] = {{b.x.lo, b.y.lo}, {b.x.hi, b.y.lo}, {b.x.lo, b.y.hi}, {b.x.hi, b.y.hi}};
    for (const auto& v : ca)
        if (d.dot(v - c) >= 0.0) return false;
    for (const auto& v : cb)
        if (d.dot(v - c) <= 0.0) return false;
    for (const auto& u : ca)
        for (const auto& v : cb) {
            const double su = d.dot(u - c);
            const double sv = d.dot(v - c);
            const double t = su / (su - sv);
            const Vec2 x = u + t * (v - u);
            if (std::abs(across.dot(x - c)) >= need) return false;
        }
    return true;
}

double half_diagonal(const Interval& x, const Interval& y) {
    return std::hypot(x.radius(), y.radius());
}

std::vector<Point> points_of(const task::Task& task, const BranchAndBoundOptions& o) {
    std::vector<Point> out;
    for (int j = 0; j < static_cast<int>(task.trajectory.size()); ++j) {
        const auto& prim = task.trajectory[j];
        const double len = geometry::length(prim);
        const int n = std::max(1, static_cast<int>(std::ceil(len / o.point_spacing)));
        for (int k = 0; k <= n; ++k) {
            if (k == n && j + 1 < static_cast<int>(task.trajectory.size()) &&
                (prim.end - task.trajectory[j + 1].start).norm() < 1e-6)
                continue;  // the next primitive's start
            out.push_back({j, geometry::point_at(prim, len * k / n)});
        }
    }
    if (static_cast<int>(out.size()) <= o.max_points) return out;
    std::vector<Point> spread;
    for (int k = 0; k < o.max_points; ++k)
        spread.push_back(out[k * (out.size() - 1) / (o.max_points - 1)]);
    return spread;
}

class Search {
public:
    Search(const task::Task& task, const std::vector<int>& obstacles,
           const BranchAndBoundOptions& o, run::Deadline deadline)
        : task_(task),
          o_(o),
          deadline_(deadline),
          discs_(no_go_discs(task, obstacles)),
          points_(points_of(task, o)) {}

    BranchAndBoundResult run();

private:
    // Contracts one theta range of point p within design d: the contracted
    // design, or the reason it is refuted (kReach, or a disc's position).
    int contract(const Design& d, const Vec2& p, const Interval& theta, Design& out,
                 const std::vector<int>& near) const;
    // Refines and contracts the ranges of point k; false when none is left.
    bool process(Node& node, int k, const std::vector<int>& near);
    // Whether the node is refuted; contracts it otherwise.
    bool refuted(Node& node, int& at);
    double violation(const Design& d) const;

    const task::Task& task_;
    const BranchAndBoundOptions& o_;
    run::Deadline deadline_;
    std::vector<NoGoDisc> discs_;
    std::vector<Point> points_;
    std::vector<int> order_;  ///< points, the last to refute a box first
    std::set<int> used_primitives_;
    std::vector<char> used_discs_;
};

int Search::contract(const Design& d, const Vec2& p, const Interval& theta, Design& out,
                     const std::vector<int>& near) const {
    IntervalPoint b{d.bx, d.by};
    Interval r1 = d.r1;
    Interval r2 = d.r2;
    const Interval c = geometry::cos(theta);
    const Interval s = geometry::sin(theta);
    IntervalPoint e{b.x + r1 * c, b.y + r1 * s};
    for (int pass = 0; pass < 2; ++pass) {
        IntervalPoint target{Interval(p.x()), Interval(p.y())};
        if (!geometry::contract_distance(e, target, r2)) return kReach;
        // e = b + r1 (cos theta, sin theta), backward to b, then |e - b| = r1.
        b.x = geometry::intersect(b.x, e.x - r1 * c);
        b.y = geometry::intersect(b.y, e.y - r1 * s);
        if (!geometry::contract_distance(e, b, r1)) return kReach;
        e.x = geometry::intersect(e.x, b.x + r1 * c);
        e.y = geometry::intersect(e.y, b.y + r1 * s);
        if (e.is_empty()) return kReach;
    }
    // Every point of a segment moves no farther than the farther of its
    // ends, so the distance at the centres plus that bounds the distance
    // for every design of the box from above.
    const Vec2 bc(b.x.mid(), b.y.mid());
    const Vec2 ec(e.x.mid(), e.y.mid());
    const double rb = half_diagonal(b.x, b.y);
    const double re = half_diagonal(e.x, e.y);
    for (int i : near) {
        const auto& disc = discs_[i];
        const double need = disc.radius - kNoGoSlack;
        if (geometry::point_segment(disc.center, bc, ec) + std::max(rb, re) < need) return i;
        if (geometry::point_segment(disc.center, ec, p) + re < need) return i;
    }
    // Rounding in the crossings is far below kNoGoSlack.
    const IntervalPoint target{Interval(p.x()), Interval(p.y())};
    for (int i : near) {
        const auto& disc = discs_[i];
        const double need = disc.radius - kNoGoSlack;
        if (every_segment_hits(b, e, disc.center, need)) return i;
        if (every_segment_hits(e, target, disc.center, need)) return i;
    }
    out = {b.x, b.y, r1, r2};
    return -2;
}

bool Search::process(Node& node, int k, const std::vector<int>& near) {
    const Vec2& p = points_[k].p;
    const double target = std::max(node.d.width(), o_.delta) / std::max(node.d.r1.hi, o_.delta);
    std::vector<Interval> todo = std::move(node.ranges[k]);
    std::vector<Interval> alive;
    Design h = empty_design();
    while (!todo.empty()) {
        const Interval t = todo.back();
        todo.pop_back();
        Design got;
        const int why = contract(node.d, p, t, got, near);
        if (why >= 0) node.used[why] = 1;
        if (why != -2) continue;
        if (t.width() > target &&
            static_cast<int>(alive.size() + todo.size()) + 2 <= o_.max_angle_ranges) {
            const double m = t.mid();
            todo.push_back({t.lo, m});
            todo.push_back({m, t.hi});
            continue;
        }
        alive.push_back(t);
        h = hull(h, got);
    }
    node.ranges[k] = std::move(alive);
    if (node.ranges[k].empty()) return false;
    node.d = intersect(node.d, h);
    return !node.d.is_empty();
}

bool Search::refuted(Node& node, int& at) {
    // Discs some link of a design in the box could touch.
    const Interval reach = node.d.r1 + node.d.r2;
    std::vector<int> near;
    for (int i = 0; i < static_cast<int>(discs_.size()); ++i) {
        const double gap = geometry::point_box(discs_[i].center, {node.d.bx.lo, node.d.by.lo},
                                               {node.d.bx.hi, node.d.by.hi});
        if (gap < discs_[i].radius + reach.hi) near.push_back(i);
    }
    for (std::size_t n = 0; n < order_.size(); ++n) {
        const int k = order_[n];
        if (!process(node, k, near)) {
            at = k;
            // The point that refuted this box is likely to refute its
            // neighbours too: try it first from now on.
            std::rotate(order_.begin(), order_.begin() + static_cast<long>(n),
                        order_.begin() + static_cast<long>(n) + 1);
            return true;
        }
    }
    return false;
}

// Largest shortfall over the points of the centre design of d, with the
// better elbow at each point.
double Search::violation(const Design& d) const {
    const Vec2 b(d.bx.mid(), d.by.mid());
    const double r1 = d.r1.mid();
    const double r2 = d.r2.mid();
    double worst = 0.0;
    for (const auto& pt : points_) {
        const Vec2 v = pt.p - b;
        const double dist = v.norm();
        double best = std::numeric_limits<double>::infinity();
        // The elbow nearest to the two circles' intersection when they do
        // not meet; both branches when they do.
        const double reach_short = std::max({dist - (r1 + r2), std::abs(r1 - r2) - dist, 0.0});
        const double a = dist > 0 ? (r1 * r1 - r2 * r2 + dist * dist) / (2 * dist) : 0.0;
        const double hh = std::sqrt(std::max(0.0, r1 * r1 - a * a));
        const Vec2 u = dist > 0 ? Vec2(v / dist) : Vec2(1.0, 0.0);
        for (int sign : {-1, 1}) {
            const Vec2 e = b + std::clamp(a, -r1, r1) * u + sign * hh * geometry::perp(u);
            double miss = reach_short;
            for (const auto& disc : discs_) {
                miss = std::max(miss, disc.radius - geometry::point_segment(disc.center, b, e));
                miss = std::max(miss, disc.radius - geometry::point_segment(disc.center, e, pt.p));
            }
            best = std::min(best, miss);
        }
        worst = std::max(worst, best);
    }
    return worst;
}

BranchAndBoundResult Search::run() {
    const run::Stopwatch clock;
    const run::Deadline stop = deadline_.within(o_.time_limit);
    BranchAndBoundResult result;
    result.points = static_cast<int>(points_.size());
    used_discs_.assign(discs_.size(), 0);
    for (int k = 0; k < static_cast<int>(points_.size()); ++k) order_.push_back(k);
    const auto finish = [&](BranchAndBoundResult::Outcome outcome) {
        result.outcome = outcome;
        result.seconds = clock.seconds();
        return result;
    };
    if (task_.base_regions.empty() || points_.empty()) return finish(result.outcome);
    const Interval lengths(task_.robot.min_link_length, task_.robot.max_link_length);
    for (int region = 0; region < static_cast<int>(task_.base_regions.size()); ++region) {
        const auto& r = task_.base_regions[region];
        Node root;
        root.d = {Interval(r.min.x(), r.max.x()), Interval(r.min.y(), r.max.y()), lengths, lengths};
        root.ranges.assign(points_.size(), {Interval(-geometry::kPi, geometry::kPi)});
        root.used.assign(discs_.size(), 0);
        std::vector<Node> stack{std::move(root)};
        while (!stack.empty()) {
            if (stop.expired() || result.boxes >= o_.max_boxes)
                return finish(BranchAndBoundResult::Outcome::Unknown);
            Node node = std::move(stack.back());
            stack.pop_back();
            ++result.boxes;
            int at = -1;
            if (refuted(node, at)) {
                used_primitives_.insert(points_[at].primitive);
                for (std::size_t i = 0; i < discs_.size(); ++i)
                    if (node.used[i]) used_discs_[i] = 1;
                continue;
            }
            if (node.d.width() <= o_.delta) {
                DesignBox box;
                box.base_region = region;
                box.base_min = {node.d.bx.lo, node.d.by.lo};
                box.base_max = {node.d.bx.hi, node.d.by.hi};
                box.r1_min = node.d.r1.lo, box.r1_max = node.d.r1.hi;
                box.r2_min = node.d.r2.lo, box.r2_max = node.d.r2.hi;
                result.box = box;
                result.violation = violation(node.d);
                return finish(BranchAndBoundResult::Outcome::Box);
            }
            // Bisect the widest variable.
            int w = 0;
            for (int v = 1; v < 4; ++v)
                if (var(node.d, v).width() > var(node.d, w).width()) w = v;
            const Interval whole = var(node.d, w);
            Node other = node;
            var(node.d, w) = {whole.lo, whole.mid()};
            var(other.d, w) = {whole.mid(), whole.hi};
            stack.push_back(std::move(other));
            stack.push_back(std::move(node));
        }
    }
    for (std::size_t i = 0; i < discs_.size(); ++i)
        if (used_discs_[i]) result.obstacles.push_back(discs_[i].obstacle);
    result.primitives.assign(used_primitives_.begin(), used_primitives_.end());
    return finish(BranchAndBoundResult::Outcome::Infeasible);
}

}  // namespace

bool BranchAndBoundOptions::IsValid(std::string* error) const {
    return text::OptionCheck("BranchAndBoundOptions", error)
        .greater("delta", delta, 0.0)
        .greater("time_limit", time_limit, 0.0)
        .at_least("max_boxes", static_cast<double>(max_boxes), 1)
        .greater("point_spacing", point_spacing, 0.0)
        .at_least("max_points", max_points, 2)
        .at_least("max_angle_ranges", max_angle_ranges, 2)
        .at_least("core_time_limit", core_time_limit, 0.0)
        .greater("core_run_time_limit", core_run_time_limit, 0.0)
        .ok();
}

BranchAndBoundResult branch_and_bound(const task::Task& task, const std::vector<int>& obstacles,
                                      const BranchAndBoundOptions& options,
                                      run::Deadline deadline) {
    text::require_valid(options);
    Search search(task, obstacles, options, deadline);
    return search.run();
}

}  // namespace modsynth::prove
