#include <modsynth/prove/spatial_enclosure.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <map>
#include <set>
#include <utility>
#include <variant>

#include <modsynth/geometry/interval.h>
#include <modsynth/geometry/primitive3.h>
#include <modsynth/prove/obstacle_proof.h>
#include <modsynth/task/spatial_strokes.h>
#include <modsynth/text/format.h>

namespace modsynth::prove {
namespace {

using geometry::Box3;
using geometry::Interval;
using geometry::Vec3;

/// A box's shape grown by `grow`, bounding box only.
Box3 grown_bounds(const geometry::Obstacle3& o, double grow) {
    return std::visit(
        [&](const auto& s) -> Box3 {
            using T = std::decay_t<decltype(s)>;
            if constexpr (std::is_same_v<T, geometry::Sphere>) {
                const Vec3 r = Vec3::Constant(s.radius + grow);
                return {s.center - r, s.center + r};
            } else if constexpr (std::is_same_v<T, geometry::Capsule>) {
                const Vec3 r = Vec3::Constant(s.radius + grow);
                return {s.a.cwiseMin(s.b) - r, s.a.cwiseMax(s.b) + r};
            } else {
                return {s.min - Vec3::Constant(grow), s.max + Vec3::Constant(grow)};
            }
        },
        o);
}

Interval squared_distance(const Vec3& p, const Vec3& q) {
    Interval d2(0.0);
    for (int a = 0; a < 3; ++a) d2 = d2 + geometry::sqr(Interval(p[a]) - Interval(q[a]));
    return d2;
}

/// Whether p lies in the open grown obstacle, for certain: the squared
/// distance's upper bound below the squared grown radius's lower bound.
bool surely_inside(const Vec3& p, const geometry::Obstacle3& o, const Interval& half_tube) {
    return std::visit(
        [&](const auto& s) -> bool {
            using T = std::decay_t<decltype(s)>;
            if constexpr (std::is_same_v<T, geometry::Sphere>) {
                const Interval r = Interval(s.radius) + half_tube;
                return squared_distance(p, s.center).hi < geometry::sqr(r).lo;
            } else if constexpr (std::is_same_v<T, geometry::Capsule>) {
                // Any point of the axis is at least as far as the nearest;
                // t is exact once chosen, so only the point's rounding counts.
                const Vec3 ab = s.b - s.a;
                const double len2 = ab.squaredNorm();
                const double t = len2 > 0.0 ? std::clamp((p - s.a).dot(ab) / len2, 0.0, 1.0) : 0.0;
                Interval d2(0.0);
                for (int a = 0; a < 3; ++a) {
                    const Interval q =
                        Interval(s.a[a]) + Interval(t) * (Interval(s.b[a]) - Interval(s.a[a]));
                    d2 = d2 + geometry::sqr(Interval(p[a]) - q);
                }
                const Interval r = Interval(s.radius) + half_tube;
                return d2.hi < geometry::sqr(r).lo;
            } else {
                Interval d2(0.0);
                for (int a = 0; a < 3; ++a) {
                    const Interval below = Interval(s.min[a]) - Interval(p[a]);
                    const Interval above = Interval(p[a]) - Interval(s.max[a]);
                    const Interval out(std::max({0.0, below.lo, above.lo}),
                                       std::max({0.0, below.hi, above.hi}));
                    d2 = d2 + geometry::sqr(out);
                }
                return d2.hi < geometry::sqr(half_tube).lo;
            }
        },
        o);
}

/// The cells of one try: which obstacles block each (a cell inside one
/// grown obstacle), and the cells of each obstacle, so that one can be
/// taken out again.
class CellGrid {
public:
    CellGrid(const EnclosureGrid& g) : g_(g) {
        n_ = static_cast<std::size_t>(g.size[0]) * g.size[1] * g.size[2];
        blockers_.assign(n_, 0);
    }

