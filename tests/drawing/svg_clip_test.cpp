// SVG clip paths applied to what the robot traces: the centrelines inside
// the clip are kept, cut where they cross its edge; clips that cannot be
// honoured are refused by name.
#include <catch2/catch.hpp>
#include <chrono>
#include <string>

#include <modsynth/drawing/svg_reader.h>
#include <modsynth/task/input_error.h>

namespace {

using namespace modsynth::drawing;

std::string svg(const std::string& body) {
    return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"100mm\" height=\"100mm\" "
           "viewBox=\"0 0 100 100\">\n" +
           body + "\n</svg>";
}

/// In the file's user units (y down).
Vec2 user(const Vec2& p) { return Vec2(p.x(), 100.0 - p.y()); }

}  // namespace

TEST_CASE("SVG clip-path: a rectangle cuts the lines that cross it and drops the rest",
          "[drawing][svg]") {
    // The clip rectangle is in the user space of the group, moved by its
    // transform: x from 20 to 60, y from 10 to 50 in the file.
    const Drawing d = read_svg(svg(
        R"svg(<defs><clipPath id="c"><rect x="10" y="0" width="40" height="40"/></clipPath></defs>
<g clip-path="url(#c)" transform="translate(10,10)">
  <path d="M 0,20 L 90,20"/>
  <path d="M 20,60 L 30,60"/>
  <path d="M 10,0 L 10,40"/>
</g>
<path d="M 0,90 L 90,90"/>)svg"));
    // The crossing line cut, the one outside dropped, the one on the edge
    // kept, and the unclipped one whole.
    REQUIRE(d.curves.size() == 3);
    CHECK((user(start_point(d.curves[0].segments.front())) - Vec2(20, 30)).norm() < 1e-9);
    CHECK((user(end_point(d.curves[0].segments.back())) - Vec2(60, 30)).norm() < 1e-9);
    CHECK((user(start_point(d.curves[1].segments.front())) - Vec2(20, 10)).norm() < 1e-9);
    CHECK((user(end_point(d.curves[1].segments.back())) - Vec2(20, 50)).norm() < 1e-9);
    CHECK((user(end_point(d.curves[2].segments.back())) - Vec2(90, 90)).norm() < 1e-9);
}

TEST_CASE("SVG clip-path: a path clip cuts curves where they leave it", "[drawing][svg]") {
    // A circle of radius 20 about (50,50) clipped by the triangle on the
    // side y >= x of the diagonal (y down): what is kept lies in it.
    const Drawing d = read_svg(svg(
        R"svg(<clipPath id="t"><path d="M 0,0 L 100,100 L 0,100 Z" clip-rule="evenodd"/></clipPath>
<circle clip-path="url(#t)" cx="50" cy="50" r="20"/>)svg"));
    REQUIRE(!d.curves.empty());
    double length = 0.0;
    for (const Curve& c : d.curves) {
        for (const Segment& s : c.segments) {
            for (int i = 0; i <= 16; ++i) {
                const Vec2 p = user(point(s, i / 16.0));
                CHECK(p.y() >= p.x() - 1e-6);
            }
            length += approximate_length(s, 256);
        }
    }
    // Half the circle is inside.
    CHECK(length == Approx(modsynth::geometry::kPi * 20.0).epsilon(1e-4));
}

TEST_CASE("SVG clip-path: clips that cannot be honoured are refused by name", "[drawing][svg]") {
    CHECK_THROWS_WITH(
        read_svg(svg(R"svg(<path id="p" clip-path="url(#none)" d="M 0,0 L 1,1"/>)svg")),
        Catch::Contains("path#p (line 2)") && Catch::Contains("does not name a clipPath"));
    CHECK_THROWS_WITH(
        read_svg(svg(
            R"svg(<clipPath id="b" clipPathUnits="objectBoundingBox"><rect width="1" height="1"/></clipPath>
<path clip-path="url(#b)" d="M 0,0 L 1,1"/>)svg")),
        Catch::Contains("objectBoundingBox"));
    CHECK_THROWS_WITH(read_svg(svg(R"svg(<clipPath id="t"><text>Hi</text></clipPath>
<path clip-path="url(#t)" d="M 0,0 L 1,1"/>)svg")),
                      Catch::Contains("clipPath#t (line 2)") && Catch::Contains("text"));
    // A drawing clipped away entirely is empty.
    CHECK_THROWS_WITH(
        read_svg(svg(R"svg(<clipPath id="c"><rect x="50" y="50" width="1" height="1"/></clipPath>
<path clip-path="url(#c)" d="M 0,0 L 10,0"/>)svg")),
        Catch::Contains("empty drawing"));
}

TEST_CASE("SVG clip-path: a clip inside a clip is refused as such, wherever it is defined",
          "[drawing][svg]") {
    for (const char* order : {"later", "earlier"}) {
        INFO(order);
        const std::string inner =
            R"svg(<clipPath id="d"><rect x="0" y="40" width="100" height="20"/></clipPath>)svg";
        const std::string outer =
            R"svg(<clipPath id="c"><rect x="20" y="0" width="60" height="100" clip-path="url(#d)"/></clipPath>)svg";
        const std::string line = R"svg(<path d="M 10,50 L 90,50" clip-path="url(#c)"/>)svg";
        const std::string body =
            std::string(order) == "later" ? line + outer + inner : inner + outer + line;
        try {
            read_svg(svg(body));
            FAIL("read");
        } catch (const modsynth::task::InputError& e) {
            CHECK_THAT(e.what(), Catch::Contains("a clip inside a clip"));
            CHECK_THAT(e.what(), !Catch::Contains("does not name"));
        }
    }
}

TEST_CASE(
    "SVG clip-path: elements clipped alike share one region, and reading stops at its "
    "deadline",
    "[drawing][svg]") {
    // A clip path of 2000 curves used by 3000 lines: 3000 regions of half a
    // million points each once, one now.
    std::string d = "M10 10";
    for (int k = 0; k < 2000; ++k)
        d += " C" + std::to_string(10 + k % 80) + " 5 " + std::to_string(12 + k % 80) + " 95 " +
             std::to_string(14 + k % 80) + " 90";
    std::string body = "<clipPath id=\"c\"><path d=\"" + d + " Z\"/></clipPath>";
    for (int i = 0; i < 3000; ++i)
        body += "<path d=\"M 20," + std::to_string(20 + i % 60) + " L 80," +
                std::to_string(20 + i % 60) + "\" clip-path=\"url(#c)\"/>";
    ReadOptions options;
    options.deadline = Clock::now() + std::chrono::milliseconds(300);
    const auto start = Clock::now();
    CHECK_THROWS_AS(read_svg(svg(body), options), ImportTimeout);
    CHECK(std::chrono::duration<double>(Clock::now() - start).count() < 2.0);
}
