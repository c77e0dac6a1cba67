#include <modsynth/drawing/stroke_order.h>

#include <algorithm>
#include <cstddef>
#include <limits>

#include <modsynth/drawing/biarc_fit.h>

namespace modsynth::drawing {

namespace {

using geometry::Vec2;

/// Beyond this many chains 2-opt (quadratic per pass) is skipped; the
/// greedy order alone is kept.
constexpr std::size_t kMaxTwoOpt = 1000;
constexpr int kMaxPasses = 50;
/// Chains moved by 2-opt's reversals, in all: each pass compares at most
/// kMaxTwoOpt^2 / 2 pairs, but every improvement found reverses a run, so
/// the moves are capped too (the same for every run: the order stays
/// repeatable).
constexpr std::size_t kMaxMoves = 50'000'000;

Chain reversed_chain(const Chain& c) {
    Chain out;
    out.reserve(c.size());
    for (auto it = c.rbegin(); it != c.rend(); ++it) out.push_back(reversed(*it));
    return out;
}

struct Visit {
    std::size_t chain;
    bool flipped;
};

struct Ends {
    Vec2 start, end;
};

}  // namespace

double travel_length(const std::vector<Chain>& chains) {
    double total = 0.0;
    for (std::size_t i = 0; i + 1 < chains.size(); ++i) {
        total += (chains[i + 1].front().start - chains[i].back().end).norm();
    }
    return total;
}

StrokeOrder order_strokes(std::vector<Chain> chains, bool keep_order) {
    std::vector<Chain> ordered;
    if (keep_order || chains.size() <= 1) {
        ordered = std::move(chains);
    } else {
        const std::size_t n = chains.size();
        std::vector<Ends> ends(n);
        for (std::size_t i = 0; i < n; ++i)
            ends[i] = {chains[i].front().start, chains[i].back().end};
        auto start_of = [&](const Visit& v) {
            return v.flipped ? ends[v.chain].end : ends[v.chain].start;
        };
        auto end_of = [&](const Visit& v) {
            return v.flipped ? ends[v.chain].start : ends[v.chain].end;
        };
        // Greedy: from the first chain, always on to the nearest free end.
        std::vector<Visit> tour{{0, false}};
        std::vector<bool> used(n, false);
        used[0] = true;
        for (std::size_t k = 1; k < n; ++k) {
            const Vec2 at = end_of(tour.back());
            Visit best{0, false};
            double best_d = std::numeric_limits<double>::infinity();
            for (std::size_t i = 0; i < n; ++i) {
                if (used[i]) continue;
                const double ds = (ends[i].start - at).norm(), de = (ends[i].end - at).norm();
                if (ds < best_d) best_d = ds, best = {i, false};
                if (de < best_d) best_d = de, best = {i, true};
            }
            used[best.chain] = true;
            tour.push_back(best);
        }
        // 2-opt: reversing the run i..j (order and directions) replaces the
        // gaps before i and after j; keep it when shorter.
        if (n <= kMaxTwoOpt) {
            std::size_t moves = 0;
            for (int pass = 0; pass < kMaxPasses && moves < kMaxMoves; ++pass) {
                bool improved = false;
                for (std::size_t i = 1; i < n; ++i) {
                    for (std::size_t j = i; j < n; ++j) {
                        const Vec2 before = end_of(tour[i - 1]);
                        const double old_gap =
                            (start_of(tour[i]) - before).norm() +
                            (j + 1 < n ? (start_of(tour[j + 1]) - end_of(tour[j])).norm() : 0.0);
                        const double new_gap =
                            (end_of(tour[j]) - before).norm() +
                            (j + 1 < n ? (start_of(tour[j + 1]) - start_of(tour[i])).norm() : 0.0);
                        if (new_gap < old_gap - 1e-12 && moves < kMaxMoves) {
                            moves += j + 1 - i;
                            std::reverse(tour.begin() + i, tour.begin() + j + 1);
                            for (std::size_t k = i; k <= j; ++k) tour[k].flipped = !tour[k].flipped;
                            improved = true;
                        }
                    }
                }
                if (!improved) break;
            }
        }
        for (const Visit& v : tour) {
            ordered.push_back(v.flipped ? reversed_chain(chains[v.chain])
                                        : std::move(chains[v.chain]));
        }
    }
    StrokeOrder out;
    for (Chain& c : ordered) {
        if (!out.strokes.empty() &&
            (c.front().start - out.strokes.back().back().end).norm() <= kTouching) {
            out.strokes.back().insert(out.strokes.back().end(), c.begin(), c.end());
        } else {
            out.strokes.push_back(std::move(c));
        }
    }
    out.travel = travel_length(out.strokes);
    return out;
}

}  // namespace modsynth::drawing
