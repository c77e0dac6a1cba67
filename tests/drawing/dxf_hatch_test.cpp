// HATCH boundaries traced on request: polyline paths with bulges and edge
// paths (lines, arcs either way round, elliptic arcs, splines), read from
// the DXF's groups, as closed curves where the hatch's boundary is closed.
#include <catch2/catch.hpp>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include <modsynth/drawing/dxf_reader.h>
#include <modsynth/task/input_error.h>

#include "../support/fixtures.h"

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

std::string dxf(const std::string& entities, const std::string& blocks = "") {
    return "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n" +
           (blocks.empty() ? std::string() : "0\nSECTION\n2\nBLOCKS\n" + blocks + "0\nENDSEC\n") +
           "0\nSECTION\n2\nENTITIES\n" + entities + "0\nENDSEC\n0\nEOF\n";
}

std::string fixture() {
    std::ifstream in(modsynth::testing::source_path("tests/fixtures/drawings/hatches.dxf"));
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

ReadOptions traced() {
    ReadOptions o;
    o.hatch_boundaries = true;
    return o;
}

/// The largest gap between a segment's end and the next one's start, and
/// between the last end and the first start (0 for a closed curve).
double closing_gap(const Curve& c) {
    double worst = (start_point(c.segments.front()) - end_point(c.segments.back())).norm();
    for (std::size_t i = 1; i < c.segments.size(); ++i)
        worst = std::max(worst, (start_point(c.segments[i]) - end_point(c.segments[i - 1])).norm());
    return worst;
}

Vec2 midpoint(const Segment& s) { return point(s, 0.5); }

}  // namespace

TEST_CASE("HATCH: skipped with a warning that names the option, unless asked for",
          "[drawing][dxf][hatch]") {
    CHECK_THAT(message_of([] { read_dxf(fixture()); }),
               Catch::Contains("nothing to draw") && Catch::Contains("HATCH #1 (layer outline)") &&
                   Catch::Contains("--hatch-boundaries"));
}

TEST_CASE("HATCH: both kinds of boundary path are traced, closed", "[drawing][dxf][hatch]") {
    const Drawing d = read_dxf(fixture(), traced());
    CHECK(d.warnings.empty());
    // The D and its hole, the quarter disc, the half ellipse, the spline.
    REQUIRE(d.curves.size() == 5);
    for (const Curve& c : d.curves) {
        INFO(c.source);
        CHECK(closing_gap(c) < 1e-9);
    }
    // The polyline path: three lines and the half circle its bulge of 1
    // makes, out to x = 40 through (40, 10).
    const Curve& outer = d.curves[0];
    CHECK(outer.source == "HATCH #1 (layer outline) boundary path 1");
    REQUIRE(outer.segments.size() == 4);
    const auto* half = std::get_if<EllipticArc>(&outer.segments[1]);
    REQUIRE(half);
    CHECK(midpoint(outer.segments[1]).isApprox(Vec2(40.0, 10.0), 1e-12));
    // The edge path of one arc of a whole turn: a circle round (12, 10).
    const Curve& hole = d.curves[1];
    CHECK(hole.source == "HATCH #1 (layer outline) boundary path 2");
    REQUIRE(hole.segments.size() == 1);
    CHECK(midpoint(hole.segments[0]).isApprox(Vec2(7.0, 10.0), 1e-12));
    // Clockwise, the arc edge's angles are 360 minus the true ones: the
    // quarter from (50, 10) to (60, 0), not the three quarters round.
    const Curve& quarter = d.curves[2];
    REQUIRE(quarter.segments.size() == 3);
    CHECK(start_point(quarter.segments[1]).isApprox(Vec2(50.0, 10.0), 1e-12));
    CHECK(midpoint(quarter.segments[1])
              .isApprox(Vec2(50.0 + 10.0 / std::sqrt(2.0), 10.0 / std::sqrt(2.0)), 1e-12));
    // The elliptic arc starts on the ray at 45 degrees from its centre (the
    // line edge before it ends there), not at the parameter 45 degrees.
    const Curve& ellipse = d.curves[3];
    REQUIRE(ellipse.segments.size() == 3);
    const Vec2 from = start_point(ellipse.segments[1]) - Vec2(85.0, 10.0);
    CHECK(from.x() == Approx(from.y()));
    CHECK(end_point(ellipse.segments[1]).isApprox(Vec2(65.0, 10.0), 1e-12));
    // The spline edge, through its middle control point's pull.
    const Curve& spline = d.curves[4];
    REQUIRE(spline.segments.size() == 2);
    REQUIRE(std::get_if<BSpline>(&spline.segments[0]));
    CHECK(midpoint(spline.segments[0]).isApprox(Vec2(120.0, 10.0), 1e-12));
}

