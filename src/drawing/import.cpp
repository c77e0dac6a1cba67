#include <modsynth/drawing/import.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

#include <Eigen/LU>

#include <modsynth/drawing/biarc_fit.h>
#include <modsynth/drawing/dxf_reader.h>
#include <modsynth/drawing/svg_reader.h>
#include <modsynth/task/input_error.h>
#include <modsynth/task/limits.h>

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
    const Drawing drawing =
        format == DrawingFormat::Svg ? read_svg(text, options.read) : read_dxf(text, options.read);
    check_deadline(options.deadline, "reading the drawing");
    const Affine map = placement_map(drawing, options.placement);
    ImportResult result;
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
    std::vector<Chain> chains;
    std::size_t total = 0;
    for (const Curve& c : drawing.curves) {
        Curve placed{c.source, {}};
        for (const Segment& s : c.segments) {
            placed.segments.push_back(transformed(s, map));
            check(start_point(placed.segments.back()), c.source);
            check(end_point(placed.segments.back()), c.source);
        }
        if (total >= task::kMaxPrimitives) {
            throw InputError(c.source, "the drawing needs more than " +
                                           std::to_string(task::kMaxPrimitives) +
                                           " primitives: raise --tolerance or simplify it");
        }
        FittedCurve f =
            fit_curve(placed, options.tolerance, task::kMaxPrimitives - total, options.deadline);
        for (const geometry::Primitive& p : f.primitives) {
            check(p.center, c.source + " (an arc's center)");
        }
        total += f.primitives.size();
        if (total > task::kMaxPrimitives) {
            throw InputError(c.source, "the drawing needs more than " +
                                           std::to_string(task::kMaxPrimitives) +
                                           " primitives: raise --tolerance or simplify it");
        }
        result.deviation = std::max(result.deviation, f.deviation);
        chains.push_back(std::move(f.primitives));
    }
    for (const geometry::Disc& d : drawing.obstacles) {
        const geometry::Disc placed{map(d.center), d.radius * result.metres_per_unit};
        check(placed.center, "obstacle");
        result.obstacles.push_back(placed);
    }
    StrokeOrder order = order_strokes(std::move(chains), options.keep_order);
    result.strokes = std::move(order.strokes);
    result.travel = order.travel;
    return result;
}

}  // namespace modsynth::drawing