    const EnclosureGrid& grid() const { return g_; }
    std::size_t cells() const { return n_; }
    std::size_t index(int i, int j, int k) const {
        return (static_cast<std::size_t>(k) * g_.size[1] + j) * g_.size[0] + i;
    }
    std::array<int, 3> coords(std::size_t c) const {
        const int i = static_cast<int>(c % g_.size[0]);
        const std::size_t r = c / g_.size[0];
        return {i, static_cast<int>(r % g_.size[1]), static_cast<int>(r / g_.size[1])};
    }
    bool blocked(std::size_t c) const { return blockers_[c] > 0; }
    double corner(int axis, int i) const { return g_.origin[axis] + i * g_.cell; }

    /// Marks the cells inside obstacle `id`'s grown shape.
    void add(int id, const geometry::Obstacle3& o, double half_tube) {
        const Box3 b = grown_bounds(o, half_tube);
        std::array<int, 3> lo{}, hi{};
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::max(0, static_cast<int>(std::floor((b.min[a] - g_.origin[a]) / g_.cell)));
            hi[a] = std::min(g_.size[a],
                             static_cast<int>(std::ceil((b.max[a] - g_.origin[a]) / g_.cell)));
            if (lo[a] >= hi[a]) return;
        }
        // Corner flags first: each corner is shared by eight cells.
        const int vx = hi[0] - lo[0] + 1, vy = hi[1] - lo[1] + 1, vz = hi[2] - lo[2] + 1;
        std::vector<std::uint8_t> in(static_cast<std::size_t>(vx) * vy * vz);
        const Interval h = Interval(half_tube);
        for (int z = 0; z < vz; ++z)
            for (int y = 0; y < vy; ++y)
                for (int x = 0; x < vx; ++x)
                    in[(static_cast<std::size_t>(z) * vy + y) * vx + x] = surely_inside(
                        Vec3(corner(0, lo[0] + x), corner(1, lo[1] + y), corner(2, lo[2] + z)), o,
                        h);
        const auto at = [&](int x, int y, int z) {
            return in[(static_cast<std::size_t>(z) * vy + y) * vx + x] != 0;
        };
        std::vector<std::size_t>& mine = cells_of_[id];
        for (int z = 0; z + 1 < vz; ++z)
            for (int y = 0; y + 1 < vy; ++y)
                for (int x = 0; x + 1 < vx; ++x) {
                    bool all = true;
                    for (int c = 0; c < 8 && all; ++c)
                        all = at(x + (c & 1), y + ((c >> 1) & 1), z + ((c >> 2) & 1));
                    if (!all) continue;
                    const std::size_t cell = index(lo[0] + x, lo[1] + y, lo[2] + z);
                    ++blockers_[cell];
                    mine.push_back(cell);
                }
    }
    /// Marks every cell whose centre lies within `reach` of the obstacle's
    /// core (a sphere's centre, a capsule's axis, a box): a cell that comes
    /// near the obstacle when reach adds half the cell's diagonal.
    void add_near(int id, const geometry::Obstacle3& o, double reach) {
        const Box3 b = grown_bounds(o, reach);
        std::array<int, 3> lo{}, hi{};
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::max(0, static_cast<int>(std::floor((b.min[a] - g_.origin[a]) / g_.cell)));
            hi[a] = std::min(g_.size[a],
                             static_cast<int>(std::ceil((b.max[a] - g_.origin[a]) / g_.cell)));
        }
        std::vector<std::size_t>& mine = cells_of_[id];
        for (int k = lo[2]; k < hi[2]; ++k)
            for (int j = lo[1]; j < hi[1]; ++j)
                for (int i = lo[0]; i < hi[0]; ++i) {
                    const Vec3 c(corner(0, i) + g_.cell / 2, corner(1, j) + g_.cell / 2,
                                 corner(2, k) + g_.cell / 2);
                    if (geometry::point_gap(c, o) >= reach) continue;
                    ++blockers_[index(i, j, k)];
                    mine.push_back(index(i, j, k));
                }
    }
    void remove(int id) {
        for (std::size_t c : cells_of_[id]) --blockers_[c];
    }
    void restore(int id) {
        for (std::size_t c : cells_of_[id]) ++blockers_[c];
    }
    /// The obstacles blocking cell c.
    std::vector<int> blockers_of(std::size_t c) const {
        std::vector<int> out;
        for (const auto& [id, cells] : cells_of_)
            if (blockers_[c] > 0 && std::binary_search(cells.begin(), cells.end(), c))
                out.push_back(id);
        return out;
    }
    std::size_t cell_count(int id) const {
        const auto it = cells_of_.find(id);
        return it == cells_of_.end() ? 0 : it->second.size();
    }
    void sort_cells() {
        for (auto& [id, cells] : cells_of_) std::sort(cells.begin(), cells.end());
    }