TEST_CASE("HATCH: seed points and pattern lines after the paths are not boundary",
          "[drawing][dxf][hatch]") {
    // One path of two vertices (a line there and back), then the seed point
    // (98, 10/20) a lax reader would take for a third vertex.
    const std::string hatch =
        "0\nHATCH\n8\n0\n10\n0\n20\n0\n30\n0\n2\nSOLID\n70\n1\n71\n0\n91\n1\n92\n2\n72\n0\n73\n"
        "1\n93\n3\n10\n0\n20\n0\n10\n10\n20\n0\n10\n10\n20\n10\n97\n0\n75\n0\n76\n1\n98\n1\n10\n"
        "500\n20\n500\n";
    const Drawing d = read_dxf(dxf(hatch), traced());
    REQUIRE(d.curves.size() == 1);
    CHECK(d.curves[0].segments.size() == 3);
    for (const Segment& s : d.curves[0].segments) {
        CHECK(start_point(s).maxCoeff() <= 10.0);
        CHECK(end_point(s).maxCoeff() <= 10.0);
    }
}

TEST_CASE("HATCH: in blocks, on layers, mirrored", "[drawing][dxf][hatch]") {
    const std::string square =
        "91\n1\n92\n1\n93\n4\n72\n1\n10\n0\n20\n0\n11\n5\n21\n0\n72\n1\n10\n5\n20\n0\n11\n5\n21\n"
        "5\n72\n1\n10\n5\n20\n5\n11\n0\n21\n5\n72\n1\n10\n0\n20\n5\n11\n0\n21\n0\n97\n0\n75\n0\n"
        "76\n1\n";
    const std::string block = "0\nBLOCK\n8\n0\n2\nB\n70\n0\n10\n0\n20\n0\n0\nHATCH\n8\n0\n" +
                              square + "0\nENDBLK\n8\n0\n";
    const std::string inserts =
        "0\nINSERT\n8\nparts\n2\nB\n10\n100\n20\n0\n"
        "0\nINSERT\n8\nparts\n2\nB\n10\n200\n20\n0\n";
    const Drawing d = read_dxf(dxf(inserts + "0\nHATCH\n8\nfill\n" + square, block), traced());
    REQUIRE(d.curves.size() == 3);
    CHECK(d.curves[0].source == "HATCH #3 (layer fill) boundary path 1");
    CHECK_THAT(d.curves[1].source,
               Catch::Contains("HATCH #1 of block B boundary path 1 in INSERT #1 (layer parts)"));
    CHECK(start_point(d.curves[2].segments[0]).isApprox(Vec2(200.0, 0.0)));
    // Only the layers asked for: the inserts' layer.
    ReadOptions parts = traced();
    parts.layers = {"parts"};
    CHECK(read_dxf(dxf(inserts + "0\nHATCH\n8\nfill\n" + square, block), parts).curves.size() == 2);
    // An extrusion pointing down turns the hatch's coordinates over.
    const Drawing m = read_dxf(dxf("0\nHATCH\n8\n0\n210\n0\n220\n0\n230\n-1\n" + square), traced());
    REQUIRE(m.curves.size() == 1);
    CHECK(end_point(m.curves[0].segments[0]).isApprox(Vec2(-5.0, 0.0)));
    // On the obstacle layer a hatch fills an obstacle: skipped, as before.
    ReadOptions obstacles = traced();
    obstacles.obstacle_layer = "fill";
    const Drawing o = read_dxf(
        dxf("0\nLINE\n8\n0\n10\n0\n20\n0\n11\n9\n21\n0\n0\nHATCH\n8\nfill\n" + square), obstacles);
    CHECK(o.curves.size() == 1);
    REQUIRE(o.warnings.size() == 1);
    CHECK_THAT(o.warnings[0], Catch::Contains("HATCH #2 (layer fill)"));
}

