#include "dxf_hatch.h"

#include <algorithm>
#include <cmath>
#include <set>

#include <modsynth/drawing/drawing.h>
#include <modsynth/text/printable.h>

#include "elliptic_arc.h"

namespace modsynth::drawing {

namespace {

constexpr double kDegree = geometry::kPi / 180.0;

/// The groups a boundary path may hold (DXF reference, "Boundary path
/// data"): the first other group ends the paths (the hatch style, 75, always
/// follows them), so that the seed points (10/20 after 98) are never read
/// as vertices.
const std::set<int> kPolylineCodes = {72, 73, 93, 10, 20, 42, 97, 330};
const std::set<int> kEdgeCodes = {93, 72, 10, 20, 11, 21, 40, 42, 50, 51, 73,
                                  74, 94, 95, 96, 97, 12, 22, 13, 23, 330};

/// An angle difference as a sweep in (0, turn]: 0 is a whole turn, as an
/// ARC's equal angles are.
double within_turn(double difference, double turn) {
    const double sweep = std::fmod(difference, turn);
    return sweep > 0.0 ? sweep : sweep + turn;
}

/// The ellipse's parameter at a true angle from its major axis (the hatch
/// edge stores angles, the ELLIPSE entity parameters), on the same turn as
/// the angle so that a sweep keeps its length.
double parameter_at(double angle, double ratio) {
    if (ratio == 1.0) return angle;
    const double t = std::atan2(std::sin(angle) / ratio, std::cos(angle));
    return t + geometry::kTau * std::round((angle - t) / geometry::kTau);
}

/// An arc or elliptic arc edge: counter-clockwise from 50 to 51; a
/// clockwise one (73 = 0) stores its angles as 360 minus the true ones, so
/// it runs clockwise from -50 by the same sweep.
EllipticArc arc_edge(const Vec2& center, const Vec2& u, const Vec2& v, double ratio, double start,
                     double end, bool ccw) {
    const double sweep = within_turn(end - start, 360.0) * kDegree;
    const double from = (ccw ? start : -start) * kDegree;
    const double to = ccw ? from + sweep : from - sweep;
    return EllipticArc{center, u, v, parameter_at(from, ratio), parameter_at(to, ratio)};
}

}  // namespace

std::string HatchReader::where(std::size_t path, std::size_t line) const {
    return "boundary path " + std::to_string(path) + " (line " + std::to_string(line) + ")";
}

void HatchReader::fail(const std::string& problem) {
    if (out_.problem.empty()) out_.problem = problem;
}

void HatchReader::text(int code, const std::string& value) {
    if (code == 8 && phase_ == Phase::Header) out_.layer = value;
}

void HatchReader::number(int code, double value, std::size_t line) {
    if (code == 230) {
        mirrored_ = value < 0.0;
        return;
    }
    if (phase_ == Phase::Header) {
        if (code == 91) {
            declared_paths_ = static_cast<long long>(value);
            phase_ = *declared_paths_ > 0 ? Phase::Paths : Phase::After;
        }
        return;
    }
    if (phase_ == Phase::After) return;
    if (code == 92) {
        end_path();
        ++paths_;
        path_ = Path{};
        path_->polyline = (static_cast<long long>(value) & 2) != 0;
        path_->line = line;
        return;
    }
    if (!path_ || !(path_->polyline ? kPolylineCodes : kEdgeCodes).count(code)) {
        end_path();
        phase_ = Phase::After;
        return;
    }
    Path& p = *path_;
    if (p.polyline) {
        switch (code) {
            case 93:
                p.declared = static_cast<long long>(value);
                break;
            case 10:
                p.vertices.push_back({Vec2(value, 0.0), 0.0});
                break;
            case 20:
                if (!p.vertices.empty()) p.vertices.back().p.y() = value;
                break;
            case 42:
                if (!p.vertices.empty()) p.vertices.back().bulge = value;
                break;
            default:  // has-bulge (72) and closed (73) flags: a boundary is closed
                break;
        }
        return;
    }
    if (code == 72) {
        p.edges.push_back(Edge{});
        p.edges.back().type = static_cast<int>(value);
        p.edges.back().line = line;
        return;
    }
    if (code == 93 && p.edges.empty()) {
        p.declared = static_cast<long long>(value);
        return;
    }
    if (p.edges.empty()) return;
    Edge& e = p.edges.back();
    const bool spline = e.type == 4;
    switch (code) {
        case 10:
            if (spline) {
                e.control.push_back(Vec2(value, 0.0));
            } else {
                e.p10.x() = value;
            }
            break;
        case 20:
            if (spline) {
                if (!e.control.empty()) e.control.back().y() = value;
            } else {
                e.p10.y() = value;
            }
            break;
        case 11:
            if (spline) {
                ++e.fit_points;
            } else {
                e.p11.x() = value;
            }
            break;
        case 21:
            if (!spline) e.p11.y() = value;
            break;
        case 40:
            if (spline) {
                e.knots.push_back(value);
            } else {
                e.g40 = value;
            }
            break;
        case 42:
            if (spline) e.weights.push_back(value);
            break;
        case 50:
            e.g50 = value;
            break;
        case 51:
            e.g51 = value;
            break;
        case 73:
            if (!spline) e.ccw = value != 0.0;
            break;
        case 94:
            e.degree = static_cast<int>(value);
            break;
        case 95:
            e.declared_knots = static_cast<long long>(value);
            break;
        case 96:
            e.declared_control = static_cast<long long>(value);
            break;
        default:  // periodic (74), fit count (97), tangents, source handles
            break;
    }
}

void HatchReader::end_path() {
    if (!path_) return;
    Path p = std::move(*path_);
    path_.reset();
    const std::size_t index = paths_;
    std::vector<Segment> loop;
    if (p.polyline) {
        const std::size_t n = p.vertices.size();
        if (p.declared && *p.declared != static_cast<long long>(n)) {
            fail(where(index, p.line) + ": group code 93 declares " + std::to_string(*p.declared) +
                 " vertices, but " + std::to_string(n) + " follow");
            return;
        }
        // A boundary encloses its area: the last vertex joins the first
        // whether or not the closed flag says so (a writer that repeats the
        // first vertex adds a closing piece of no length, left out below).
        for (std::size_t i = 0; n >= 2 && i < n; ++i) {
            const Vertex& a = p.vertices[i];
            const Vec2 b = p.vertices[(i + 1) % n].p;
            if (!std::isfinite(a.bulge) || std::abs(a.bulge) > 1e6) {
                fail(where(index, p.line) + ": bulge out of range at vertex " + std::to_string(i));
                return;
            }
            if (const auto arc = arc_from_bulge(a.p, b, a.bulge)) {
                loop.push_back(*arc);
            } else {
                loop.push_back(LineSegment{a.p, b});
            }
        }
    } else {
        if (p.declared && *p.declared != static_cast<long long>(p.edges.size())) {
            fail(where(index, p.line) + ": group code 93 declares " + std::to_string(*p.declared) +
                 " edges, but " + std::to_string(p.edges.size()) + " follow");
            return;
        }
        for (std::size_t k = 0; k < p.edges.size(); ++k) {
            const Edge& e = p.edges[k];
            const std::string edge = "boundary path " + std::to_string(index) + ", edge " +
                                     std::to_string(k + 1) + " (line " + std::to_string(e.line) +
                                     ")";
            switch (e.type) {
                case 1:
                    loop.push_back(LineSegment{e.p10, e.p11});
                    break;
                case 2:
                    if (e.g40 == 0.0) break;  // a point: its neighbours meet there
                    if (!(e.g40 > 0.0)) {
                        fail(edge + ": radius " + text::compact(e.g40) + ": it must be positive");
                        return;
                    }
                    loop.push_back(arc_edge(e.p10, Vec2(e.g40, 0.0), Vec2(0.0, e.g40), 1.0, e.g50,
                                            e.g51, e.ccw));
                    break;
                case 3:
                    if (!(e.g40 > 0.0) || e.p11.norm() == 0.0) {
                        fail(edge + ": an ellipse needs a major axis and a positive axis ratio");
                        return;
                    }
                    loop.push_back(arc_edge(e.p10, e.p11, e.g40 * geometry::perp(e.p11), e.g40,
                                            e.g50, e.g51, e.ccw));
                    break;
                case 4: {
                    if (e.control.empty()) {
                        out_.left_out.push_back(edge + ": a spline given by fit points only");
                        break;
                    }
                    const auto bad = [&](const std::string& why) { fail(edge + ": " + why); };
                    if (e.degree < 1 || e.degree > kMaxSplineDegree) {
                        bad("degree " + std::to_string(e.degree) + " is outside 1.." +
                            std::to_string(kMaxSplineDegree));
                        return;
                    }
                    const std::size_t n = e.control.size();
                    if ((e.declared_control && *e.declared_control != static_cast<long long>(n)) ||
                        (e.declared_knots &&
                         *e.declared_knots != static_cast<long long>(e.knots.size()))) {
                        bad("the knots and control points do not match their counts (95, 96)");
                        return;
                    }
                    if (n < static_cast<std::size_t>(e.degree) + 1) {
                        bad("fewer control points than degree + 1");
                        return;
                    }
                    if (e.knots.size() != n + e.degree + 1) {
                        bad(std::to_string(e.knots.size()) + " knots, expected " +
                            std::to_string(n + e.degree + 1));
                        return;
                    }
                    if (!std::is_sorted(e.knots.begin(), e.knots.end()) ||
                        !(e.knots[n] > e.knots[e.degree])) {
                        bad("knots must be non-decreasing over a range of some length");
                        return;
                    }
                    std::vector<double> weights = e.weights;
                    if (weights.empty()) weights.assign(n, 1.0);
                    if (weights.size() != n || !std::all_of(weights.begin(), weights.end(),
                                                            [](double w) { return w > 0.0; })) {
                        bad("one positive weight per control point, or none");
                        return;
                    }
                    loop.push_back(BSpline{e.degree, e.knots, e.control, weights});
                    break;
                }
                default:
                    fail(edge + ": edge type " + std::to_string(e.type) +
                         " (1 line, 2 arc, 3 elliptic arc, 4 spline)");
                    return;
            }
        }
    }
    // Runs split where one edge does not start where the last one ended
    // (within what the file's digits hold): the pen lifts there.
    double reach = 1.0;
    for (const Segment& s : loop) {
        reach = std::max(
            {reach, start_point(s).cwiseAbs().maxCoeff(), end_point(s).cwiseAbs().maxCoeff()});
    }
    const double gap = 1e-9 * reach;
    Affine mirror;
    mirror.m << -1.0, 0.0, 0.0, 1.0;
    for (const Segment& s : loop) {
        if (start_point(s) == end_point(s) && approximate_length(s, 8) == 0.0) continue;
        const Segment placed = mirrored_ ? transformed(s, mirror) : s;
        if (out_.runs.empty() || out_.runs.back().path != index ||
            (start_point(placed) - end_point(out_.runs.back().segments.back())).norm() > gap) {
            out_.runs.push_back({index, {}});
        }
        out_.runs.back().segments.push_back(placed);
    }
}

HatchBoundary HatchReader::finish() {
    end_path();
    if (declared_paths_ && out_.problem.empty() &&
        *declared_paths_ != static_cast<long long>(paths_)) {
        fail("group code 91 declares " + std::to_string(*declared_paths_) +
             " boundary paths, but " + std::to_string(paths_) + " follow");
    }
    if (!out_.problem.empty()) out_.runs.clear();
    return std::move(out_);
}

}  // namespace modsynth::drawing
