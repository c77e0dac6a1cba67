#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include <modsynth/drawing/biarc_fit.h>
#include <modsynth/drawing/dxf_reader.h>
#include <modsynth/drawing/import.h>
#include <modsynth/drawing/svg_reader.h>
#include <modsynth/drawing/svg_writer.h>
#include <modsynth/task/input_error.h>

namespace {

using namespace modsynth::drawing;
using modsynth::geometry::Primitive;
using modsynth::geometry::PrimitiveKind;
using modsynth::task::InputError;

std::string fixture(const std::string& name) {
    std::ifstream in(std::string(MODSYNTH_SOURCE_DIR) + "/tasks/drawings/" + name);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

/// Distance from a dense sampling of the segment to the primitives, and
/// from a dense sampling of the primitives back to the segment's samples.
double dense_deviation(const Segment& s, const std::vector<Primitive>& ps) {
    constexpr int n = 4000;
    std::vector<Vec2> curve;
    double worst = 0.0, chord = 0.0;
    for (int i = 0; i <= n; ++i) {
        curve.push_back(point(s, static_cast<double>(i) / n));
        double d = 1e9;
        for (const Primitive& p : ps)
            d = std::min(d, modsynth::geometry::nearest(p, curve.back()).distance);
        worst = std::max(worst, d);
        if (i > 0) chord = std::max(chord, (curve[i] - curve[i - 1]).norm());
    }
    // Back: each primitive's samples to the nearest curve sample, less half
    // the sample spacing (the curve passes between its samples).
    for (const Primitive& p : ps) {
        for (int k = 0; k <= 100; ++k) {
            const Vec2 q = modsynth::geometry::point_at(p, length(p) * k / 100);
            double d = 1e9;
            for (const Vec2& c : curve) d = std::min(d, (c - q).norm());
            worst = std::max(worst, d - chord / 2);
        }
    }
    return worst;
}

void check_chain(const std::vector<Primitive>& ps, const Segment& s) {
    REQUIRE(!ps.empty());
    CHECK((ps.front().start - point(s, 0.0)).norm() <= 1e-9);
    CHECK((ps.back().end - point(s, 1.0)).norm() <= 1e-9);
    for (std::size_t j = 1; j < ps.size(); ++j) {
        CHECK((ps[j].start - ps[j - 1].end).norm() <= 1e-9);
        // Tangent-continuous: the curve is smooth.
        const Vec2 a = modsynth::geometry::tangent_at(ps[j - 1], length(ps[j - 1]));
        const Vec2 b = modsynth::geometry::tangent_at(ps[j], 0.0);
        CHECK((a - b).norm() <= 1e-6);
    }
}

std::string message_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

}  // namespace

TEST_CASE("random Béziers fit within the tolerance, tangent-continuous", "[drawing][slow]") {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> coord(-0.2, 0.2);
    for (double tol : {1e-3, 1e-4, 1e-5}) {
        for (int i = 0; i < 15; ++i) {
            CubicBezier c{Vec2(coord(rng), coord(rng)), Vec2(coord(rng), coord(rng)),
                          Vec2(coord(rng), coord(rng)), Vec2(coord(rng), coord(rng))};
            const Curve curve{"bezier", {c}};
            const FittedCurve f = fit_curve(curve, tol, 5000);
            INFO("tolerance " << tol << ", curve " << i);
            CHECK(f.deviation <= tol);
            CHECK(dense_deviation(c, f.primitives) <= tol);
            // A cusp (zero derivative) is the one place a smooth chain is
            // impossible; random control points almost never make one.
            check_chain(f.primitives, c);
        }
    }
}

TEST_CASE("ellipses fit within the tolerance in few pieces", "[drawing][slow]") {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> radius(0.01, 0.3), angle(-3.0, 3.0);
    for (double tol : {1e-3, 1e-4, 1e-5}) {
        for (int i = 0; i < 10; ++i) {
            const double a = angle(rng), rx = radius(rng), ry = radius(rng);
            EllipticArc e{Vec2(0.5, 0.2), rx * Vec2(std::cos(a), std::sin(a)),
                          ry * Vec2(-std::sin(a), std::cos(a)), angle(rng), 0.0};
            e.t1 = e.t0 + (i % 2 ? 1 : -1) * (0.5 + std::abs(angle(rng)));
            const FittedCurve f = fit_curve({"ellipse", {e}}, tol, 5000);
            INFO("tolerance " << tol << ", ellipse " << i);
            CHECK(dense_deviation(e, f.primitives) <= tol);
            check_chain(f.primitives, e);
        }
    }
    // Fewer pieces for a looser tolerance (measured: 12, 24, 48 pieces at
    // 1, 0.1, 0.01 mm for this 2:1 ellipse).
    EllipticArc full{Vec2::Zero(), Vec2(0.1, 0.0), Vec2(0.0, 0.05), 0.0, 2 * M_PI};
    const auto loose = fit_curve({"e", {full}}, 1e-3, 5000).primitives.size();
    const auto tight = fit_curve({"e", {full}}, 1e-5, 5000).primitives.size();
    CHECK(loose < tight);
    CHECK(fit_curve({"e", {full}}, 1e-4, 5000).primitives.size() <= 26);
}

TEST_CASE("lines and circular arcs map exactly; one circle's arcs merge", "[drawing]") {
    const FittedCurve line = fit_curve({"l", {LineSegment{Vec2(0, 0), Vec2(0.3, 0.1)}}}, 1e-4, 10);
    REQUIRE(line.primitives.size() == 1);
    CHECK(line.primitives[0].kind == PrimitiveKind::Line);
    EllipticArc arc{Vec2(0.2, 0.1), Vec2(0.05, 0.0), Vec2(0.0, 0.05), 0.3, 2.0};
    const FittedCurve a = fit_curve({"a", {arc}}, 1e-4, 10);
    REQUIRE(a.primitives.size() == 1);
    CHECK(a.primitives[0].kind == PrimitiveKind::Arc);
    CHECK(a.primitives[0].radius == Approx(0.05).epsilon(1e-14));
    CHECK(a.primitives[0].sweep == Approx(1.7).epsilon(1e-12));
    // Clockwise when the axes are mirrored.
    EllipticArc mirrored{Vec2(0.2, 0.1), Vec2(0.05, 0.0), Vec2(0.0, -0.05), 0.3, 2.0};
    CHECK(fit_curve({"m", {mirrored}}, 1e-4, 10).primitives[0].sweep < 0.0);
    // Four quarter arcs of one circle are one circle.
    std::vector<Segment> quarters;
    for (int k = 0; k < 4; ++k) {
        quarters.push_back(EllipticArc{Vec2(0.2, 0.1), Vec2(0.05, 0.0), Vec2(0.0, 0.05),
                                       k * M_PI / 2, (k + 1) * M_PI / 2});
    }
    const FittedCurve c = fit_curve({"c", quarters}, 1e-4, 10);
    REQUIRE(c.primitives.size() == 1);
    CHECK(c.primitives[0].kind == PrimitiveKind::Circle);
}

TEST_CASE("SVG: relative and absolute commands, transforms and viewBox units", "[drawing]") {
    const std::string head =
        R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="50mm" viewBox="0 0 10 5">)svg";
    const Drawing abs = read_svg(
        head + R"svg(<path d="M 1,1 L 3,1 C 4,1 4,2 3,3 Q 2,4 1,3 A 1 1 0 0 1 1,1"/></svg>)svg");
    const Drawing rel = read_svg(
        head + R"svg(<path d="m 1,1 l 2,0 c 1,0 1,1 0,2 q -1,1 -2,0 a 1 1 0 0 1 0,-2"/></svg>)svg");
    REQUIRE(abs.curves.size() == 1);
    REQUIRE(rel.curves.size() == 1);
    REQUIRE(abs.curves[0].segments.size() == 4);
    REQUIRE(rel.curves[0].segments.size() == 4);
    for (std::size_t i = 0; i < 4; ++i) {
        for (double t : {0.0, 0.3, 1.0}) {
            CHECK((point(abs.curves[0].segments[i], t) - point(rel.curves[0].segments[i], t))
                      .norm() <= 1e-9);
        }
    }
    // One user unit is 10 mm; y up from the page's bottom (50 mm high).
    CHECK((start_point(abs.curves[0].segments[0]) - Vec2(10.0, 40.0)).norm() <= 1e-9);
    CHECK(abs.metres_per_unit == 1e-3);
    // Nested transforms compose: translate then scale.
    const Drawing t = read_svg(
        head +
        R"svg(<g transform="translate(2,1)"><g transform="scale(2)"><line x1="0" y1="0" x2="1" y2="0"/></g></g></svg>)svg");
    REQUIRE(t.curves.size() == 1);
    CHECK((start_point(t.curves[0].segments[0]) - Vec2(20.0, 40.0)).norm() <= 1e-9);
    CHECK((end_point(t.curves[0].segments[0]) - Vec2(40.0, 40.0)).norm() <= 1e-9);
    // rect, polygon, polyline, circle, ellipse
    const Drawing shapes = read_svg(
        head +
        R"svg(<rect x="1" y="1" width="2" height="1"/><polygon points="5,1 6,1 6,2"/><polyline points="7,1 8,1 8,2"/><circle cx="2" cy="3" r="1"/><ellipse cx="5" cy="3" rx="1" ry="0.5"/></svg>)svg");
    CHECK(shapes.curves.size() == 5);
}