TEST_CASE("HATCH: what cannot be traced is named, a malformed boundary refused",
          "[drawing][dxf][hatch]") {
    // A spline edge given by fit points only: left out by name (the line
    // edge is drawn), refused with --strict.
    const std::string fit_only =
        "0\nHATCH\n8\n0\n91\n1\n92\n1\n93\n2\n72\n1\n10\n0\n20\n0\n11\n10\n21\n0\n72\n4\n94\n3\n"
        "73\n0\n74\n0\n95\n0\n96\n0\n97\n3\n11\n10\n21\n0\n11\n5\n21\n5\n11\n0\n21\n0\n97\n0\n75\n"
        "0\n76\n1\n";
    const Drawing d = read_dxf(dxf(fit_only), traced());
    REQUIRE(d.curves.size() == 1);
    REQUIRE(d.warnings.size() == 1);
    CHECK_THAT(d.warnings[0], Catch::Contains("HATCH #1 (layer 0) boundary path 1, edge 2 "
                                              "(line 36): a spline given by fit points only"));
    ReadOptions strict = traced();
    strict.strict = true;
    CHECK_THAT(message_of([&] { read_dxf(dxf(fit_only), strict); }),
               Catch::Contains("cannot be drawn: HATCH edges"));
    // Counts that do not match what follows, and unknown edges: refused
    // naming the hatch, the path and the line.
    CHECK_THAT(
        message_of([&] {
            read_dxf(
                dxf("0\nHATCH\n8\n0\n91\n1\n92\n2\n93\n3\n10\n0\n20\n0\n10\n1\n20\n0\n75\n0\n"),
                traced());
        }),
        Catch::Contains("HATCH #1 (layer 0): boundary path 1 (line 22): group code 93 declares 3 "
                        "vertices, but 2 follow"));
    CHECK_THAT(message_of([&] {
                   read_dxf(dxf("0\nHATCH\n8\n0\n91\n2\n92\n1\n93\n1\n72\n1\n10\n0\n20\n0\n11\n1\n"
                                "21\n0\n75\n0\n"),
                            traced());
               }),
               Catch::Contains("group code 91 declares 2 boundary paths, but 1 follow"));
    CHECK_THAT(message_of([&] {
                   read_dxf(
                       dxf("0\nHATCH\n8\n0\n91\n1\n92\n1\n93\n1\n72\n9\n10\n0\n20\n0\n75\n0\n"),
                       traced());
               }),
               Catch::Contains("edge 1 (line 26): edge type 9"));
    CHECK_THAT(message_of([&] {
                   read_dxf(dxf("0\nHATCH\n8\n0\n91\n1\n92\n1\n93\n1\n72\n2\n10\n0\n20\n0\n40\n-2\n"
                                "50\n0\n51\n90\n73\n1\n75\n0\n"),
                            traced());
               }),
               Catch::Contains("radius -2: it must be positive"));
    // Not asked for, a malformed boundary is skipped with the hatch.
    const Drawing quiet = read_dxf(
        dxf("0\nLINE\n8\n0\n10\n0\n20\n0\n11\n9\n21\n0\n0\nHATCH\n8\n0\n91\n1\n92\n1\n93\n1\n72\n"
            "9\n75\n0\n"));
    CHECK(quiet.curves.size() == 1);
}