    /// The cells meeting a box (a few more where rounding could matter:
    /// more is only safer); `outside` when the box reaches the border.
    std::vector<std::size_t> meeting(const Box3& b, bool& outside) const {
        std::array<int, 3> lo{}, hi{};
        outside = false;
        for (int a = 0; a < 3; ++a) {
            const int l = static_cast<int>(std::floor((b.min[a] - g_.origin[a]) / g_.cell)) - 1;
            const int h = static_cast<int>(std::floor((b.max[a] - g_.origin[a]) / g_.cell)) + 1;
            if (l < 1 || h > g_.size[a] - 2) outside = true;
            lo[a] = std::max(0, l);
            hi[a] = std::min(g_.size[a] - 1, h);
        }
        std::vector<std::size_t> out;
        for (int k = lo[2]; k <= hi[2]; ++k)
            for (int j = lo[1]; j <= hi[1]; ++j)
                for (int i = lo[0]; i <= hi[0]; ++i) out.push_back(index(i, j, k));
        return out;
    }

private:
    EnclosureGrid g_;
    std::size_t n_ = 0;
    std::vector<std::uint16_t> blockers_;
    std::map<int, std::vector<std::size_t>> cells_of_;
};

/// The free cells a curve from `from` reaches, when they stay off the
/// border, meet none of `to`, and number at most `cap`; nullopt otherwise.
std::optional<std::vector<std::size_t>> enclosed(const CellGrid& g,
                                                 const std::vector<std::size_t>& from,
                                                 const std::vector<std::size_t>& to,
                                                 std::size_t cap, const run::Deadline& deadline) {
    std::vector<std::uint8_t> mark(g.cells(), 0);
    for (std::size_t c : to) mark[c] = 2;
    std::vector<std::size_t> seen;
    std::deque<std::size_t> queue;
    for (std::size_t c : from) {
        if (g.blocked(c) || mark[c] == 1) continue;
        if (mark[c] == 2) return std::nullopt;
        mark[c] = 1;
        queue.push_back(c);
        seen.push_back(c);
    }
    const auto& size = g.grid().size;
    while (!queue.empty()) {
        if (seen.size() > cap || ((seen.size() & 0xffff) == 0 && deadline.expired()))
            return std::nullopt;
        const std::size_t c = queue.front();
        queue.pop_front();
        const auto [i, j, k] = g.coords(c);
        if (i == 0 || j == 0 || k == 0 || i + 1 == size[0] || j + 1 == size[1] || k + 1 == size[2])
            return std::nullopt;
        for (const std::size_t n : {c - 1, c + 1, c - size[0], c + size[0],
                                    c - static_cast<std::size_t>(size[0]) * size[1],
                                    c + static_cast<std::size_t>(size[0]) * size[1]}) {
            if (mark[n] == 1 || g.blocked(n)) continue;
            if (mark[n] == 2) return std::nullopt;
            mark[n] = 1;
            queue.push_back(n);
            seen.push_back(n);
        }
    }
    std::sort(seen.begin(), seen.end());
    return seen;
}

/// The obstacles that block a face neighbour of the cells.
std::set<int> shell_of(const CellGrid& g, const std::vector<std::size_t>& cells) {
    std::set<int> out;
    const auto& size = g.grid().size;
    for (std::size_t c : cells)
        for (const std::size_t n : {c - 1, c + 1, c - size[0], c + size[0],
                                    c - static_cast<std::size_t>(size[0]) * size[1],
                                    c + static_cast<std::size_t>(size[0]) * size[1]})
            if (g.blocked(n) && !std::binary_search(cells.begin(), cells.end(), n))
                for (int id : g.blockers_of(n)) out.insert(id);
    return out;
}