TEST_CASE("SVG: errors name the element and its line", "[drawing]") {
    const std::string head = "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 10 10\">\n";
    CHECK_THAT(message_of([&] { read_svg(head + "<path id=\"p3\" d=\"M 10,\"/></svg>"); }),
               Catch::Contains("path#p3 (line 2)") && Catch::Contains("malformed path data") &&
                   Catch::Contains("M 10,"));
    CHECK_THAT(
        message_of([&] { read_svg(head + "<foreignObject id=\"t1\"/>\n<image id=\"i\"/></svg>"); }),
        Catch::Contains("foreignObject#t1 (line 2)") && Catch::Contains("image#i (line 3)"));
    CHECK_THAT(message_of([&] { read_svg(head + "<path id=\"z\" d=\"M 1,1 L 1,1\"/></svg>"); }),
               Catch::Contains("path#z (line 2)") && Catch::Contains("zero-length"));
    CHECK_THAT(message_of([&] { read_svg(head + "</svg>"); }), Catch::Contains("empty drawing"));
    CHECK_THAT(message_of([] { read_svg("{\"format\": 1}"); }), Catch::Contains("not an SVG file"));
    CHECK_THAT(message_of([] { read_svg("<html></html>"); }), Catch::Contains("not an SVG file"));
    CHECK_THAT(message_of([&] { read_svg(head + "<path d=\"M 1e300,0 L 0,0\"/></svg>"); }),
               Catch::Contains("out of range"));
}

