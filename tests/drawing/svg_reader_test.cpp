// The SVG reader on what SVG does not draw and on arcs at the edges of
// double precision: drawn as a browser draws them, or refused by name.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <string>

#include <modsynth/drawing/biarc_fit.h>
#include <modsynth/drawing/import.h>
#include <modsynth/drawing/svg_reader.h>
#include <modsynth/task/input_error.h>

namespace {

using namespace modsynth::drawing;
using modsynth::task::InputError;

std::string message_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

std::string svg(const std::string& body) {
    return R"(<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="100mm" viewBox="0 0 100 100">)" +
           body + "</svg>";
}

const std::string kShown = R"(<path id="shown" d="M 10,10 L 90,10"/>)";

}  // namespace

TEST_CASE("SVG: what is not rendered is not drawn", "[drawing][svg]") {
    for (const std::string hidden :
         {R"(<g display="none"><path d="M 10,50 L 90,50"/></g>)",
          R"(<g style="fill:red; display : none"><g><circle cx="50" cy="50" r="5"/></g></g>)",
          R"(<g style="display:none !important"><path d="M 10,50 L 90,50"/></g>)",
          R"(<path visibility="hidden" d="M 10,50 L 90,50"/>)",
          R"(<g visibility="hidden"><path d="M 10,50 L 90,50"/></g>)",
          R"(<g style="visibility:collapse"><rect x="1" y="1" width="5" height="5"/></g>)",
          // What cannot be drawn is no error where it is not drawn.
          R"(<g display="none"><text>not converted</text><image href="x.png"/></g>)"}) {
        INFO(hidden);
        const Drawing d = read_svg(svg(kShown + hidden));
        CHECK(d.curves.size() == 1);
    }
    // Visibility is inherited, and a child may turn it back on; display
    // none hides whatever is inside.
    CHECK(read_svg(
              svg(kShown +
                  R"(<g visibility="hidden"><path visibility="visible" d="M 10,50 L 90,50"/></g>)"))
              .curves.size() == 2);
    CHECK(
        read_svg(
            svg(kShown +
                R"(<g display="none"><path visibility="visible" display="inline" d="M 10,50 L 90,50"/></g>)"))
            .curves.size() == 1);
    // A hidden circle on the obstacle layer is no obstacle.
    const Drawing o = read_svg(
        svg(kShown +
            R"(<g id="obs"><circle cx="50" cy="50" r="5"/><circle style="display:none" cx="20" cy="50" r="5"/></g>)"),
        ReadOptions{"obs"});
    CHECK(o.obstacles.size() == 1);
    CHECK_THAT(message_of([] { read_svg(svg(R"(<g display="none">)" + kShown + "</g>")); }),
               Catch::Contains("empty drawing"));
}