std::vector<CellRun> runs_of(const CellGrid& g, const std::vector<std::size_t>& cells) {
    std::vector<CellRun> out;
    for (std::size_t c : cells) {
        const auto [i, j, k] = g.coords(c);
        if (!out.empty() && out.back().j == j && out.back().k == k && out.back().i1 + 1 == i)
            out.back().i1 = i;
        else
            out.push_back({j, k, i, i});
    }
    return out;
}

/// Points of the path an EE must visit, a few per primitive.
std::vector<std::pair<int, Vec3>> path_points(const task::SpatialTask& task) {
    std::vector<std::pair<int, Vec3>> out;
    for (int j = 0; j < static_cast<int>(task.trajectory.size()); ++j) {
        const auto& p = task.trajectory[static_cast<std::size_t>(j)];
        const double l = geometry::length(p);
        for (double f : {0.5, 0.0, 1.0}) out.push_back({j, geometry::point_at(p, f * l)});
    }
    return out;
}

/// m: how near the free part of a chain comes to a path point it must
/// visit: the tool, and the 1 mm the EE may stay off the path (rule 1).
constexpr double kOffPath = 1e-3;
double reach_slack(const task::SpatialTask& task) { return task.robot.tool_length + kOffPath; }

Box3 around(const Vec3& p, double r) { return {p - Vec3::Constant(r), p + Vec3::Constant(r)}; }

/// The searched box: the base region and the path (their neighbourhoods)
/// and the obstacles, clipped to a margin round the first two: cells
/// beyond it count as one free outside.
EnclosureGrid grid_for(const task::SpatialTask& task, const Box3& seed, int resolution) {
    Box3 near = seed;
    for (const auto& [j, p] : path_points(task)) {
        near.min = near.min.cwiseMin(p - Vec3::Constant(reach_slack(task)));
        near.max = near.max.cwiseMax(p + Vec3::Constant(reach_slack(task)));
    }
    Box3 all = near;
    for (const auto& o : task.obstacles) {
        const Box3 b = grown_bounds(o, task.robot.link_diameter / 2.0);
        all.min = all.min.cwiseMin(b.min);
        all.max = all.max.cwiseMax(b.max);
    }
    const double margin = std::max(0.25, (near.max - near.min).maxCoeff());
    all.min = all.min.cwiseMax(near.min - Vec3::Constant(margin));
    all.max = all.max.cwiseMin(near.max + Vec3::Constant(margin));
    const double extent = std::max((all.max - all.min).maxCoeff(), 1e-6);
    EnclosureGrid g;
    // A power of two, and an origin on its multiples: exact corners.
    g.cell = std::exp2(std::ceil(std::log2(extent / resolution)));
    for (int a = 0; a < 3; ++a) {
        // Two cells of border, free unless an obstacle reaches them.
        const double lo = std::floor(all.min[a] / g.cell) - 2.0;
        const double hi = std::ceil(all.max[a] / g.cell) + 2.0;
        g.origin[a] = lo * g.cell;
        g.size[a] = static_cast<int>(hi - lo);
    }
    return g;
}

/// The free cells' connected components (face neighbours), and which
/// touch the grid's border (they join the free outside).
struct Components {
    std::vector<int> label;  ///< per cell, -1 when blocked
    std::vector<bool> open;  ///< per component

    /// The components of the free cells among `cells`; `open` becomes true
    /// when one of them is open.
    std::set<int> of(const CellGrid& g, const std::vector<std::size_t>& cells,
                     bool& is_open) const {
        std::set<int> out;
        for (std::size_t c : cells)
            if (!g.blocked(c)) out.insert(label[c]);
        for (int c : out) is_open = is_open || open[static_cast<std::size_t>(c)];
        return out;
    }
};

/// Empty labels when the deadline passes first.
Components components(const CellGrid& g, const run::Deadline& deadline) {
    Components out;
    out.label.assign(g.cells(), -1);
    const auto& size = g.grid().size;
    const std::size_t plane = static_cast<std::size_t>(size[0]) * size[1];
    std::vector<std::size_t> stack;
    for (std::size_t start = 0; start < g.cells(); ++start) {
        if (g.blocked(start) || out.label[start] >= 0) continue;
        if (deadline.expired()) return {};
        const int id = static_cast<int>(out.open.size());
        bool open = false;
        out.label[start] = id;
        stack.push_back(start);
        while (!stack.empty()) {
            const std::size_t c = stack.back();
            stack.pop_back();
            const auto [i, j, k] = g.coords(c);
            if (i == 0 || j == 0 || k == 0 || i + 1 == size[0] || j + 1 == size[1] ||
                k + 1 == size[2]) {
                open = true;
                continue;  // neighbours beyond the border are the outside
            }
            for (const std::size_t n :
                 {c - 1, c + 1, c - size[0], c + size[0], c - plane, c + plane}) {
                if (g.blocked(n) || out.label[n] >= 0) continue;
                out.label[n] = id;
                stack.push_back(n);
            }
        }
        out.open.push_back(open);
    }
    return out;
}

