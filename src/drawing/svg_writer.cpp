#include <modsynth/drawing/svg_writer.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace modsynth::drawing {

namespace {

using geometry::Primitive;
using geometry::PrimitiveKind;
using geometry::Vec2;

std::string number(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

// How far a primitive reaches beyond its end points and centre.
double bulge(const Primitive& p) {
    switch (p.kind) {
        case PrimitiveKind::Line:
            return 0.0;
        case PrimitiveKind::Arc:
        case PrimitiveKind::Circle:
            return p.radius;
    }
    geometry::invalid_kind(p.kind);
}

}  // namespace

std::string write_svg(const std::vector<Chain>& strokes) {
    // The page reaches from the origin past every point (and arc), so that
    // the y flip of reading (about the page height) restores y exactly.
    double width = 1.0, height = 1.0;  // mm
    for (const Chain& c : strokes) {
        for (const Primitive& p : c) {
            const double reach = bulge(p);
            for (const Vec2& q : {p.start, p.end, p.center}) {
                width = std::max(width, std::ceil(1e3 * (q.x() + reach)) + 1.0);
                height = std::max(height, std::ceil(1e3 * (q.y() + reach)) + 1.0);
            }
        }
    }
    auto pt = [height](const Vec2& p) {
        return number(1e3 * p.x()) + "," + number(height - 1e3 * p.y());
    };
    std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    out += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + number(width) + "mm\" height=\"" +
           number(height) + "mm\" viewBox=\"0 0 " + number(width) + " " + number(height) + "\">\n";
    for (std::size_t s = 0; s < strokes.size(); ++s) {
        std::string d = "M " + pt(strokes[s].front().start);
        for (const Primitive& p : strokes[s]) {
            switch (p.kind) {
                case PrimitiveKind::Line:
                    d += " L " + pt(p.end);
                    continue;
                case PrimitiveKind::Arc:
                case PrimitiveKind::Circle:
                    break;
            }
            // Arcs of at most a quarter turn: SVG's end-point form finds
            // their centers well conditioned (a half turn would not), and
            // reading merges the pieces of one circle back into one.
            const int pieces = std::max(
                1, static_cast<int>(std::ceil(std::abs(p.sweep) / (geometry::kPi / 2) - 1e-9)));
            const std::string r = number(1e3 * p.radius);
            for (int k = 1; k <= pieces; ++k) {
                const Vec2 q = k == pieces
                                   ? p.end
                                   : p.center + p.radius * geometry::unit(p.start_angle +
                                                                          p.sweep * k / pieces);
                // y flips: counter-clockwise in the task is SVG's negative
                // sweep direction.
                d += " A " + r + "," + r + " 0 0 " + (p.sweep > 0.0 ? "0 " : "1 ") + pt(q);
            }
        }
        out += "  <path id=\"stroke" + std::to_string(s) + "\" d=\"" + d +
               "\" fill=\"none\" stroke=\"black\" stroke-width=\"0.5\"/>\n";
    }
    out += "</svg>\n";
    return out;
}

}  // namespace modsynth::drawing
