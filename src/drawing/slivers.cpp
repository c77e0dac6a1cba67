#include <modsynth/drawing/slivers.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <unordered_map>

#include <boost/geometry/geometries/box.hpp>
#include <boost/geometry/geometries/point.hpp>
#include <boost/geometry/index/rtree.hpp>

#include <modsynth/drawing/biarc_fit.h>
#include <modsynth/geometry/distance.h>

namespace modsynth::drawing {

namespace {

using geometry::Primitive;
using geometry::PrimitiveKind;
using geometry::Vec2;

/// Tangents this close in direction (the sine of the angle) meet smoothly:
/// the fitting's biarcs meet to about 1e-12, corners of a drawing are
/// degrees apart.
constexpr double kSmooth = 1e-6;
/// Samples along each piece when measuring how far a replacement strays:
/// the pieces compared are within a few tolerances of length, and meet at
/// their ends, so their distance varies slowly between samples.
constexpr int kSamples = 64;
static_assert((kSamples & (kSamples - 1)) == 0, "halved down to 1");

/// The sample indices 0..kSamples, the middle first, then the middles of
/// the halves, and so on, the ends last: a replacement strays farthest from
/// the drawing between its ends, and once the worst is known the other
/// samples are quick to clear.
constexpr std::array<int, kSamples + 1> kMiddleFirst = [] {
    std::array<int, kSamples + 1> order{};
    std::size_t n = 0;
    for (int step = kSamples / 2; step >= 1; step /= 2)
        for (int i = step; i < kSamples; i += 2 * step) order[n++] = i;
    order[n++] = 0;
    order[n++] = kSamples;
    return order;
}();

Vec2 start_tangent(const Primitive& p) { return geometry::tangent_at(p, 0.0); }
Vec2 end_tangent(const Primitive& p) { return geometry::tangent_at(p, geometry::length(p)); }

bool smooth(const Primitive& a, const Primitive& b) {
    const Vec2 ta = end_tangent(a), tb = start_tangent(b);
    return ta.dot(tb) > 0.0 && std::abs(geometry::cross(ta, tb)) <= kSmooth;
}

/// The part of p (a line or an arc) from arc length s0 to s1 < length.
Primitive part(const Primitive& p, double s0, double s1) {
    const Vec2 a = geometry::point_at(p, s0), b = geometry::point_at(p, s1);
    if (p.kind == PrimitiveKind::Line) return geometry::make_line(a, b);
    return geometry::make_arc(a, b, p.center, p.sweep > 0.0);
}

/// A neighbour cut where a window of about `s` next to the sliver begins:
/// the window is replaced, the rest kept (none when it would be shorter
/// than the tolerance: then the whole neighbour is the window).
struct Cut {
    std::optional<Primitive> kept;
    Primitive window;
};

Cut cut_end(const Primitive& a, double s, double tolerance) {
    const double len = geometry::length(a);
    if (len - s < tolerance) return {std::nullopt, a};
    return {part(a, 0.0, len - s), part(a, len - s, len)};
}

Cut cut_start(const Primitive& b, double s, double tolerance) {
    const double len = geometry::length(b);
    if (len - s < tolerance) return {std::nullopt, b};
    return {part(b, s, len), part(b, 0.0, s)};
}

/// geometry::nearest(p, q).distance, the very same number, found for an
/// arc without q's polar angle when q's direction from the centre lies
/// clearly inside or clearly outside the arc's span (by the sines of its
/// angles with the ends' directions, a billionth of a radian from either):
/// thousands of drawing points are measured against every stretch of a
/// long run.
double piece_distance(const Primitive& p, const Vec2& q) {
    if (p.kind == PrimitiveKind::Arc && std::abs(std::abs(p.sweep) - geometry::kPi) > 1e-3) {
        const Vec2 v = q - p.center;
        const double r = v.norm();
        const double turn = p.sweep > 0.0 ? 1.0 : -1.0;
        // How far v lies past the start's direction, and short of the
        // end's, turning the arc's way.
        const double past_start = turn * geometry::cross(p.start - p.center, v);
        const double before_end = turn * geometry::cross(v, p.end - p.center);
        const double margin = 1e-9 * r * p.radius;
        int inside = -1;  // unknown
        if (std::abs(p.sweep) < geometry::kPi) {
            if (past_start > margin && before_end > margin) inside = 1;
            if (past_start < -margin || before_end < -margin) inside = 0;
        } else {
            // Outside a major arc is inside the minor arc from its end
            // round to its start.
            if (past_start < -margin && before_end < -margin) inside = 0;
            if (past_start > margin || before_end > margin) inside = 1;
        }
        if (r > 0.0 && inside == 1) return std::abs(r - p.radius);
        if (r > 0.0 && inside == 0) return std::min((q - p.start).norm(), (q - p.end).norm());
    }
    return geometry::nearest(p, q).distance;
}

/// The distance from q to the nearest of ps; as soon as one piece lies
/// within `enough` of q, that piece's distance (which is all a caller
/// taking the largest of such distances up to `enough` needs).
double distance_to(const std::vector<Primitive>& ps, const Vec2& q, double enough = -1.0) {
    double best = std::numeric_limits<double>::infinity();
    for (const Primitive& p : ps) {
        best = std::min(best, piece_distance(p, q));
        if (best <= enough) return best;
    }
    return best;
}

/// How far apart two runs of pieces lie, both ways, on samples of each.
double apart(const std::vector<Primitive>& a, const std::vector<Primitive>& b) {
    double worst = 0.0;
    for (const auto& [from, to] : {std::pair{&a, &b}, std::pair{&b, &a}}) {
        for (const Primitive& p : *from) {
            const double len = geometry::length(p);
            for (int i = 0; i <= kSamples; ++i) {
                worst =
                    std::max(worst, distance_to(*to, geometry::point_at(p, len * i / kSamples)));
            }
        }
    }
    return worst;
}

enum class Merge { Both, IntoPrevious, IntoNext };

/// chain[first..last] becomes `pieces`, `far` from what it replaces.
struct Replacement {
    std::size_t first = 0, last = 0;
    std::vector<Primitive> pieces;
    double far = 0.0;
};

std::optional<Replacement> candidate(const std::vector<Primitive>& chain, std::size_t i, Merge how,
                                     double s, double tolerance) {
    const Primitive& p = chain[i];
    Replacement r;
    std::vector<Primitive> old, fresh;
    std::optional<Primitive> before, after;
    switch (how) {
        case Merge::Both: {
            const Cut a = cut_end(chain[i - 1], s, tolerance);
            const Cut b = cut_start(chain[i + 1], s, tolerance);
            const auto arcs =
                biarc(a.window.start, start_tangent(a.window), b.window.end, end_tangent(b.window));
            if (!arcs) return std::nullopt;
            old = {a.window, p, b.window};
            fresh = *arcs;
            before = a.kept;
            after = b.kept;
            r.first = i - 1;
            r.last = i + 1;
            break;
        }
        case Merge::IntoPrevious: {
            const Cut a = cut_end(chain[i - 1], s, tolerance);
            old = {a.window, p};
            fresh = {arc_through(a.window.start, start_tangent(a.window), p.end)};
            before = a.kept;
            r.first = i - 1;
            r.last = i;
            break;
        }
        case Merge::IntoNext: {
            const Cut b = cut_start(chain[i + 1], s, tolerance);
            old = {p, b.window};
            fresh = {arc_into(p.start, b.window.end, end_tangent(b.window))};
            after = b.kept;
            r.first = i;
            r.last = i + 1;
            break;
        }
    }
    // A stroke shorter than the tolerance may end as one piece that short.
    const bool whole = r.first == 0 && r.last + 1 == chain.size() && !before && !after;
    for (const Primitive& q : fresh) {
        // A stroke that closes on itself within the tolerance would become
        // a piece of no length.
        if (q.kind == PrimitiveKind::Circle || !(geometry::length(q) >= kMinPiece))
            return std::nullopt;
        if (geometry::length(q) < tolerance && !(whole && fresh.size() == 1)) return std::nullopt;
    }
    r.far = apart(old, fresh);
    if (before) r.pieces.push_back(*before);
    r.pieces.insert(r.pieces.end(), fresh.begin(), fresh.end());
    if (after) r.pieces.push_back(*after);
    return r;
}

/// Gives up, as fitting does, once the import's deadline has passed;
/// looks at the clock every few hundred candidates.
class Watch {
public:
    Watch(Clock::time_point deadline, std::string doing)
        : deadline_(deadline), doing_(std::move(doing)) {}
    void tick() {
        if (count_++ % 256 == 0) now();
    }
    void now() const { check_deadline(deadline_, doing_); }

private:
    Clock::time_point deadline_;
    std::string doing_;
    unsigned count_ = 0;
};

/// The drawing a chain was fitted to, as a polyline whose points are at
/// most an eighth of the tolerance apart, filed in a grid of cells a bit
/// wider than the tolerance: how near a point lies to the drawing, and
/// which of its points lie near a place, without a pass over all of it.
class Drawn {
public:
    Drawn(std::span<const Curve> curves, double tolerance, const Watch& watch)
        : cell_(1.25 * tolerance) {
        const double step = tolerance / 8.0;
        std::vector<int> counts;
        std::size_t total = 0;
        for (const Curve& curve : curves) {
            watch.now();
            for (const Segment& seg : curve.segments) {
                double rough = 0.0;
                Vec2 last = point(seg, 0.0);
                for (int k = 1; k <= 64; ++k) {
                    const Vec2 q = point(seg, k / 64.0);
                    rough += (q - last).norm();
                    last = q;
                }
                // The coarse length is short of the true one by at most a
                // few per cent on the curves drawings hold; twice as many
                // points keep them within the step.
                counts.push_back(int(std::clamp(std::ceil(2.0 * rough / step), 8.0, 200000.0)));
                total += counts.back() + 1;
            }
        }
        pts_.reserve(total);
        joined_.reserve(total);
        std::size_t next = 0;
        for (const Curve& curve : curves) {
            bool first = true;
            for (const Segment& seg : curve.segments) {
                const int n = counts[next++];
                // A drawing hundreds of metres across at a tolerance of
                // micrometres holds millions of points.
                watch.now();
                for (int k = first ? 0 : 1; k <= n; ++k) {
                    pts_.push_back(point(seg, double(k) / n));
                    joined_.push_back(!(first && k == 0));
                }
                first = false;
            }
        }
        // The points are filed in the grid a chunk at a time, when a cell
        // a chunk's box meets is first looked at: merging looks near the
        // short pieces only, and a drawing much larger than the tolerance
        // would fill millions of cells.
        std::vector<std::pair<CellBox, std::uint32_t>> boxes;
        for (std::uint32_t begin = 0; begin < pts_.size(); begin += kChunk) {
            if (begin % 65536 == 0) watch.now();
            const std::uint32_t end = std::min<std::uint32_t>(begin + kChunk, pts_.size());
            auto [x0, y0] = cell(pts_[begin]);
            auto [x1, y1] = std::pair{x0, y0};
            for (std::uint32_t k = begin + 1; k < end; ++k) {
                const auto [x, y] = cell(pts_[k]);
                x0 = std::min(x0, x), x1 = std::max(x1, x);
                y0 = std::min(y0, y), y1 = std::max(y1, y);
            }
            boxes.push_back({CellBox({x0, y0}, {x1, y1}), begin / kChunk});
        }
        filed_.assign(boxes.size(), false);
        chunks_ = Chunks(boxes.begin(), boxes.end());
    }