/// Which path points some shell could keep from the seed at all: on a
/// coarse grid where every cell that comes near a grown obstacle counts as
/// blocked, free cells that join the seed to a point show a way clear of
/// every obstacle, which no finer grid closes. Only saves time.
std::vector<bool> possibly_walled(const task::SpatialTask& task, const Box3& seed,
                                  const std::vector<std::pair<int, Vec3>>& points,
                                  const EnclosureGrid& grid, const run::Deadline& deadline) {
    CellGrid g(grid);
    const double half_diagonal = std::sqrt(3.0) * grid.cell / 2.0 + 1e-9;
    for (int id = 0; id < static_cast<int>(task.obstacles.size()); ++id)
        g.add_near(id, task.obstacles[static_cast<std::size_t>(id)],
                   task.robot.link_diameter / 2.0 + half_diagonal);
    std::vector<bool> out(points.size(), true);
    const Components parts = components(g, deadline);
    if (parts.label.empty()) return out;
    bool seed_open = false;
    const std::set<int> from = parts.of(g, g.meeting(seed, seed_open), seed_open);
    for (std::size_t k = 0; k < points.size(); ++k) {
        bool open = false;
        const auto to =
            parts.of(g, g.meeting(around(points[k].second, reach_slack(task)), open), open);
        out[k] = !(seed_open && open) &&
                 std::none_of(from.begin(), from.end(), [&](int c) { return to.count(c) > 0; });
    }
    return out;
}

/// What one base region's shell came to.
struct Shell {
    Enclosure wall;
    std::vector<std::size_t> cells;  ///< the enclosed cells, ascending
};

class RegionSearch {
public:
    RegionSearch(const task::SpatialTask& task, int region, const run::Deadline& deadline,
                 bool minimise)
        : task_(task), region_(region), deadline_(deadline), minimise_(minimise) {
        const Box3& b = task.base_regions[static_cast<std::size_t>(region)];
        seed_ = {b.min - Vec3::Constant(task.robot.link_diameter / 2.0),
                 b.max + Vec3::Constant(task.robot.link_diameter / 2.0)};
    }

    /// A shell at the first resolution that closes one.
    std::optional<Shell> find(const EnclosureOptions& options, bool& timed_out);
    /// Drops the shell's obstacles that it closes without, one at a time,
    /// and fills in the witness's obstacles and cells; false when the
    /// deadline stopped it (the shell is then sound, not minimal).
    bool minimise(Shell& shell);

private:
    std::optional<Shell> at(const EnclosureGrid& grid, const std::vector<bool>& candidates);
    std::optional<std::vector<std::size_t>> close(const CellGrid& g, bool base_inside,
                                                  const Vec3& point, std::size_t cap) const {
        bool out_seed = false, out_point = false;
        const auto s = g.meeting(seed_, out_seed);
        const auto t = g.meeting(around(point, reach_slack(task_)), out_point);
        if (base_inside ? out_seed : out_point) return std::nullopt;
        return base_inside ? enclosed(g, s, t, cap, deadline_) : enclosed(g, t, s, cap, deadline_);
    }

    const task::SpatialTask& task_;
    const int region_;
    const run::Deadline& deadline_;
    const bool minimise_;
    Box3 seed_;
    std::optional<CellGrid> grid_;
};