TEST_CASE("SVG: arc radii too small are scaled up, however small", "[drawing][svg]") {
    // SVG 1.1 F.6.6: radii that cannot span the end points are scaled up
    // until they just do: a half circle between them.
    for (const char* r : {"1e-170", "1e-300", "0.001", "40"}) {
        INFO(r);
        const Drawing d = read_svg(
            svg(std::string(R"(<path d="M 10,50 A )") + r + " " + r + R"( 0 0 1 90,50"/>)"));
        REQUIRE(d.curves.size() == 1);
        const auto& e = std::get<EllipticArc>(d.curves[0].segments[0]);
        CHECK(e.u.norm() == Approx(40.0));  // millimetres: 80 mm apart
        CHECK((e.center - Vec2(50.0, 50.0)).norm() <= 1e-9);
        CHECK(std::abs(e.t1 - e.t0) == Approx(M_PI));
        const ImportResult r2 = import_drawing(
            svg(std::string(R"(<path d="M 10,50 A )") + r + " " + r + R"( 0 0 1 90,50"/>)"),
            DrawingFormat::Svg, ImportOptions{});
        CHECK(r2.deviation <= 1e-4);
    }
    // Elliptic radii keep their proportion when scaled up.
    const Drawing e = read_svg(svg(R"(<path d="M 10,50 A 1e-170 2e-170 0 0 1 90,50"/>)"));
    const auto& arc = std::get<EllipticArc>(e.curves[0].segments[0]);
    CHECK(arc.v.norm() / arc.u.norm() == Approx(2.0));
    // Radii far apart beyond what a double holds are refused by name.
    CHECK_THAT(message_of([] {
                   read_svg(svg(R"(<path id="a" d="M 10,50 A 1e-300 1e300 0 0 1 90,60"/>)"));
               }),
               Catch::Contains("path#a") && Catch::Contains("no ellipse can draw"));
}

TEST_CASE("SVG: elements with too many attributes are refused before parsing", "[drawing][svg]") {
    std::string many = "<path d=\"M 1,1 L 2,2\"";
    for (int i = 0; i < 300; ++i) many += " a" + std::to_string(i) + "=\"x>'\"";
    many += "/>";
    CHECK_THAT(message_of([&] { read_svg(svg(many)); }),
               Catch::Contains("more than 256 attributes"));
    // Quotes, comments and CDATA are delimited as the XML parser does.
    const std::string odd = R"(<!-- it's a comment with = = = --><![CDATA[ = = ]]>)" + kShown;
    CHECK(read_svg(svg(odd)).curves.size() == 1);
}

TEST_CASE("SVG: names from the file are printed escaped", "[drawing][svg]") {
    const std::string m =
        message_of([] { read_svg(svg("<path id=\"p\x1b[2J\" d=\"M 1,1 L 1,1\"/>")); });
    CHECK_THAT(m, Catch::Contains("path#p\\x1B[2J"));
    CHECK(m.find('\x1b') == std::string::npos);
}

TEST_CASE("SVG: dots are skipped with a warning, or refused with strict", "[drawing][svg]") {
    // As stroke icon sets draw them: a zero-length subpath with round caps.
    const std::string svg =
        "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 24 24\">\n"
        "<path id=\"i\" d=\"M12 8v8\"/>\n<path id=\"dot\" d=\"M12 4h.01\"/>\n"
        "<path id=\"dot2\" d=\"M6 4l0 0\"/></svg>";
    const Drawing d = read_svg(svg);
    CHECK(d.curves.size() == 2);  // the stem, and "h.01" (0.01 px long: not zero)
    REQUIRE(d.warnings.size() == 1);
    CHECK_THAT(d.warnings[0],
               Catch::Contains("skipped dots") && Catch::Contains("path#dot2 (line 4)"));
    ReadOptions strict;
    strict.strict = true;
    CHECK_THROWS_WITH(read_svg(svg, strict),
                      Catch::Contains("path#dot2 (line 4)") && Catch::Contains("zero-length"));
}

TEST_CASE("SVG: a shape neither filled nor stroked is not drawn; filled ones are counted",
          "[drawing][svg]") {
    // As tabler's icons hold it: an invisible frame beside the strokes.
    const std::string icon =
        R"svg(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 24 24" fill="none" stroke="currentColor">
<path stroke="none" d="M0 0h24v24H0z" fill="none"/>
<path d="M12 5l0 14"/><path d="M5 12l14 0"/></svg>)svg";
    const Drawing d = read_svg(icon);
    CHECK(d.curves.size() == 2);
    CHECK(d.filled_outlines == 0);
    // The frame once placed would set the width: the cross does now.
    ImportOptions options;
    options.placement.width = 0.14;
    const ImportResult r = import_drawing(icon, DrawingFormat::Svg, options);
    double lo = 1e9, hi = -1e9;
    for (const auto& stroke : r.strokes) {
        for (const auto& p : stroke) {
            lo = std::min({lo, p.start.x(), p.end.x()});
            hi = std::max({hi, p.start.x(), p.end.x()});
        }
    }
    CHECK(hi - lo == Approx(0.14));
    // Inherited: a group that sets stroke none hides its unfilled shapes.
    CHECK(read_svg(svg(kShown +
                       R"svg(<g stroke="none" style="fill:none"><path d="M 1,1 L 9,9"/></g>)svg"))
              .curves.size() == 1);
    // Fill-only shapes (what a browser shows as solid) are traced along
    // their outlines and counted; stroked ones and unset strokes are not.
    const Drawing filled = read_svg(svg(R"svg(<path d="M 10,10 h 10 v 10 z"/>
<g fill="red"><rect x="30" y="30" width="5" height="5"/><circle stroke="black" cx="60" cy="60" r="3"/></g>
<path style="fill:none" d="M 1,1 L 9,9"/>)svg"));
    CHECK(filled.curves.size() == 4);
    CHECK(filled.filled_outlines == 2);
}

TEST_CASE("SVG: a curve that goes out and back within the tolerance is a dot, skipped",
          "[drawing][svg]") {
    // As flag-icons' finer emblems hold them: "q0-.2 0 0", a curve of no
    // area ending where it starts, 0.1 units out.
    const std::string flag = svg(kShown + R"svg(<path id="speck" d="M50 50 q0-.2 0 0"/>)svg");
    ImportOptions options;
    options.placement.scale = 1e-4;  // 10 µm out
    const ImportResult r = import_drawing(flag, DrawingFormat::Svg, options);
    CHECK(r.strokes.size() == 1);
    REQUIRE(!r.warnings.empty());
    CHECK_THAT(r.warnings.back(),
               Catch::Contains("skipped dots") && Catch::Contains("path#speck (line 1)"));
    options.read.strict = true;
    CHECK_THROWS_WITH(import_drawing(flag, DrawingFormat::Svg, options),
                      Catch::Contains("path#speck") && Catch::Contains("a dot"));
    // Larger than the tolerance it is a loop, and followed.
    options.read.strict = false;
    options.tolerance = 1e-6;
    CHECK(import_drawing(flag, DrawingFormat::Svg, options).strokes.size() == 2);
}

TEST_CASE("SVG: a rect without a width or height is not rendered", "[drawing][svg]") {
    // flag-icons' gb-nir.svg holds one (SVG 2: its size is auto, 0).
    const Drawing d =
        read_svg(svg(kShown + R"svg(<rect fill="#fff" rx="0" ry="0"/><rect height="5"/>)svg"));
    CHECK(d.curves.size() == 1);
}

namespace {

struct Box {
    Vec2 min = Vec2::Constant(1e300), max = Vec2::Constant(-1e300);
    Vec2 centre() const { return (min + max) / 2.0; }
};

Box box_of(const Drawing& d) {
    Box b;
    for (const Curve& c : d.curves) {
        for (const Segment& s : c.segments) {
            for (const Vec2& p : {start_point(s), end_point(s)}) {
                b.min = b.min.cwiseMin(p);
                b.max = b.max.cwiseMax(p);
            }
        }
    }
    return b;
}

}  // namespace

TEST_CASE("SVG: text is written in a Hershey font where the text lies", "[drawing][svg][text]") {
    // One user unit is a millimetre; y grows down from the page's top,
    // 100 mm above the drawing's origin.
    const Drawing d = read_svg(svg(R"(<text id="t" x="10" y="40" font-size="16">HI</text>)"));
    REQUIRE(!d.curves.empty());
    CHECK(d.curves.front().source == "text#t (line 1)");
    const Box b = box_of(d);
    // Capitals stand on the baseline, 21/32 of the font size high.
    CHECK(b.min.y() == Approx(60.0));
    CHECK(b.max.y() == Approx(60.0 + 16.0 * 21.0 / 32.0));
    CHECK(b.min.x() > 10.0);
    CHECK(b.max.x() < 10.0 + 16.0);
    CHECK(d.filled_outlines == 0);  // filled text: its strokes, not outlines

    // The anchor moves the text by half its advance, or all of it.
    const auto anchored = [](const std::string& anchor) {
        return box_of(read_svg(svg(R"(<text x="50" y="40" font-size="16" text-anchor=")" + anchor +
                                   R"(">HI</text>)")));
    };
    const Box start = anchored("start"), middle = anchored("middle"), end = anchored("end");
    // The anchor is inherited.
    CHECK(
        box_of(
            read_svg(svg(
                R"(<g style="text-anchor:end"><text x="50" y="40" font-size="16">HI</text></g>)")))
            .max.x() == Approx(end.max.x()));
    CHECK(start.min.x() > 50.0);
    CHECK(end.max.x() < 50.0);
    CHECK(start.min.x() - middle.min.x() == Approx((start.min.x() - end.min.x()) / 2.0));
    CHECK(middle.centre().x() == Approx(50.0).margin(0.5));
    CHECK(middle.min.y() == Approx(start.min.y()));

    // The font size from a style, in px, inherited, or in em; a
    // transform moves and scales the glyphs.
    const Box styled =
        box_of(read_svg(svg(R"(<text x="10" y="40" style="font-size:16px">HI</text>)")));
    CHECK(styled.max.x() == Approx(b.max.x()));
    const Box inherited = box_of(
        read_svg(svg(R"(<g font-size="8"><text x="10" y="40" font-size="2em">HI</text></g>)")));
    CHECK(inherited.max.y() == Approx(b.max.y()));
    const Box moved = box_of(read_svg(svg(
        R"x(<g transform="translate(5,-10)"><text x="10" y="40" font-size="8" transform="scale(2)">HI</text></g>)x")));
    CHECK(moved.min.x() == Approx(b.min.x() + 10.0 + 5.0));  // 2 * (10 + bearing at 8) + 5
    CHECK(moved.min.y() == Approx(100.0 - (80.0 - 10.0)));
    CHECK(moved.max.y() == Approx(moved.min.y() + 16.0 * 21.0 / 32.0));
}

TEST_CASE("SVG: tspans continue the text or start a chunk of their own", "[drawing][svg][text]") {
    // A tspan with dy is written after the text before it, lower; one with
    // x and y starts where it says (Inkscape writes each line so).
    const Drawing d = read_svg(svg(
        R"(<text x="10" y="20" font-size="10">AB<tspan id="s" dy="30">CD</tspan><tspan x="60" y="90" text-anchor="end">E</tspan></text>)"));
    Box ab, cd, e;
    for (const Curve& c : d.curves) {
        Box& to = c.source.rfind("tspan#s", 0) == 0 ? cd : c.source.rfind("tspan", 0) == 0 ? e : ab;
        for (const Segment& s : c.segments) {
            for (const Vec2& p : {start_point(s), end_point(s)}) {
                to.min = to.min.cwiseMin(p);
                to.max = to.max.cwiseMax(p);
            }
        }
    }
    CHECK(ab.min.y() == Approx(80.0));
    CHECK(cd.min.y() == Approx(50.0));
    CHECK(cd.min.x() > ab.max.x());
    CHECK(e.min.y() == Approx(10.0));
    CHECK(e.max.x() < 60.0);
    CHECK(e.max.x() > 50.0);
    // White space collapses as a browser shows it; a text of none draws
    // nothing.
    const Box spaced =
        box_of(read_svg(svg("<text x=\"10\" y=\"20\" font-size=\"10\">\n   AB  </text>")));
    CHECK(spaced.min.x() == Approx(ab.min.x()));
    CHECK_THAT(message_of([] { read_svg(svg(R"(<text x="1" y="2">  </text>)")); }),
               Catch::Contains("empty drawing"));
}

TEST_CASE("SVG: per-character positions and spacing move the characters", "[drawing][svg][text]") {
    const auto points = [](const std::string& body) {
        std::vector<std::pair<double, double>> out;
        for (const Curve& c : read_svg(svg(body)).curves) {
            for (const Segment& s : c.segments)
                out.emplace_back(start_point(s).x(), start_point(s).y());
        }
        std::sort(out.begin(), out.end());
        return out;
    };
    const auto same = [](const std::vector<std::pair<double, double>>& a,
                         const std::vector<std::pair<double, double>>& b) {
        if (a.size() != b.size()) return false;
        for (std::size_t i = 0; i < a.size(); ++i) {
            if (std::abs(a[i].first - b[i].first) > 1e-9 ||
                std::abs(a[i].second - b[i].second) > 1e-9)
                return false;
        }
        return true;
    };
    // An x list places each character, as texts of one character would;
    // a tspan without its own takes its ancestor's for its characters.
    const auto apart = points(
        R"(<text x="10" y="40" font-size="16">A</text><text x="30" y="40" font-size="16">B</text><text x="50" y="40" font-size="16">C</text>)");
    CHECK(same(points(R"(<text x="10 30 50" y="40" font-size="16">ABC</text>)"), apart));
    CHECK(same(
        points(
            R"(<text x="10,30" y="40" font-size="16">A<tspan>B</tspan><tspan x="50">C</tspan></text>)"),
        apart));
    // Shorter lists leave the rest of the characters flowing on.
    const Box plain = box_of(read_svg(svg(R"(<text x="10" y="40" font-size="16">AB</text>)")));
    const auto box = [](const std::string& body) { return box_of(read_svg(svg(body))); };
    const Box shifted = box(R"(<text x="10" y="40" font-size="16" dx="0 5">AB</text>)");
    CHECK(shifted.min.x() == Approx(plain.min.x()));
    CHECK(shifted.max.x() == Approx(plain.max.x() + 5.0));
    const Box raised = box(R"(<text x="10" y="40" font-size="16" dy="0,-3">AB</text>)");
    CHECK(raised.max.y() == Approx(plain.max.y() + 3.0));
    CHECK(raised.min.y() == Approx(plain.min.y()));
    // letter-spacing after every character (em: of the font size),
    // word-spacing after every space.
    CHECK(box(R"(<text x="10" y="40" font-size="16" letter-spacing="2">AB</text>)").max.x() ==
          Approx(plain.max.x() + 2.0));
    CHECK(box(R"(<text x="10" y="40" font-size="16" style="letter-spacing:0.5em">AB</text>)")
              .max.x() == Approx(plain.max.x() + 8.0));
    const Box words = box(R"(<text x="10" y="40" font-size="16">A B</text>)");
    CHECK(box(R"(<text x="10" y="40" font-size="16" word-spacing="4">A B</text>)").max.x() ==
          Approx(words.max.x() + 4.0));
    CHECK(
        box(R"(<g letter-spacing="1"><text x="10" y="40" font-size="16">A B</text></g>)").max.x() ==
        Approx(words.max.x() + 2.0));
}

TEST_CASE("SVG: text that is not rendered is not drawn; fonts map to Hershey ones",
          "[drawing][svg][text]") {
    for (const std::string hidden :
         {R"(<text display="none">A</text>)", R"(<g visibility="hidden"><text>A</text></g>)",
          R"(<text fill="none" stroke="none">A</text>)",
          R"(<text>A<tspan display="none">B</tspan></text>)"}) {
        INFO(hidden);
        const std::size_t a = read_svg(svg("<text>A</text>")).curves.size();
        const Drawing d = read_svg(svg(kShown + hidden));
        CHECK(d.curves.size() == (hidden.find("tspan") != std::string::npos ? 1 + a : 1));
    }
    // A serif family is written in a serif font, a sans-serif one in the
    // default; a family naming an installed Hershey font is that font.
    const auto strokes = [](const std::string& family) {
        return read_svg(svg("<text x=\"10\" y=\"50\" font-family=\"" + family + "\">H</text>"))
            .curves.size();
    };
    CHECK(strokes("Arial, sans-serif") == 3);
    CHECK(strokes("'Times New Roman', serif") > 3);
    CHECK(strokes("Hershey rowmans") == 3);
    CHECK(strokes("Unknown Font") == 3);
}

TEST_CASE("SVG: text that cannot be honoured is refused by name", "[drawing][svg][text]") {
    for (const auto& [body, why] : std::vector<std::pair<std::string, std::string>>{
             {R"(<text id="a"><textPath href="#p">A</textPath></text>)", "textPath (line 1)"},
             {R"(<text id="a" style="writing-mode:tb">A</text>)", "vertical writing"},
             {R"(<text id="a" font-family="Hershey NoSuch">A</text>)", "not installed"},
             {R"(<text id="a" baseline-shift="super">A</text>)", "baseline-shift 'super'"},
             {R"(<text id="a" style="dominant-baseline:middle">A</text>)",
              "dominant-baseline 'middle'"},
             {R"(<text id="a" direction="rtl">A</text>)", "direction 'rtl'"},
             {R"(<text id="a" letter-spacing="10%">A</text>)", "letter-spacing '10%'"},
             {R"(<text id="a" x="1 b">AB</text>)", "malformed attribute x"},
             {R"(<text id="a" rotate="30">A</text>)", "rotate"},
             {R"(<text id="a" font-size="big">A</text>)", "font-size"}}) {
        INFO(body);
        CHECK_THAT(message_of([&] { read_svg(svg(kShown + body)); }),
                   Catch::Contains("(line 1)") && Catch::Contains(why));
    }
    CHECK_THAT(message_of([] { read_svg(svg(R"(<text id="a" rotate="30">A</text>)")); }),
               Catch::Contains("text#a (line 1)"));
}

TEST_CASE("SVG: a label as Inkscape writes it imports; characters without a glyph are said",
          "[drawing][svg][text]") {
    const std::string label =
        R"svg(<svg xmlns="http://www.w3.org/2000/svg" xmlns:sodipodi="http://sodipodi.sourceforge.net/DTD/sodipodi-0.dtd"
   width="60mm" height="30mm" viewBox="0 0 60 30">
  <g id="layer1">
    <rect style="fill:none;stroke:#000000;stroke-width:0.5" width="56" height="26" x="2" y="2" ry="3"/>
    <text xml:space="preserve" style="font-size:8.46667px;line-height:1.25;font-family:sans-serif;text-anchor:middle;fill:#000000;stroke:none"
       x="36" y="18" id="text1"><tspan sodipodi:role="line" id="tspan1" x="36" y="18">WARN°</tspan></text>
  </g>
</svg>)svg";
    ImportOptions options;
    options.placement.width = 0.25;
    const ImportResult r = import_drawing(label, DrawingFormat::Svg, options);
    CHECK(r.strokes.size() > 5);
    REQUIRE(!r.warnings.empty());
    CHECK_THAT(r.warnings.front(),
               Catch::Contains("tspan#tspan1 (line 6)") && Catch::Contains("without a glyph"));
    // The word is centred on x = 36 mm of the 60 mm label.
    const Drawing d = read_svg(label);
    Box word;
    for (const Curve& c : d.curves) {
        if (c.source.rfind("tspan", 0) != 0) continue;
        for (const Segment& s : c.segments) {
            for (const Vec2& p : {start_point(s), end_point(s)}) {
                word.min = word.min.cwiseMin(p);
                word.max = word.max.cwiseMax(p);
            }
        }
    }
    CHECK(word.centre().x() == Approx(36.0).margin(0.3));
    CHECK(word.min.y() == Approx(12.0).margin(1e-9));  // "WARN" has no descender
}