    /// The distance from q to the drawing when it is within the tolerance
    /// (and somewhat beyond); infinity when the drawing is farther. As
    /// soon as a part of the drawing lies within `enough` of q, that part's
    /// distance.
    double distance(const Vec2& q, double enough = -1.0) const {
        double best = std::numeric_limits<double>::infinity();
        const auto [ix, iy] = cell(q);
        // q's own cell first: what lies within `enough` is most likely there.
        constexpr int kOwnFirst[9][2] = {{0, 0}, {-1, -1}, {-1, 0}, {-1, 1}, {0, -1},
                                         {0, 1}, {1, -1},  {1, 0},  {1, 1}};
        for (const auto& [dx, dy] : kOwnFirst) {
            const Cell& c = at_cell(ix + dx, iy + dy);
            for (std::size_t r = 0; r < c.size(); ++r) {
                for (std::uint32_t k = c[r].begin; k < c[r].end; ++k) {
                    // The point itself is the quickest to measure: it is
                    // usually within `enough` when the drawing is.
                    best = std::min(best, (q - pts_[k]).norm());
                    if (best <= enough) return best;
                    // Curves are not joined to each other: the segment
                    // before a curve's first point is none.
                    if (k + 1 < pts_.size() && joined_[k + 1])
                        best = std::min(best, geometry::point_segment(q, pts_[k], pts_[k + 1]));
                    if (joined_[k])
                        best = std::min(best, geometry::point_segment(q, pts_[k - 1], pts_[k]));
                    if (best <= enough) return best;
                }
            }
        }
        return best;
    }

