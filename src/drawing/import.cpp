#include <modsynth/drawing/import.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <optional>

#include <Eigen/LU>

#include <modsynth/drawing/biarc_fit.h>
#include <modsynth/drawing/dxf_reader.h>
#include <modsynth/drawing/slivers.h>
#include <modsynth/drawing/svg_reader.h>
#include <modsynth/geometry/distance.h>
#include <modsynth/task/input_error.h>
#include <modsynth/task/limits.h>
#include <modsynth/text/printable.h>

namespace modsynth::drawing {

namespace {

using task::InputError;

struct Box {
    Vec2 min = Vec2::Constant(std::numeric_limits<double>::infinity());
    Vec2 max = Vec2::Constant(-std::numeric_limits<double>::infinity());
    void add(const Vec2& p) {
        min = min.cwiseMin(p);
        max = max.cwiseMax(p);
    }
};

Box bounding_box(const Drawing& d) {
    Box b;
    for (const Curve& c : d.curves) {
        for (const Segment& s : c.segments) {
            for (int i = 0; i <= 32; ++i) b.add(point(s, i / 32.0));
        }
    }
    return b;
}

/// The larger side of the curve's bounding box (sampled).
double size_across(const Curve& c) {
    Box b;
    for (const Segment& s : c.segments) {
        for (int i = 0; i <= 32; ++i) b.add(point(s, i / 32.0));
    }
    return (b.max - b.min).maxCoeff();
}

/// A line shorter than the tolerance (a path optimiser's leftover of a few
/// micrometres) is folded into the line next to it when every corner the
/// longer line leaves out stays within what the tolerance leaves beside
/// `deviation`: lines deviate by their corners only. Returns the deviation
/// after folding. A chain of one primitive (a stroke that short) is kept.
double fold_short_lines(std::vector<geometry::Primitive>& chain, double tolerance,
                        double deviation) {
    using geometry::PrimitiveKind;
    if (chain.size() < 2) return deviation;
    std::vector<geometry::Primitive> out;
    std::vector<Vec2> corners;  // those the last line of `out` leaves out
    double worst = deviation;
    for (const geometry::Primitive& p : chain) {
        if (!out.empty() && out.back().kind == PrimitiveKind::Line &&
            p.kind == PrimitiveKind::Line &&
            (geometry::length(out.back()) < tolerance || geometry::length(p) < tolerance) &&
            (p.end - out.back().start).norm() >= tolerance) {
            const geometry::Primitive joined = geometry::make_line(out.back().start, p.end);
            double far = geometry::point_segment(p.start, joined.start, joined.end);
            for (const Vec2& c : corners)
                far = std::max(far, geometry::point_segment(c, joined.start, joined.end));
            if (deviation + far <= tolerance) {
                out.back() = joined;
                corners.push_back(p.start);
                worst = std::max(worst, deviation + far);
                continue;
            }
        }
        out.push_back(p);
        corners.clear();
    }
    chain = std::move(out);
    return worst;
}

/// Primitives the drawable curves need at `tolerance`; more than the cap
/// when past it (counting stops there), none when some curve cannot be
/// followed at it.
std::optional<std::size_t> primitives_needed(const std::vector<Curve>& placed, double tolerance,
                                             Clock::time_point deadline) {
    std::size_t total = 0;
    for (const Curve& c : placed) {
        if (!(size_across(c) >= kMinPiece)) continue;
        try {
            FittedCurve f = fit_curve(c, tolerance, task::kMaxPrimitives, deadline);
            merge_slivers(f.primitives, tolerance,
                          fold_short_lines(f.primitives, tolerance, f.deviation), {&c, 1},
                          deadline);
            total += f.primitives.size();
        } catch (const InputError&) {
            return std::nullopt;
        }
        if (total > task::kMaxPrimitives) break;
    }
    return total;
}

/// The drawing needs `needed` primitives, more than a task may hold: says
/// so, with the least tolerance (doubling from this one, up to 1 mm
/// times 16) at which it fits, when one does within the time left.
[[noreturn]] void too_many(const std::vector<Curve>& placed, std::size_t needed,
                           const ImportOptions& options) {
    std::string fits;
    double t = 2.0 * options.tolerance;
    try {
        for (; t <= 0.016 && fits.empty(); t *= 2.0) {
            const auto n = primitives_needed(placed, t, options.deadline);
            if (n && *n <= task::kMaxPrimitives) {
                fits = ": --tolerance " + text::compact(t) + " fits it (" + std::to_string(*n) +
                       " primitives), or simplify the drawing";
            }
        }
    } catch (const ImportTimeout&) {
        fits = ": simplify it (the time limit ended the search for a tolerance that fits at " +
               text::compact(t) + " m)";
    }
    // Lines need as many primitives at any tolerance.
    if (fits.empty()) fits = ": simplify it (no --tolerance up to 0.016 m was found to fit)";
    throw InputError("(document)",
                     "the drawing needs " + std::to_string(needed) + " primitives at --tolerance " +
                         text::compact(options.tolerance) + " m, more than the " +
                         std::to_string(task::kMaxPrimitives) + " a task may hold" + fits);
}

}  // namespace

DrawingFormat format_of(const std::string& path) {
    std::string ext = path.size() >= 4 ? path.substr(path.size() - 4) : "";
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    if (ext == ".svg") return DrawingFormat::Svg;
    if (ext == ".dxf") return DrawingFormat::Dxf;
    throw InputError(path, "not a drawing: expected a .svg or .dxf file");
}

Affine placement_map(const Drawing& drawing, const Placement& placement) {
    const Box box = bounding_box(drawing);
    double scale = drawing.metres_per_unit;
    if (placement.scale) {
        scale = *placement.scale;
    } else if (placement.width) {
        const double w = box.max.x() - box.min.x();
        if (!(w > 0.0)) throw InputError("--width", "the drawing has no width to scale");
        scale = *placement.width / w;
    }
    if (!(scale > 0.0) || !std::isfinite(scale)) {
        throw InputError("--scale", "the file does not state its units: give --scale or --width");
    }
    const double a = placement.rotate_degrees * geometry::kPi / 180.0;
    Eigen::Matrix2d rotation;
    rotation << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
    Affine map;
    map.m = scale * rotation;
    if (placement.at) {
        const Vec2 centre = (box.min + box.max) / 2.0;
        map.offset = *placement.at - map.m * centre;
    }
    return map;
}

ImportResult import_drawing(std::string_view text, DrawingFormat format,
                            const ImportOptions& options) {
    if (!(options.tolerance > 0.0) || !std::isfinite(options.tolerance)) {
        throw InputError("--tolerance", "must be a positive number of metres");
    }
    // The reading counts against the import's time too.
    ReadOptions read = options.read;
    read.deadline = options.deadline;
    const Drawing drawing =
        format == DrawingFormat::Svg ? read_svg(text, read) : read_dxf(text, read);
    check_deadline(options.deadline, "reading the drawing");
    return import_drawing(drawing, options);
}

ImportResult import_drawing(const Drawing& drawing, const ImportOptions& options) {
    if (!(options.tolerance > 0.0) || !std::isfinite(options.tolerance)) {
        throw InputError("--tolerance", "must be a positive number of metres");
    }
    const Affine map = placement_map(drawing, options.placement);
    ImportResult result;
    result.warnings = drawing.warnings;
    result.layers = drawing.layers;
    result.filled_outlines = drawing.filled_outlines;
    result.placement = map;
    result.page_size = drawing.page_size;
    result.page_to_task = map.after(drawing.page_to_units);
    result.metres_per_unit =
        std::abs(map.m.determinant()) > 0.0 ? std::sqrt(std::abs(map.m.determinant())) : 0.0;
    auto check = [](const Vec2& p, const std::string& source) {
        if (!(p.cwiseAbs().maxCoeff() <= task::kMaxCoordinate)) {
            throw InputError(source,
                             "lies beyond " + std::to_string(int(task::kMaxCoordinate)) +
                                 " m of the origin once placed: check --width, --scale, --at");
        }
    };
    std::vector<Curve> all_placed;
    std::size_t drawable = 0;
    for (const Curve& c : drawing.curves) {
        Curve placed{c.source, {}};
        for (const Segment& s : c.segments) {
            placed.segments.push_back(transformed(s, map));
            check(start_point(placed.segments.back()), c.source);
            check(end_point(placed.segments.back()), c.source);
        }
        if (size_across(placed) >= kMinPiece) ++drawable;
        all_placed.push_back(std::move(placed));
    }
    // A curve smaller than the fitting resolves (an ellipse of 1e-15 m, a
    // CAD program's leftover) among others is a degenerate piece: skipped
    // with a warning. A drawing made only of such curves is refused by the
    // fitting (a --scale far too small).
    std::vector<std::string> tiny;
    std::size_t tiny_count = 0;
    std::vector<std::string> dots;
    std::size_t dot_count = 0;
    std::vector<Chain> chains;
    std::size_t total = 0;
    for (Curve& placed : all_placed) {
        const Curve& c = placed;
        if (drawable > 0 && !(size_across(placed) >= kMinPiece)) {
            if (options.read.strict) {
                throw InputError(c.source, "less than " + text::compact(kMinPiece) +
                                               " m across once placed (--strict)");
            }
            if (tiny.size() < 3) tiny.push_back(c.source);
            ++tiny_count;
            continue;
        }
        // Past the cap the rest is still fitted, to say what the whole
        // drawing needs.
        FittedCurve f =
            fit_curve(placed, options.tolerance, task::kMaxPrimitives, options.deadline);
        if (f.dot) {
            if (options.read.strict) {
                throw InputError(c.source,
                                 "a dot: it stays within the tolerance of a point "
                                 "(--strict)");
            }
            if (dots.size() < 3) dots.push_back(c.source);
            ++dot_count;
            continue;
        }
        // An arc so nearly straight that its centre lies beyond reach of
        // any task is its chord, when the chord strays from it (by its
        // sagitta) within what the tolerance leaves.
        double straightened = 0.0;
        for (geometry::Primitive& p : f.primitives) {
            if (p.kind == geometry::PrimitiveKind::Arc &&
                !(p.center.cwiseAbs().maxCoeff() <= task::kMaxCoordinate) &&
                std::abs(p.sweep) < geometry::kPi) {
                const double sagitta = p.radius * (1.0 - std::cos(p.sweep / 2.0));
                if (f.deviation + sagitta <= options.tolerance) {
                    p = geometry::make_line(p.start, p.end);
                    straightened = std::max(straightened, sagitta);
                }
            }
            check(p.center, c.source + " (an arc's center)");
        }
        f.deviation += straightened;
        f.deviation = fold_short_lines(f.primitives, options.tolerance, f.deviation);
        // What is still shorter than the tolerance (an arc between arcs, a
        // line between arcs) is merged into its neighbours.
        f.deviation = merge_slivers(f.primitives, options.tolerance, f.deviation, {&placed, 1},
                                    options.deadline);
        total += f.primitives.size();
        if (total > task::kMaxPrimitives) continue;
        result.deviation = std::max(result.deviation, f.deviation);
        chains.push_back(std::move(f.primitives));
    }
    if (total > task::kMaxPrimitives) too_many(all_placed, total, options);
    if (tiny_count > 0) {
        std::string list;
        for (const std::string& t : tiny) list += (list.empty() ? "" : ", ") + t;
        if (tiny_count > tiny.size())
            list += " and " + std::to_string(tiny_count - tiny.size()) + " more";
        result.warnings.push_back("skipped pieces less than " + text::compact(kMinPiece) +
                                  " m across once placed: " + list);
    }
    if (dot_count > 0) {
        std::string list;
        for (const std::string& t : dots) list += (list.empty() ? "" : ", ") + t;
        if (dot_count > dots.size())
            list += " and " + std::to_string(dot_count - dots.size()) + " more";
        result.warnings.push_back(
            "skipped dots (curves within the tolerance of a point, which a "
            "stroke cannot draw): " +
            list);
    }
    for (const geometry::Disc& d : drawing.obstacles) {
        const geometry::Disc placed{map(d.center), d.radius * result.metres_per_unit};
        check(placed.center, "obstacle");
        result.obstacles.push_back(placed);
    }
    if (chains.empty()) {
        throw InputError("(document)",
                         "empty drawing: nothing to draw" +
                             (result.warnings.empty() ? "" : " (" + result.warnings.back() + ")"));
    }
    StrokeOrder order = order_strokes(std::move(chains), options.keep_order);
    // Strokes joined from curves end to end (a CAD polyline written as
    // LINE entities) may run through pieces shorter than the tolerance
    // that no one curve held: merged now, against the whole drawing.
    std::size_t pieces = 0;
    for (const Chain& stroke : order.strokes) pieces += stroke.size();
    result.deviation = merge_stroke_slivers(order.strokes, options.tolerance, result.deviation,
                                            all_placed, options.deadline);
    for (const Chain& stroke : order.strokes) pieces -= stroke.size();
    const bool merged = pieces != 0;
    result.strokes = std::move(order.strokes);
    result.travel = merged ? travel_length(result.strokes) : order.travel;
    return result;
}

}  // namespace modsynth::drawing