TEST_CASE("DXF: the fixture's entities, exact bulges, clamped spline ends", "[drawing]") {
    const Drawing d = read_dxf(fixture("bracket.dxf"), ReadOptions{"keepout"});
    CHECK(d.metres_per_unit == 1e-3);
    REQUIRE(d.obstacles.size() == 1);
    CHECK((d.obstacles[0].center - Vec2(50, 70)).norm() <= 1e-12);
    REQUIRE(d.curves.size() == 6);  // outline, polyline, spline, ellipse, arc, line
    const Curve& outline = d.curves[0];
    REQUIRE(outline.segments.size() == 8);
    // The bulge 0.4142 rounds a corner by a quarter circle of radius 10.
    const FittedCurve f = fit_curve(outline, 1e-4, 100);
    CHECK(f.primitives.size() == 8);
    CHECK(f.primitives[1].kind == PrimitiveKind::Arc);
    CHECK(f.primitives[1].radius == Approx(10.0).epsilon(1e-12));
    const Segment& spline = d.curves[2].segments[0];
    CHECK((point(spline, 0.0) - Vec2(15, 45)).norm() <= 1e-12);
    CHECK((point(spline, 1.0) - Vec2(65, 45)).norm() <= 1e-12);
    CHECK_THAT(message_of([] { read_dxf("hello"); }), Catch::Contains("not a DXF file"));
    const std::string hatch =
        "0\nSECTION\n2\nENTITIES\n0\nHATCH\n8\n0\n10\n0\n20\n0\n0\nENDSEC\n0\nEOF\n";
    CHECK_THAT(message_of([&] { read_dxf(hatch); }),
               Catch::Contains("nothing to draw") && Catch::Contains("HATCH #1"));
}

