// The SVG reader on what SVG does not draw and on arcs at the edges of
// double precision: drawn as a browser draws them, or refused by name.
#include <algorithm>
#include <catch2/catch.hpp>
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