std::optional<Shell> RegionSearch::find(const EnclosureOptions& options, bool& timed_out) {
    if (options.resolutions.empty()) return std::nullopt;
    const std::vector<bool> candidates =
        possibly_walled(task_, seed_, path_points(task_),
                        grid_for(task_, seed_, options.resolutions.front()), deadline_);
    if (std::none_of(candidates.begin(), candidates.end(), [](bool b) { return b; }))
        return std::nullopt;
    for (int resolution : options.resolutions) {
        if (deadline_.expired()) {
            timed_out = true;
            return std::nullopt;
        }
        if (auto s = at(grid_for(task_, seed_, resolution), candidates)) return s;
    }
    return std::nullopt;
}

std::optional<Shell> RegionSearch::at(const EnclosureGrid& grid,
                                      const std::vector<bool>& candidates) {
    grid_.emplace(grid);
    CellGrid& g = *grid_;
    for (int i = 0; i < static_cast<int>(task_.obstacles.size()); ++i)
        g.add(i, task_.obstacles[static_cast<std::size_t>(i)], task_.robot.link_diameter / 2.0);
    g.sort_cells();
    const Components parts = components(g, deadline_);
    if (parts.label.empty()) return std::nullopt;
    bool seed_open = false;
    const std::set<int> seed = parts.of(g, g.meeting(seed_, seed_open), seed_open);
    const auto points = path_points(task_);
    for (std::size_t k = 0; k < points.size(); ++k) {
        if (!candidates[k]) continue;
        const auto& [j, p] = points[k];
        bool point_open = false;
        const std::set<int> target =
            parts.of(g, g.meeting(around(p, reach_slack(task_)), point_open), point_open);
        if ((seed_open && point_open) ||
            std::any_of(seed.begin(), seed.end(), [&](int c) { return target.count(c) > 0; }))
            continue;
        // The closed side: its components' cells.
        const std::set<int>& inside = seed_open ? target : seed;
        Shell s;
        s.wall = {region_, j, p, {}, grid, !seed_open, {}};
        for (std::size_t c = 0; c < g.cells(); ++c)
            if (parts.label[c] >= 0 && inside.count(parts.label[c])) s.cells.push_back(c);
        return s;
    }
    return std::nullopt;
}

bool RegionSearch::minimise(Shell& s) {
    CellGrid& g = *grid_;
    const bool inside = s.wall.base_inside;
    const std::set<int> shell = shell_of(g, s.cells);
    // Obstacles that block no neighbour of the cells are not part of the
    // wall; without them (inner ones freed) the cells are found again.
    const int n = static_cast<int>(task_.obstacles.size());
    for (int i = 0; i < n; ++i)
        if (!shell.count(i)) g.remove(i);
    if (auto c = close(g, inside, s.wall.point, g.cells())) {
        s.cells = std::move(*c);
    } else {
        for (int i = 0; i < n; ++i)
            if (!shell.count(i)) g.restore(i);
    }
    bool complete = true;
    // Largest first: a big obstacle that others cover goes before the
    // small ones that it would otherwise keep.
    std::vector<int> order;
    if (minimise_) order.assign(shell.begin(), shell.end());
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return g.cell_count(a) > g.cell_count(b); });
    for (int id : order) {
        if (deadline_.expired()) {
            complete = false;
            break;
        }
        g.remove(id);
        // Without it the cells can only gain its own and what they open.
        const std::size_t cap = s.cells.size() + g.cell_count(id) + 64;
        if (auto c = close(g, inside, s.wall.point, cap)) {
            s.cells = std::move(*c);
        } else {
            g.restore(id);
        }
    }
    // The wall: what blocks a neighbour of the cells now; with no free cell
    // on the enclosed side (a base region deep inside an obstacle, or a
    // tube as thick as the region's surroundings), what blocks the cells
    // that side meets: the chain has no free point there to start from.
    std::set<int> wall = shell_of(g, s.cells);
    if (s.cells.empty()) {
        bool out = false;
        const auto side = g.meeting(inside ? seed_ : around(s.wall.point, reach_slack(task_)), out);
        for (std::size_t c : side)
            for (int id : g.blockers_of(c)) wall.insert(id);
    }
    s.wall.obstacles.assign(wall.begin(), wall.end());
    s.wall.cells = runs_of(g, s.cells);
    return complete;
}

