// SVG use elements: drawn where a browser draws them (their transform, x and
// y, nested), and refused by name when they refer to nothing or to
// themselves.
#include <catch2/catch.hpp>
#include <string>

#include <modsynth/drawing/svg_reader.h>
#include <modsynth/task/input_error.h>

namespace {

using namespace modsynth::drawing;

std::string svg(const std::string& body) {
    return "<svg xmlns=\"http://www.w3.org/2000/svg\" "
           "xmlns:xlink=\"http://www.w3.org/1999/xlink\" width=\"100mm\" height=\"100mm\" "
           "viewBox=\"0 0 100 100\">\n" +
           body + "\n</svg>";
}

/// The curve's start in the file's user units (y down), as drawn.
Vec2 start_of(const Curve& c) {
    const Vec2 p = start_point(c.segments.front());
    return Vec2(p.x(), 100.0 - p.y());
}

}  // namespace

TEST_CASE("SVG use: a copy of what it refers to, moved by its transform, x and y",
          "[drawing][svg]") {
    const Drawing d = read_svg(svg(R"svg(<defs><path id="dash" d="M 0,0 L 10,0"/></defs>
<use href="#dash" x="5" y="7"/>
<use xlink:href="#dash" transform="translate(50,0)" x="1" y="2"/>
<use xlink:href="#dash" transform="rotate(90)" y="-20"/>)svg"));
    REQUIRE(d.curves.size() == 3);
    CHECK((start_of(d.curves[0]) - Vec2(5, 7)).norm() < 1e-12);
    CHECK((start_of(d.curves[1]) - Vec2(51, 2)).norm() < 1e-12);
    // rotate(90) then translate(0,-20): (0,0) -> (0,-20) -> (20,0).
    CHECK((start_of(d.curves[2]) - Vec2(20, 0)).norm() < 1e-12);
    CHECK((start_of(d.curves[2]) - Vec2(20, 0)).norm() < 1e-12);
}

TEST_CASE("SVG use: nested uses, groups and symbols", "[drawing][svg]") {
    const Drawing d = read_svg(svg(R"svg(<defs>
<path id="dash" d="M 0,0 L 10,0"/>
<g id="two"><use href="#dash"/><use href="#dash" y="10"/></g>
<symbol id="sym" viewBox="0 0 10 10"><path d="M 0,0 L 10,10"/></symbol>
</defs>
<use href="#two" x="20" y="20"/>
<use href="#two" transform="translate(40,40)"/>
<use href="#sym" x="60" y="60" width="20" height="20"/>)svg"));
    REQUIRE(d.curves.size() == 5);
    CHECK((start_of(d.curves[0]) - Vec2(20, 20)).norm() < 1e-12);
    CHECK((start_of(d.curves[1]) - Vec2(20, 30)).norm() < 1e-12);
    CHECK((start_of(d.curves[3]) - Vec2(40, 50)).norm() < 1e-12);
    // The symbol's viewBox of 10 fills the use's 20 by 20.
    const Vec2 end = end_point(d.curves[4].segments.back());
    CHECK((start_of(d.curves[4]) - Vec2(60, 60)).norm() < 1e-9);
    CHECK((Vec2(end.x(), 100.0 - end.y()) - Vec2(80, 80)).norm() < 1e-9);
}

TEST_CASE("SVG use: what a use draws keeps its rendering and its name", "[drawing][svg]") {
    // A use hidden draws nothing; what it draws takes its visibility.
    CHECK(read_svg(svg(R"svg(<path id="a" d="M 0,0 L 10,0"/><use href="#a" display="none"/>
<use href="#a" visibility="hidden" y="5"/>)svg"))
              .curves.size() == 1);
    // Errors in a copy name the original's line and the use's.
    CHECK_THROWS_WITH(read_svg(svg(R"svg(<defs><path id="bad" d="M 0,0 L"/></defs>
<use href="#bad"/>)svg")),
                      Catch::Contains("path#bad (line 2, drawn by use at line 3)"));
}

TEST_CASE("SVG use: a reference to nothing, elsewhere or to itself is refused by name",
          "[drawing][svg]") {
    CHECK_THROWS_WITH(read_svg(svg(R"svg(<use id="u" href="#nowhere"/>)svg")),
                      Catch::Contains("use#u (line 2)") &&
                          Catch::Contains("#nowhere, which the file does not hold"));
    CHECK_THROWS_WITH(read_svg(svg(R"svg(<use href="other.svg#a"/>)svg")),
                      Catch::Contains("outside the file"));
    CHECK_THROWS_WITH(
        read_svg(svg(R"svg(<use href="#a" x="50%"/><path id="a" d="M 0,0 L 1,1"/>)svg")),
        Catch::Contains("x='50%' is not a length"));
    // Directly, through another, and through an ancestor.
    CHECK_THROWS_WITH(read_svg(svg(R"svg(<use id="self" href="#self"/>)svg")),
                      Catch::Contains("which draws itself (self -> self)"));
    CHECK_THROWS_WITH(
        read_svg(svg(R"svg(<defs><g id="a"><use href="#b"/></g><g id="b"><use href="#a"/></g></defs>
<use href="#a"/>)svg")),
        Catch::Contains("(a -> b -> a)") || Catch::Contains("(b -> a -> b)"));
    CHECK_THROWS_WITH(
        read_svg(svg(R"svg(<g id="outer"><path d="M 0,0 L 1,1"/><use href="#outer"/></g>)svg")),
        Catch::Contains("which draws itself (outer -> outer)"));
}

TEST_CASE("SVG use: copies that multiply are capped, not followed", "[drawing][svg]") {
    // Ten uses of the one before, each drawing it ten times: 10^10 paths.
    std::string body = R"svg(<defs><path id="l0" d="M 0,0 L 1,1"/>)svg";
    for (int level = 1; level <= 10; ++level) {
        body += "<g id=\"l" + std::to_string(level) + "\">";
        for (int k = 0; k < 10; ++k) body += "<use href=\"#l" + std::to_string(level - 1) + "\"/>";
        body += "</g>";
    }
    body += "</defs><use href=\"#l10\"/>";
    CHECK_THROWS_WITH(read_svg(svg(body)), Catch::Contains("too large for a drawing"));
}

TEST_CASE("SVG use: a broken use in defs is no error until something draws it", "[drawing][svg]") {
    const std::string defs = R"svg(<defs><g id="kept"><use href="#gone"/></g></defs>
<path d="M 0,0 L 10,0"/>)svg";
    CHECK(read_svg(svg(defs)).curves.size() == 1);
    CHECK_THROWS_WITH(read_svg(svg(defs + R"svg(<use href="#kept"/>)svg")),
                      Catch::Contains("#gone, which the file does not hold"));
}

TEST_CASE("SVG use: a use of a use draws what that use draws, wherever it stands",
          "[drawing][svg]") {
    // After the use it refers to (replaced already) and before it.
    const Drawing d = read_svg(svg(R"svg(<defs><path id="a" d="M 10,10 L 90,10"/></defs>
<use id="u1" href="#a" y="10"/>
<use id="u2" href="#u1" y="30"/>
<use href="#u3" x="5"/>
<use id="u3" xlink:href="#a" y="60"/>)svg"));
    REQUIRE(d.curves.size() == 4);
    CHECK((start_of(d.curves[0]) - Vec2(10, 20)).norm() < 1e-12);
    // u2: u1's copy (moved by 10) moved by 30 more.
    CHECK((start_of(d.curves[1]) - Vec2(10, 50)).norm() < 1e-12);
    CHECK((start_of(d.curves[2]) - Vec2(15, 70)).norm() < 1e-12);
    CHECK((start_of(d.curves[3]) - Vec2(10, 70)).norm() < 1e-12);
}
