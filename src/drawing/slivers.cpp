#include <modsynth/drawing/slivers.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <modsynth/drawing/biarc_fit.h>

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

double distance_to(const std::vector<Primitive>& ps, const Vec2& q) {
    double best = std::numeric_limits<double>::infinity();
    for (const Primitive& p : ps) best = std::min(best, geometry::nearest(p, q).distance);
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

}  // namespace

double merge_slivers(std::vector<Primitive>& chain, double tolerance, double deviation) {
    double worst = deviation;
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
    return worst;
}

}  // namespace modsynth::drawing