    /// Calls f once with the index of every point of the drawing in the
    /// cells that hold one of `samples` or are next to one that does.
    /// Millions of samples make millions of cells: the deadline is looked
    /// at all along.
    template <class F>
    void around(const std::vector<Vec2>& samples, const Watch& watch, F f) const {
        // Cells are taken as they come, each once: a sort of all of them
        // would be one step too long to look at the clock inside.
        const std::uint32_t pass = ++around_pass_;
        std::pair<std::int64_t, std::int64_t> last{0, 0};
        for (std::size_t i = 0; i < samples.size(); ++i) {
            if (i % 1024 == 0) watch.now();
            const auto [ix, iy] = cell(samples[i]);
            // Samples a fifth of a cell apart mostly share their cell, and
            // the next cell's neighbours are mostly the last one's.
            if (i > 0 && last == std::pair{ix, iy}) continue;
            const auto [lx, ly] = last;
            const bool after = i > 0;
            last = {ix, iy};
            for (std::int64_t dx = -1; dx <= 1; ++dx) {
                for (std::int64_t dy = -1; dy <= 1; ++dy) {
                    if (after && std::abs(ix + dx - lx) <= 1 && std::abs(iy + dy - ly) <= 1)
                        continue;
                    const Cell& c = at_cell(ix + dx, iy + dy);
                    if (c.taken == pass) continue;
                    c.taken = pass;
                    for (std::size_t r = 0; r < c.size(); ++r)
                        for (std::uint32_t k = c[r].begin; k < c[r].end; ++k) f(k);
                }
            }
        }
    }

    const Vec2& at(std::uint32_t k) const { return pts_[k]; }

    /// Marks for a pass over points that may come up more than once: a
    /// new pass, then whether a point comes up for the first time in it.
    std::uint32_t new_pass() const {
        if (seen_.empty() || pass_ == std::numeric_limits<std::uint32_t>::max()) {
            seen_.assign(pts_.size(), 0);
            pass_ = 0;
        }
        return ++pass_;
    }
    bool first_in(std::uint32_t pass, std::uint32_t k) const {
        if (seen_[k] == pass) return false;
        seen_[k] = pass;
        return true;
    }

private:
    /// Points begin..end-1, consecutive along a curve.
    struct Run {
        std::uint32_t begin = 0, end = 0;
    };
    /// A cell's runs (most cells are crossed once), and whether every
    /// chunk that may hold points in it has been filed.
    struct Cell {
        Run first;
        std::vector<Run> more;
        bool complete = false;
        mutable std::uint32_t taken = 0;  ///< the last call of around() that took it
        std::size_t size() const { return first.end == 0 ? 0 : 1 + more.size(); }
        const Run& operator[](std::size_t r) const { return r == 0 ? first : more[r - 1]; }
        void add(std::uint32_t k) {
            if (first.end == 0)
                first = {k, k + 1};
            else if (Run& last = more.empty() ? first : more.back(); last.end == k)
                ++last.end;
            else
                more.push_back({k, k + 1});
        }
    };
    using CellPoint =
        boost::geometry::model::point<std::int64_t, 2, boost::geometry::cs::cartesian>;
    using CellBox = boost::geometry::model::box<CellPoint>;
    using Chunks = boost::geometry::index::rtree<std::pair<CellBox, std::uint32_t>,
                                                 boost::geometry::index::rstar<16>>;
    static constexpr std::uint32_t kChunk = 64;