TEST_CASE("import: placement, stroke order, and the SVG round trip", "[drawing]") {
    ImportOptions o;
    o.read.obstacle_layer = "Obstacles";
    const ImportResult kept = [&] {
        ImportOptions k = o;
        k.keep_order = true;
        return import_drawing(fixture("sketch.svg"), DrawingFormat::Svg, k);
    }();
    const ImportResult ordered = import_drawing(fixture("sketch.svg"), DrawingFormat::Svg, o);
    CHECK(ordered.strokes.size() == kept.strokes.size());
    CHECK(ordered.travel <= kept.travel);
    CHECK(ordered.deviation <= 1e-4);
    CHECK(ordered.obstacles.size() == 2);
    // --width and --at: the bounding box is 0.5 m wide, centred there.
    ImportOptions placed = o;
    placed.placement.width = 0.5;
    placed.placement.at = Vec2(1.0, 2.0);
    const ImportResult p = import_drawing(fixture("sketch.svg"), DrawingFormat::Svg, placed);
    double xmin = 1e9, xmax = -1e9;
    for (const auto& s : p.strokes) {
        for (const Primitive& q : s)
            xmin = std::min({xmin, q.start.x(), q.end.x()}),
            xmax = std::max({xmax, q.start.x(), q.end.x()});
    }
    CHECK(xmax - xmin == Approx(0.5).epsilon(1e-3));
    CHECK((xmax + xmin) / 2 == Approx(1.0).epsilon(1e-3));

    // Written as SVG and read back: the same primitives.
    ImportOptions again;
    again.keep_order = true;
    const ImportResult back = import_drawing(write_svg(kept.strokes), DrawingFormat::Svg, again);
    REQUIRE(back.strokes.size() == kept.strokes.size());
    for (std::size_t s = 0; s < kept.strokes.size(); ++s) {
        REQUIRE(back.strokes[s].size() == kept.strokes[s].size());
        for (std::size_t j = 0; j < kept.strokes[s].size(); ++j) {
            const Primitive &a = kept.strokes[s][j], &b = back.strokes[s][j];
            INFO("stroke " << s << " primitive " << j);
            CHECK(a.kind == b.kind);
            CHECK((a.start - b.start).norm() <= 1e-9 * 0.2);
            CHECK((a.end - b.end).norm() <= 1e-9 * 0.2);
            switch (a.kind) {
                case PrimitiveKind::Line:
                    break;
                case PrimitiveKind::Arc:
                case PrimitiveKind::Circle:
                    CHECK((a.center - b.center).norm() <= 1e-9 * 0.2);
                    CHECK(a.sweep == Approx(b.sweep).epsilon(1e-9));
                    break;
            }
        }
    }
}

TEST_CASE("import: a line shorter than the tolerance is folded into its neighbour",
          "[drawing][import]") {
    // A path optimiser's leftover: a 5 µm jog between two lines of 50 mm,
    // and a stroke that is itself that short, kept.
    const std::string text =
        R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="100mm" viewBox="0 0 100 100">
<path d="M 0,10 L 50,10 L 50.004,10.003 L 100,10"/><path d="M 0,50 L 0.005,50"/></svg>)svg";
    ImportOptions options;
    options.keep_order = true;
    const ImportResult r = import_drawing(text, DrawingFormat::Svg, options);
    REQUIRE(r.strokes.size() == 2);
    CHECK(r.strokes[0].size() == 2);
    for (const Primitive& p : r.strokes[0]) CHECK(modsynth::geometry::length(p) >= 1e-4);
    CHECK(r.strokes[1].size() == 1);
    CHECK(r.deviation <= 1e-4);
    // Two in a row at a corner: the second is not folded where the first
    // went (its corners would stray 0.16 mm), but into the line after it.
    const std::string corner =
        R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="100mm" viewBox="0 0 100 100">
<path d="M 0,10 L 50,10 L 50.01,10.08 L 50,10.16 L 0,10.16"/></svg>)svg";
    const ImportResult c = import_drawing(corner, DrawingFormat::Svg, options);
    REQUIRE(c.strokes.size() == 1);
    CHECK(c.strokes[0].size() == 2);
    for (const Primitive& p : c.strokes[0]) CHECK(modsynth::geometry::length(p) >= 1e-4);
    CHECK(c.deviation <= 1e-4);
}