/// Whether the same obstacles close a shell on the same grid for a tube of
/// diameter 0 (the base region and the obstacles not grown).
bool closes_without_tube(const task::SpatialTask& task, const Enclosure& wall,
                         const run::Deadline& deadline) {
    CellGrid g(wall.grid);
    for (int i : wall.obstacles) g.add(i, task.obstacles[static_cast<std::size_t>(i)], 0.0);
    bool out_seed = false, out_point = false;
    const auto s =
        g.meeting(task.base_regions[static_cast<std::size_t>(wall.base_region)], out_seed);
    const auto t = g.meeting(around(wall.point, reach_slack(task)), out_point);
    if (wall.base_inside ? out_seed : out_point) return false;
    return (wall.base_inside ? enclosed(g, s, t, g.cells(), deadline)
                             : enclosed(g, t, s, g.cells(), deadline))
        .has_value();
}

std::string point_text(const Vec3& p) {
    return text::format("(%.3f, %.3f, %.3f)", p.x(), p.y(), p.z());
}

}  // namespace

std::optional<Proof> prove_spatial_enclosure(const task::SpatialTask& task,
                                             const run::Deadline& deadline,
                                             const EnclosureOptions& options) {
    if (task.base_regions.empty() || task.obstacles.empty() || task.trajectory.empty())
        return std::nullopt;
    Proof proof;
    EnclosureWitness witness;
    bool tube = false;
    std::set<int> obstacles;
    std::vector<int> primitives;
    std::string said;
    bool cells = false;  ///< some wall holds cells (the others none)
    for (int r = 0; r < static_cast<int>(task.base_regions.size()); ++r) {
        RegionSearch search(task, r, deadline, options.minimise);
        bool timed_out = false;
        std::optional<Shell> shell = search.find(options, timed_out);
        if (!shell) return std::nullopt;
        if (!search.minimise(*shell) || !options.minimise) proof.minimal = false;
        Enclosure& w = shell->wall;
        tube = tube || !closes_without_tube(task, w, deadline);
        obstacles.insert(w.obstacles.begin(), w.obstacles.end());
        if (std::find(primitives.begin(), primitives.end(), w.primitive) == primitives.end())
            primitives.push_back(w.primitive);
        const std::string region = task::to_string(task::TaskPart::base_region(r));
        const std::string point = task::part_name(task, w.primitive) + " at " + point_text(w.point);
        // In a builder's words; the grid and its cells are the witness's.
        const std::string wall = "obstacles " + index_ranges(w.obstacles);
        cells = cells || !w.cells.empty();
        if (w.cells.empty())
            said += (said.empty() ? "" : "; ") + wall + " fill the space round " +
                    (w.base_inside ? region + " (to half an arm's thickness)"
                                   : "the path (" + point + ", to the tool's length and 1 mm)") +
                    ": no free point there for an arm to " +
                    (w.base_inside ? "leave from" : "reach");
        else
            said += (said.empty() ? "" : "; ") +
                    (w.base_inside ? wall + " close in " + region + ", and the path (" + point +
                                         ") is outside them"
                                   : "the path is closed in by " + wall + " (" + point +
                                         " is inside them), away from " + region);
        witness.walls.push_back(std::move(w));
    }
    std::sort(primitives.begin(), primitives.end());
    for (int j : primitives) proof.core.push_back(task::primitive_part(task, j));
    for (int i : obstacles) proof.core.push_back(task::TaskPart::obstacle(i));
    proof.core.push_back(task::TaskPart::base_regions());
    if (tube) proof.core.push_back(task::TaskPart::robot(task::RobotKey::LinkDiameter));
    if (task.robot.tool_length > 0.0)
        proof.core.push_back(task::TaskPart::robot(task::RobotKey::ToolLength));
    proof.message =
        said + (cells ? ": no arm from the base box can reach round them, since an arm is one "
                        "tube from its base to its tool" +
                            (tube ? text::format(", %.2f mm thick, and no gap between them is that "
                                                 "wide.",
                                                 task.robot.link_diameter * 1000.0)
                                  : std::string(", and they leave no gap at all."))
                      : std::string("."));
    if (!proof.minimal && options.minimise)
        proof.message += " (core not minimised within the time limit)";
    proof.enclosure = std::move(witness);
    return proof;
}

}  // namespace modsynth::prove