    /// The cell (ix, iy) with all of its points, filing first the chunks
    /// that may hold some.
    const Cell& at_cell(std::int64_t ix, std::int64_t iy) const {
        Cell& c = grid_[combine(ix, iy)];
        if (c.complete) return c;
        std::vector<std::pair<CellBox, std::uint32_t>> found;
        chunks_.query(boost::geometry::index::intersects(CellBox({ix, iy}, {ix, iy})),
                      std::back_inserter(found));
        for (const auto& [box, chunk] : found) {
            if (filed_[chunk]) continue;
            filed_[chunk] = true;
            const std::uint32_t end =
                std::min<std::uint32_t>((chunk + 1) * kChunk, std::uint32_t(pts_.size()));
            for (std::uint32_t k = chunk * kChunk; k < end; ++k) grid_[key(pts_[k])].add(k);
        }
        // grid_ may have grown: c is still where it was (its nodes stay).
        c.complete = true;
        return c;
    }

    std::pair<std::int64_t, std::int64_t> cell(const Vec2& q) const {
        return {std::int64_t(std::floor(q.x() / cell_)), std::int64_t(std::floor(q.y() / cell_))};
    }
    static std::int64_t combine(std::int64_t ix, std::int64_t iy) {
        return (ix << 32) ^ (iy & 0xffffffff);
    }
    std::int64_t key(const Vec2& q) const {
        const auto [ix, iy] = cell(q);
        return combine(ix, iy);
    }

    double cell_;
    std::vector<Vec2> pts_;
    std::vector<bool> joined_;  ///< whether pts_[k] continues the curve of pts_[k - 1]
    mutable std::unordered_map<std::int64_t, Cell> grid_;
    Chunks chunks_;
    mutable std::vector<bool> filed_;
    mutable std::vector<std::uint32_t> seen_;
    mutable std::uint32_t pass_ = 0;
    mutable std::uint32_t around_pass_ = 0;
};

/// The drawing's points within the tolerance of each piece of a chain,
/// found once for a piece while the chain stays as it is: the candidates
/// for one run replace overlapping stretches of it, the stretches of a
/// long run (one more piece each) all of its start.
class Covered {
public:
    Covered(const Drawn& drawn, const std::vector<Primitive>& chain, double tolerance,
            const Watch& watch)
        : drawn_(drawn), chain_(chain), tolerance_(tolerance), watch_(watch) {}

    const std::vector<std::uint32_t>& of(std::size_t k) {
        const auto [it, fresh] = lists_.try_emplace(k);
        if (!fresh) return it->second;
        std::vector<std::uint32_t>& covered = it->second;
        // The grid's neighbourhood of a point reaches past the tolerance by
        // a quarter of it: samples that far apart find every drawing point
        // within the tolerance of a piece. Each cell is looked at once.
        const Primitive& p = chain_[k];
        const double len = geometry::length(p);
        // A piece may be metres long at a tolerance of micrometres: the
        // deadline is looked at while it is sampled, and before the search.
        const double steps = 1.0 + std::ceil(len / (0.25 * tolerance_));
        const std::size_t n = steps < 1e12 ? static_cast<std::size_t>(steps) : std::size_t(1e12);
        std::vector<Vec2> samples;
        for (std::size_t i = 0; i <= n; ++i) {
            if (i % 4096 == 0) watch_.now();
            samples.push_back(geometry::point_at(p, len * static_cast<double>(i) / n));
        }
        watch_.now();
        drawn_.around(samples, watch_, [&](std::uint32_t m) {
            if (piece_distance(p, drawn_.at(m)) <= tolerance_) covered.push_back(m);
        });
        return covered;
    }

    /// Gives up once the import's deadline has passed.
    void check_deadline() const { watch_.now(); }

private:
    const Drawn& drawn_;
    const std::vector<Primitive>& chain_;
    double tolerance_;
    const Watch& watch_;
    std::unordered_map<std::size_t, std::vector<std::uint32_t>> lists_;
};

/// The strokes beside the one being merged, each with a box round it: a
/// point of the drawing that a replaced piece passed near (where two
/// strokes of a letter meet) may lie just as near one of them, and stays
/// drawn. Boxes are measured again as each stroke is merged.
class OtherStrokes {
public:
    explicit OtherStrokes(const std::vector<std::vector<Primitive>>& strokes) : strokes_(strokes) {
        for (std::size_t s = 0; s < strokes.size(); ++s) boxes_.push_back(box(strokes[s]));
    }
    /// The stroke merged next, which is not one of the others.
    void merging(std::size_t s) { current_ = s; }
    /// Stroke s is as merged as it will be.
    void changed(std::size_t s) { boxes_[s] = box(strokes_[s]); }

    /// The distance from q to a piece of the other strokes that lies
    /// within `within` of it, or some distance past `within` when none
    /// does.
    double distance(const Vec2& q, double within) const {
        double best = std::numeric_limits<double>::infinity();
        for (std::size_t s = 0; s < strokes_.size(); ++s) {
            if (s == current_) continue;
            const Box& b = boxes_[s];
            if (q.x() < b.lo.x() - within || q.y() < b.lo.y() - within ||
                q.x() > b.hi.x() + within || q.y() > b.hi.y() + within)
                continue;
            best = std::min(best, distance_to(strokes_[s], q, within));
            if (best <= within) return best;
        }
        return best;
    }

private:
    struct Box {
        Vec2 lo, hi;
    };
    /// Holds every piece: an arc's circle bounds it.
    static Box box(const std::vector<Primitive>& stroke) {
        constexpr double inf = std::numeric_limits<double>::infinity();
        Box b{Vec2(inf, inf), Vec2(-inf, -inf)};
        const auto add = [&](const Vec2& lo, const Vec2& hi) {
            b.lo = b.lo.cwiseMin(lo);
            b.hi = b.hi.cwiseMax(hi);
        };
        for (const Primitive& p : stroke) {
            add(p.start.cwiseMin(p.end), p.start.cwiseMax(p.end));
            if (p.kind != PrimitiveKind::Line) {
                const Vec2 r(p.radius, p.radius);
                add(p.center - r, p.center + r);
            }
        }
        return b;
    }

    const std::vector<std::vector<Primitive>>& strokes_;
    std::vector<Box> boxes_;
    std::size_t current_ = std::size_t(-1);
};

/// How far the chain with chain[r.first..r.last] replaced by r.pieces
/// strays from the drawing there, both ways: the new pieces from the
/// drawing, and the drawing's points that the replaced pieces passed
/// within the tolerance of from the new pieces and their neighbours (four
/// each side), or, failing those, from the rest of the chain and the
/// `others` strokes. Up to `limit`, exact but for a point that only the
/// rest of the chain or another stroke keeps within it (some distance
/// within it, never too small); past it, some distance past it (the
/// search stops there). Distances up to `enough` are not told apart: with
/// `enough` at `limit`, the answer only says whether it is within the
/// limit, which is much quicker to find.
double strays(const Drawn& drawn, Covered& covered, const std::vector<Primitive>& chain,
              const Replacement& r, const OtherStrokes* others, double limit, double enough = 0.0) {
    double worst = 0.0;
    std::vector<Primitive> local(r.pieces);
    for (std::size_t k = r.first >= 4 ? r.first - 4 : 0; k < r.first; ++k)
        local.push_back(chain[k]);
    for (std::size_t k = r.last + 1; k < chain.size() && k <= r.last + 4; ++k)
        local.push_back(chain[k]);
    // A sample nearer than the worst so far changes nothing: the search
    // for its distance stops at the first part of the drawing that near.
    for (const Primitive& p : r.pieces) {
        const double len = geometry::length(p);
        for (const int i : kMiddleFirst) {
            worst = std::max(worst, drawn.distance(geometry::point_at(p, len * i / kSamples),
                                                   std::max(worst, enough)));
            if (worst > limit) return worst;
        }
    }
    // A point near several replaced pieces is measured once.
    const std::uint32_t pass = drawn.new_pass();
    std::size_t measured = 0, fallbacks = 0;
    for (std::size_t k = r.first; k <= r.last; ++k) {
        for (const std::uint32_t m : covered.of(k)) {
            if (!drawn.first_in(pass, m)) continue;
            if (++measured % 4096 == 0) covered.check_deadline();
            const Vec2& q = drawn.at(m);
            const double enough_here = std::max(worst, enough);
            double d = distance_to(local, q, enough_here);
            // Seldom, and looked for only where the point would refuse the
            // replacement: where the chain doubles back, or another stroke
            // meets it. Any part within the limit will do (the distance is
            // then some distance within it, never one too small).
            if (d > limit) {
                if (++fallbacks % 16 == 0) covered.check_deadline();
                for (std::size_t n = 0; n < chain.size() && d > limit; ++n) {
                    if (n + 4 >= r.first && n <= r.last + 4) continue;
                    d = std::min(d, piece_distance(chain[n], q));
                }
                if (others && d > limit) d = std::min(d, others->distance(q, limit));
            }
            worst = std::max(worst, d);
            if (worst > limit) return worst;
        }
    }
    return worst;
}

/// How far the points of `from` (on samples of each piece) lie from `to`.
double reach(const std::vector<Primitive>& from, const std::vector<Primitive>& to) {
    double worst = 0.0;
    for (const Primitive& p : from) {
        const double len = geometry::length(p);
        for (int i = 0; i <= kSamples; ++i)
            worst = std::max(worst, distance_to(to, geometry::point_at(p, len * i / kSamples)));
    }
    return worst;
}

/// Shorter than the tolerance: a circle too, which the fit makes of a
/// small loop inside a stroke.
bool is_short(const Primitive& p, double tolerance) { return geometry::length(p) < tolerance; }

/// Whether `fresh` may stand in a chain: no piece of no length or that
/// closes on itself, and none shorter than the tolerance unless it is the
/// whole stroke in one piece.
bool usable(const std::vector<Primitive>& fresh, double tolerance, bool whole) {
    for (const Primitive& q : fresh) {
        if (q.kind == PrimitiveKind::Circle || !(geometry::length(q) >= kMinPiece)) return false;
        if (geometry::length(q) < tolerance && !(whole && fresh.size() == 1)) return false;
    }
    return true;
}

/// Where the lines through a (direction da) and b (direction db) meet;
/// none when they are nearly parallel.
/// Whether the path turns back over chain[i..j] (a hairpin): it leaves
/// the run against the way it came in. Both neighbours must exist.
bool turns_back(const std::vector<Primitive>& chain, std::size_t i, std::size_t j) {
    return end_tangent(chain[i - 1]).dot(start_tangent(chain[j + 1])) < 0.0;
}

std::optional<Vec2> meet(const Vec2& a, const Vec2& da, const Vec2& b, const Vec2& db) {
    const double d = geometry::cross(da, db);
    if (std::abs(d) < 1e-9) return std::nullopt;
    return a + da * (geometry::cross(b - a, db) / d);
}

/// The replacements of the run of short pieces chain[i..j] (with, for
/// some, a window of a neighbour), each with how far it strays from what it
/// replaces unless `measure` is false (the caller measures them against
/// the drawing); the caller keeps the nearest within the tolerance.
std::vector<Replacement> run_candidates(const std::vector<Primitive>& chain, std::size_t i,
                                        std::size_t j, double tolerance, bool measure,
                                        std::optional<Vec2> drawn_tip = std::nullopt) {
    const auto far_apart = [&](const std::vector<Primitive>& a, const std::vector<Primitive>& b) {
        return measure ? apart(a, b) : 0.0;
    };
    const auto far_reach = [&](const std::vector<Primitive>& a, const std::vector<Primitive>& b) {
        return measure ? reach(a, b) : 0.0;
    };
    std::vector<Replacement> out;
    const std::size_t n = chain.size();
    const std::vector<Primitive> run(chain.begin() + i, chain.begin() + j + 1);
    const Vec2 from = run.front().start, to = run.back().end;
    const bool at_start = i == 0, at_end = j + 1 == n;
    // Dropped at a stroke's end: the stroke ends where its neighbour does
    // (a short line past a corner ends at the corner). What stays is part
    // of what was, so only the run's distance from it counts.
    if (at_end && !at_start) out.push_back({i, j, {}, far_reach(run, {chain[i - 1]})});
    if (at_start && !at_end) out.push_back({i, j, {}, far_reach(run, {chain[j + 1]})});
    // A closed feature smaller than the tolerance (a loop or a small
    // circle inside a stroke) collapses to the point it sits at.
    if (!at_start && !at_end && (to - from).norm() <= 1e-9) {
        double far = 0.0;
        for (const Primitive& p : measure ? run : std::vector<Primitive>{}) {
            const double len = geometry::length(p);
            for (int k = 0; k <= kSamples; ++k)
                far = std::max(far, (geometry::point_at(p, len * k / kSamples) - from).norm());
        }
        out.push_back({i, j, {}, far});
    }
    // One line over the whole run.
    if ((to - from).norm() >= kMinPiece) {
        const std::vector<Primitive> line{geometry::make_line(from, to)};
        if (usable(line, tolerance, at_start && at_end)) {
            out.push_back({i, j, line, far_apart(run, line)});
        }
    }
    // The neighbours' lines extended (or trimmed) to meet, the run dropped.
    if (!at_start && !at_end && chain[i - 1].kind == PrimitiveKind::Line &&
        chain[j + 1].kind == PrimitiveKind::Line) {
        const Primitive &a = chain[i - 1], &b = chain[j + 1];
        if (const auto x = meet(a.start, end_tangent(a), b.end, start_tangent(b))) {
            const std::vector<Primitive> fresh{geometry::make_line(a.start, *x),
                                               geometry::make_line(*x, b.end)};
            if (usable(fresh, tolerance, false)) {
                std::vector<Primitive> old = run;
                old.insert(old.begin(), a);
                old.push_back(b);
                out.push_back({i - 1, j + 1, fresh, far_apart(old, fresh)});
            }
        }
    }
    // Folded with a window of a neighbour into one piece that keeps the
    // neighbour's tangent at its far end (an arc, or a line when straight:
    // a neighbour extended or trimmed), or into one line.
    for (const double s : {tolerance, 2.0 * tolerance, 4.0 * tolerance}) {
        if (!at_start && chain[i - 1].kind != PrimitiveKind::Circle) {
            const Cut a = cut_end(chain[i - 1], s, tolerance);
            std::vector<Primitive> old = run;
            old.insert(old.begin(), a.window);
            const bool whole = !a.kept && i == 1 && at_end;
            for (const Primitive& q : {arc_through(a.window.start, start_tangent(a.window), to),
                                       geometry::make_line(a.window.start, to)}) {
                const std::vector<Primitive> fresh{q};
                if (!usable(fresh, tolerance, whole)) continue;
                Replacement r{i - 1, j, {}, far_apart(old, fresh)};
                if (a.kept) r.pieces.push_back(*a.kept);
                r.pieces.push_back(q);
                out.push_back(std::move(r));
            }
        }
        if (!at_end && chain[j + 1].kind != PrimitiveKind::Circle) {
            const Cut b = cut_start(chain[j + 1], s, tolerance);
            std::vector<Primitive> old = run;
            old.push_back(b.window);
            const bool whole = !b.kept && at_start && j + 2 == n;
            for (const Primitive& q : {arc_into(from, b.window.end, end_tangent(b.window)),
                                       geometry::make_line(from, b.window.end)}) {
                const std::vector<Primitive> fresh{q};
                if (!usable(fresh, tolerance, whole)) continue;
                Replacement r{i, j + 1, fresh, far_apart(old, fresh)};
                if (b.kept) r.pieces.push_back(*b.kept);
                out.push_back(std::move(r));
            }
        }
        if (!at_start && !at_end && chain[i - 1].kind != PrimitiveKind::Circle &&
            chain[j + 1].kind != PrimitiveKind::Circle) {
            const Cut a = cut_end(chain[i - 1], s, tolerance);
            const Cut b = cut_start(chain[j + 1], s, tolerance);
            std::vector<Primitive> old = run;
            old.insert(old.begin(), a.window);
            old.push_back(b.window);
            std::vector<std::vector<Primitive>> options{
                {geometry::make_line(a.window.start, b.window.end)}};
            if (auto arcs = biarc(a.window.start, start_tangent(a.window), b.window.end,
                                  end_tangent(b.window)))
                options.push_back(std::move(*arcs));
            // A turn back (a hairpin narrower than the tolerance) has no
            // smooth stand-in: the path goes to its tip and back, a cusp.
            if (turns_back(chain, i, j)) {
                const Vec2 mid = 0.5 * (from + to);
                Vec2 tip = from;
                for (const Primitive& p : run) {
                    const double len = geometry::length(p);
                    for (int k = 0; k <= kSamples; ++k) {
                        const Vec2 q = geometry::point_at(p, len * k / kSamples);
                        if ((q - mid).norm() > (tip - mid).norm()) tip = q;
                    }
                }
                // The fitting rounds a sharp tip within the tolerance, and
                // leaves nothing of it to cut the tip shorter: the cusp at
                // the drawing's own tip too, where it is known; its sides
                // straight, or bending as the neighbours do.
                for (const Vec2& t : drawn_tip ? std::vector{tip, *drawn_tip} : std::vector{tip}) {
                    options.push_back({geometry::make_line(a.window.start, t),
                                       geometry::make_line(t, b.window.end)});
                    options.push_back({arc_through(a.window.start, start_tangent(a.window), t),
                                       arc_into(t, b.window.end, end_tangent(b.window))});
                }
            }
            for (const auto& fresh : options) {
                if (!usable(fresh, tolerance, false)) continue;
                Replacement r{i - 1, j + 1, {}, far_apart(old, fresh)};
                if (a.kept) r.pieces.push_back(*a.kept);
                r.pieces.insert(r.pieces.end(), fresh.begin(), fresh.end());
                if (b.kept) r.pieces.push_back(*b.kept);
                out.push_back(std::move(r));
            }
        }
    }
    return out;
}

/// chain[i..k] for the largest k <= j (k > i) that one line or one arc
/// leaving chain[i] with its tangent replaces within the tolerance of the
/// drawing (or of the chain, beside `deviation`); `far` is that distance; none when no
/// such stretch reaches the tolerance's length. Stretches are tried in
/// order of length, up to the first that strays too far.
std::optional<Replacement> longest_stretch(const std::vector<Primitive>& chain, std::size_t i,
                                           std::size_t j, double tolerance, double deviation,
                                           const Drawn* drawn, Covered* covered,
                                           const OtherStrokes* others, Watch& watch) {
    std::optional<Replacement> best;
    const Vec2 from = chain[i].start;
    const Vec2 t = start_tangent(chain[i]);
    const bool whole_from_start = i == 0;
    for (std::size_t k = i + 1; k <= j; ++k) {
        const Vec2 to = chain[k].end;
        if (!((to - from).norm() >= kMinPiece)) continue;
        watch.tick();
        const bool whole = whole_from_start && k + 1 == chain.size();
        bool near = false;
        for (const Primitive& q : {geometry::make_line(from, to), arc_through(from, t, to)}) {
            const std::vector<Primitive> fresh{q};
            Replacement r{i, k, fresh, 0.0};
            // Against the drawing, only whether a stretch is within the
            // tolerance matters until the longest is known.
            if (drawn) {
                if (strays(*drawn, *covered, chain, r, others, tolerance, tolerance) > tolerance)
                    continue;
            } else {
                r.far =
                    deviation +
                    apart(std::vector<Primitive>(chain.begin() + i, chain.begin() + k + 1), fresh);
                if (r.far > tolerance) continue;
            }
            near = true;
            if (usable(fresh, tolerance, whole)) {
                best = std::move(r);
                break;
            }
        }
        if (!near) break;
    }
    if (best && drawn) best->far = strays(*drawn, *covered, chain, *best, others, tolerance);
    return best;
}

/// What merging piece by piece leaves: runs of short pieces (a small
/// rounded corner fitted as several slivers, a tiny loop, a short line
/// past a corner at a stroke's end), each replaced as a whole by the
/// nearest of run_candidates within what the tolerance leaves.
double merge_runs(std::vector<Primitive>& chain, double tolerance, double deviation,
                  const Drawn* drawn, Watch& watch, const OtherStrokes* others = nullptr) {
    double worst = deviation;
    double stroke_length = -1.0;  // measured when first needed, again after each change
    for (std::size_t i = 0; i < chain.size() && chain.size() > 1; ++i) {
        if (!is_short(chain[i], tolerance)) continue;
        std::size_t j = i;
        while (j + 1 < chain.size() && is_short(chain[j + 1], tolerance)) ++j;
        // A stroke that short as a whole may keep its pieces.
        if (stroke_length < 0.0) {
            stroke_length = 0.0;
            for (const Primitive& p : chain) stroke_length += geometry::length(p);
        }
        if (stroke_length < tolerance) return worst;
        std::optional<Replacement> best;
        std::optional<Covered> covered;
        if (drawn) covered.emplace(*drawn, chain, tolerance, watch);
        // A long run is a curve drawn in short pieces, which no one piece
        // over all of it follows: it goes straight to the stretches below.
        const bool long_run = j - i >= 8;
        // Where the run turns back, the drawing's point near it that lies
        // farthest out the way the path went in: the tip of the hairpin.
        // (Elsewhere its points near the run are found only if a candidate
        // comes that close.)
        std::optional<Vec2> drawn_tip;
        if (drawn && !long_run && i > 0 && j + 1 < chain.size() && turns_back(chain, i, j)) {
            const Vec2 out = end_tangent(chain[i - 1]) - start_tangent(chain[j + 1]);
            double farthest = -std::numeric_limits<double>::infinity();
            for (std::size_t k = i; k <= j; ++k) {
                for (const std::uint32_t m : covered->of(k)) {
                    if (const double along = drawn->at(m).dot(out); along > farthest) {
                        farthest = along;
                        drawn_tip = drawn->at(m);
                    }
                }
            }
        }
        for (Replacement& r : long_run
                                  ? std::vector<Replacement>{}
                                  : run_candidates(chain, i, j, tolerance, !drawn, drawn_tip)) {
            watch.tick();
            // Measured against the drawing itself where it is at hand: the
            // fitting leaves little of the tolerance to add to. Only one
            // nearer than the best so far is kept: the search stops past it.
            if (drawn)
                r.far = strays(*drawn, *covered, chain, r, others,
                               best ? std::min(tolerance, best->far) : tolerance);
            else
                r.far += deviation;
            if (r.far <= tolerance && (!best || r.far < best->far)) best = std::move(r);
        }
        // A run that no one piece replaces (a curve drawn as a polyline of
        // short lines) is replaced from its start by the longest stretch
        // one line, or one arc leaving as it did, stays close to.
        if (!best)
            best = longest_stretch(chain, i, j, tolerance, deviation, drawn,
                                   covered ? &*covered : nullptr, others, watch);
        // Else the rest of the run may still be replaced from its next piece.
        if (!best) continue;
        worst = std::max(worst, best->far);
        chain.erase(chain.begin() + best->first, chain.begin() + best->last + 1);
        chain.insert(chain.begin() + best->first, best->pieces.begin(), best->pieces.end());
        stroke_length = -1.0;
        // The short pieces just before were a longer run than what is left
        // of it, and may now be replaced: look again from its start.
        std::size_t back = best->first;
        while (back > 0 && is_short(chain[back - 1], tolerance)) --back;
        i = back == 0 ? std::size_t(-1) : back - 1;
    }
    return worst;
}

}  // namespace

double merge_slivers(std::vector<Primitive>& chain, double tolerance, double deviation,
                     std::span<const Curve> drawing, Clock::time_point deadline) {
    const auto any_short = [&] {
        return chain.size() > 1 && std::any_of(chain.begin(), chain.end(), [&](const Primitive& p) {
                   return is_short(p, tolerance);
               });
    };
    if (!any_short()) return deviation;
    Watch watch(deadline, "merging pieces shorter than the tolerance in " +
                              (drawing.empty() ? std::string("a curve") : drawing.front().source));
    std::optional<Drawn> drawn;
    if (!drawing.empty()) drawn.emplace(drawing, tolerance, watch);
    // Whole runs first, where a closed one is still whole (a small loop
    // that merging piece by piece would leave open).
    double worst = drawn ? merge_runs(chain, tolerance, deviation, &*drawn, watch) : deviation;
    for (std::size_t i = 0; i < chain.size() && chain.size() > 1; ++i) {
        const Primitive& p = chain[i];
        if (p.kind == PrimitiveKind::Circle || geometry::length(p) >= tolerance) continue;
        const bool prev = i > 0 && chain[i - 1].kind != PrimitiveKind::Circle;
        const bool next = i + 1 < chain.size() && chain[i + 1].kind != PrimitiveKind::Circle;
        // Keep tangent continuity where the chain has it: fold the sliver
        // into a neighbour only across a corner (or a stroke's end).
        const bool smooth_in = i > 0 && smooth(chain[i - 1], p);
        const bool smooth_out = i + 1 < chain.size() && smooth(p, chain[i + 1]);
        std::vector<Merge> ways;
        if (prev && !smooth_out) ways.push_back(Merge::IntoPrevious);
        if (next && !smooth_in) ways.push_back(Merge::IntoNext);
        if (prev && next) ways.push_back(Merge::Both);
        std::optional<Replacement> best;
        for (const Merge how : ways) {
            for (const double s : {tolerance, 2.0 * tolerance, 4.0 * tolerance}) {
                watch.tick();
                auto r = candidate(chain, i, how, s, tolerance);
                if (r && deviation + r->far <= tolerance) {
                    best = std::move(r);
                    break;
                }
            }
            if (best) break;
        }
        if (!best) continue;
        worst = std::max(worst, deviation + best->far);
        chain.erase(chain.begin() + best->first, chain.begin() + best->last + 1);
        chain.insert(chain.begin() + best->first, best->pieces.begin(), best->pieces.end());
        i = best->first + best->pieces.size() - 1;
    }
    worst = merge_runs(chain, tolerance, worst, drawn ? &*drawn : nullptr, watch);
    // A closed curve's first and last pieces are neighbours, though the
    // chain's ends part them: a short one left there is merged with the
    // chain started half way round, where it lies inside.
    const bool closed = chain.size() > 2 && (chain.back().end - chain.front().start).norm() <= 1e-9;
    if (closed && (is_short(chain.front(), tolerance) || is_short(chain.back(), tolerance))) {
        std::rotate(chain.begin(), chain.begin() + chain.size() / 2, chain.end());
        worst = merge_runs(chain, tolerance, worst, drawn ? &*drawn : nullptr, watch);
    }
    return worst;
}

double merge_stroke_slivers(std::vector<std::vector<Primitive>>& strokes, double tolerance,
                            double deviation, std::span<const Curve> drawing,
                            Clock::time_point deadline) {
    double worst = deviation;
    std::optional<Drawn> drawn;
    Watch watch(deadline, "merging pieces shorter than the tolerance where curves join");
    std::optional<OtherStrokes> others;
    for (std::size_t s = 0; s < strokes.size(); ++s) {
        std::vector<Primitive>& stroke = strokes[s];
        if (stroke.size() < 2 ||
            std::none_of(stroke.begin(), stroke.end(),
                         [&](const Primitive& p) { return is_short(p, tolerance); }))
            continue;
        if (!drawn) drawn.emplace(drawing, tolerance, watch);
        if (!others) others.emplace(strokes);
        others->merging(s);
        worst = std::max(worst, merge_runs(stroke, tolerance, deviation, &*drawn, watch, &*others));
        others->changed(s);
    }
    return worst;
}

}  // namespace modsynth::drawing
