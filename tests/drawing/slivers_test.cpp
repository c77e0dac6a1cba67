// Slivers: a piece shorter than the tolerance between arcs is merged into
// its neighbours, the chain staying joined, tangent-continuous where it
// was, and within the tolerance of what it replaced.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include <modsynth/drawing/import.h>
#include <modsynth/drawing/slivers.h>
#include <modsynth/drawing/svg_reader.h>
#include <modsynth/geometry/distance.h>

#include <Eigen/Geometry>

namespace {

using namespace modsynth::drawing;
using modsynth::geometry::Primitive;
using modsynth::geometry::PrimitiveKind;
using modsynth::geometry::Vec2;
namespace geometry = modsynth::geometry;

constexpr double kTolerance = 1e-4;

/// The arc from `start` about `center` by `sweep` radians (ccw > 0).
Primitive arc(const Vec2& start, const Vec2& center, double sweep) {
    const Vec2 r = start - center;
    const Vec2 end = center + Eigen::Rotation2D<double>(sweep).toRotationMatrix() * r;
    return geometry::make_arc(start, end, center, sweep > 0.0);
}

/// The arc that leaves where `p` ends, tangent to it, turning the same way
/// on a circle of `radius`, by `sweep`.
Primitive tangent_arc(const Primitive& p, double radius, double sweep) {
    const Vec2 t = geometry::tangent_at(p, geometry::length(p));
    const Vec2 normal = sweep > 0.0 ? geometry::perp(t) : Vec2(-geometry::perp(t));
    return arc(p.end, p.end + radius * normal, sweep);
}

double far_between(const std::vector<Primitive>& a, const std::vector<Primitive>& b) {
    double worst = 0.0;
    for (const auto& [from, to] : {std::pair{&a, &b}, std::pair{&b, &a}}) {
        for (const Primitive& p : *from) {
            for (int i = 0; i <= 200; ++i) {
                const Vec2 q = geometry::point_at(p, geometry::length(p) * i / 200.0);
                double best = 1e9;
                for (const Primitive& o : *to)
                    best = std::min(best, geometry::nearest(o, q).distance);
                worst = std::max(worst, best);
            }
        }
    }
    return worst;
}

double angle_between(const Vec2& a, const Vec2& b) {
    return std::atan2(geometry::cross(a, b), a.dot(b));
}

void check_joined(const std::vector<Primitive>& chain) {
    for (std::size_t i = 1; i < chain.size(); ++i)
        CHECK((chain[i].start - chain[i - 1].end).norm() <= 1e-12);
}

/// Imports an SVG and checks what the runs of slivers must leave: no
/// primitive shorter than the tolerance, every stroke joined within the
/// contract's 1e-6 m, and the result within the tolerance of the drawing,
/// sampled both ways. Returns the strokes.
std::vector<Chain> import_checked(const std::string& svg, const ImportOptions& o) {
    const ImportResult r = import_drawing(svg, DrawingFormat::Svg, o);
    CHECK(r.deviation <= o.tolerance);
    // The drawing, densely sampled in task metres.
    std::vector<std::vector<Vec2>> original;
    for (const Curve& c : read_svg(svg).curves) {
        std::vector<Vec2> pts;
        for (const Segment& seg : c.segments)
            for (int k = 0; k <= 4000; ++k) pts.push_back(r.placement(point(seg, k / 4000.0)));
        original.push_back(std::move(pts));
    }
    auto to_original = [&](const Vec2& q) {
        double best = 1e9;
        for (const auto& pts : original)
            for (std::size_t k = 1; k < pts.size(); ++k)
                best = std::min(best, geometry::point_segment(q, pts[k - 1], pts[k]));
        return best;
    };
    double far = 0.0;
    for (const Chain& stroke : r.strokes) {
        for (std::size_t i = 0; i < stroke.size(); ++i) {
            CHECK(geometry::length(stroke[i]) >= o.tolerance);
            if (i > 0) CHECK((stroke[i].start - stroke[i - 1].end).norm() <= 1e-6);
            const double len = geometry::length(stroke[i]);
            for (int k = 0; k <= 200; ++k)
                far = std::max(far, to_original(geometry::point_at(stroke[i], len * k / 200.0)));
        }
    }
    for (const auto& pts : original) {
        for (const Vec2& q : pts) {
            double best = 1e9;
            for (const Chain& stroke : r.strokes)
                for (const Primitive& p : stroke)
                    best = std::min(best, geometry::nearest(p, q).distance);
            far = std::max(far, best);
        }
    }
    // The polyline of samples lies within micrometres of the drawing.
    CHECK(far <= o.tolerance + 1e-7);
    return r.strokes;
}

/// One path, without units, placed at 1 mm a unit (tolerance 0.1 unit).
std::vector<Chain> import_checked(const std::string& path) {
    const std::string svg =
        R"(<svg xmlns="http://www.w3.org/2000/svg"><path fill="none" stroke="black" d=")" + path +
        R"("/></svg>)";
    ImportOptions o;
    o.placement.scale = 1e-3;
    o.placement.at = Vec2(0.3, 0.0);
    return import_checked(svg, o);
}

}  // namespace

TEST_CASE("Slivers: a run of tiny arcs (a 10 um wiggle after a corner) is replaced as a whole",
          "[drawing][slivers]") {
    // Three half circles of 10 um radius, alternating, between two lines:
    // each 31 um, smooth with each other, at a corner with the lines.
    const auto strokes = import_checked(
        "M 0 0 L 10 0 A 0.01 0.01 0 0 1 10.02 0 A 0.01 0.01 0 0 0 10.04 0 "
        "A 0.01 0.01 0 0 1 10.06 0 L 10.06 10");
    REQUIRE(strokes.size() == 1);
}

TEST_CASE("Slivers: a run of tiny arcs rounding a corner between two arcs", "[drawing][slivers]") {
    // A corner of two 5 mm arcs rounded by four arcs of 4 to 24 um radius.
    const auto strokes = import_checked(
        "M 0 0 A 5 5 0 0 1 5 5 A 0.024 0.024 0 0 1 5.02 5.02 A 0.004 0.004 0 0 0 5.025 5.025 "
        "A 0.012 0.012 0 0 1 5.04 5.03 A 0.02 0.02 0 0 1 5.05 5.01 A 5 5 0 0 0 10 0");
    REQUIRE(strokes.size() == 1);
}

TEST_CASE("Slivers: a loop smaller than the tolerance collapses to the point it sits at",
          "[drawing][slivers]") {
    // A circle of 20 um radius drawn within a stroke, touching it at (10, 0).
    const auto strokes =
        import_checked("M 0 0 L 10 0 A 0.02 0.02 0 0 1 10 -0.04 A 0.02 0.02 0 0 1 10 0 L 20 3");
    REQUIRE(strokes.size() == 1);
    CHECK(strokes[0].size() == 2);
}

TEST_CASE("Slivers: a short line past a corner at a stroke's end", "[drawing][slivers]") {
    SECTION("after an arc") {
        const auto strokes = import_checked("M 0 0 A 5 5 0 0 1 10 0 L 10 0.05");
        REQUIRE(strokes.size() == 1);
    }
    SECTION("after a line, at a sharp corner") { import_checked("M 0 0 L 10 0 L 9.95 0.04"); }
    SECTION("at the stroke's start") { import_checked("M 0 0.06 L 0 0 A 5 5 0 0 0 10 0"); }
}

TEST_CASE("Slivers: a stroke shorter than the tolerance may stay that short",
          "[drawing][slivers]") {
    std::vector<Primitive> chain{geometry::make_line(Vec2(0.3, 0.0), Vec2(0.30003, 0.0)),
                                 geometry::make_line(Vec2(0.30003, 0.0), Vec2(0.30003, 3e-5))};
    const std::vector<Primitive> before = chain;
    merge_slivers(chain, kTolerance, 0.0);
    REQUIRE(!chain.empty());
    CHECK(chain.front().start == before.front().start);
    CHECK((chain.back().end - before.back().end).norm() <= kTolerance);
    check_joined(chain);
}

TEST_CASE("Slivers: a short arc between two arcs becomes a biarc, smooth throughout",
          "[drawing][slivers]") {
    const Primitive a = arc(Vec2(0.3, -0.01), Vec2(0.3, 0.0), 1.2);
    const Primitive sliver = tangent_arc(a, 0.005, 2e-5 / 0.005);  // 20 um
    const Primitive b = tangent_arc(sliver, 0.02, 0.5);
    const std::vector<Primitive> before{a, sliver, b};
    std::vector<Primitive> chain = before;
    const double deviation = merge_slivers(chain, kTolerance, 0.0);
    for (const Primitive& p : chain) CHECK(geometry::length(p) >= kTolerance);
    check_joined(chain);
    CHECK((chain.front().start - before.front().start).norm() <= 1e-12);
    CHECK((chain.back().end - before.back().end).norm() <= 1e-12);
    for (std::size_t i = 1; i < chain.size(); ++i) {
        CHECK(std::abs(
                  angle_between(geometry::tangent_at(chain[i - 1], geometry::length(chain[i - 1])),
                                geometry::tangent_at(chain[i], 0.0))) <= 1e-9);
    }
    // Within the tolerance of the chain it replaced, as it says.
    const double far = far_between(before, chain);
    CHECK(far <= deviation + 1e-9);
    CHECK(deviation <= kTolerance);
}

TEST_CASE("Slivers: next to a corner, folded into the smooth side; the corner stays",
          "[drawing][slivers]") {
    const Primitive line = geometry::make_line(Vec2(0.2, 0.0), Vec2(0.3, 0.0));
    // A corner of 90 degrees, then a sliver and the arc it meets smoothly.
    const Primitive sliver = arc(Vec2(0.3, 0.0), Vec2(0.29, 0.0), 3e-5 / 0.01);
    const Primitive b = tangent_arc(sliver, 0.01, 1.0);
    std::vector<Primitive> chain{line, sliver, b};
    const double deviation = merge_slivers(chain, kTolerance, 2e-5);
    REQUIRE(chain.size() == 3);
    CHECK(chain[0].end == line.end);
    CHECK(chain[1].start == line.end);
    for (const Primitive& p : chain) CHECK(geometry::length(p) >= kTolerance);
    check_joined(chain);
    // The corner is still a corner, the arc's far end still smooth with
    // what the rest of the arc was.
    CHECK(std::abs(angle_between(Vec2(1.0, 0.0), geometry::tangent_at(chain[1], 0.0))) > 1.0);
    CHECK(std::abs(angle_between(geometry::tangent_at(chain[1], geometry::length(chain[1])),
                                 geometry::tangent_at(chain[2], 0.0))) <= 1e-9);
    CHECK(deviation <= kTolerance);
    CHECK(deviation >= 2e-5);
}

TEST_CASE("Slivers: at a stroke's end, folded into the piece before it", "[drawing][slivers]") {
    const Primitive a = arc(Vec2(0.3, -0.01), Vec2(0.3, 0.0), 1.0);
    const Primitive sliver = tangent_arc(a, 0.004, -1e-5 / 0.004);  // the other way round
    std::vector<Primitive> chain{a, sliver};
    merge_slivers(chain, kTolerance, 0.0);
    REQUIRE(chain.size() == 2);
    CHECK((chain.front().start - a.start).norm() <= 1e-12);
    CHECK((chain.back().end - sliver.end).norm() <= 1e-12);
    for (const Primitive& p : chain) CHECK(geometry::length(p) >= kTolerance);
    check_joined(chain);
}

TEST_CASE("Slivers: kept when merging would stray past the tolerance", "[drawing][slivers]") {
    const Primitive a = arc(Vec2(0.3, -0.01), Vec2(0.3, 0.0), 1.2);
    const Primitive sliver = tangent_arc(a, 0.005, 2e-5 / 0.005);
    const Primitive b = tangent_arc(sliver, 0.02, 0.5);
    // The fitting already used all of the tolerance: nothing is left.
    std::vector<Primitive> chain{a, sliver, b};
    CHECK(merge_slivers(chain, kTolerance, kTolerance) == kTolerance);
    CHECK(chain.size() == 3);
    // A stroke out and back within the tolerance is not merged into a
    // piece of no length.
    std::vector<Primitive> back{geometry::make_line(Vec2(0.3, 0.0), Vec2(0.30001, 0.0)),
                                geometry::make_line(Vec2(0.30001, 0.0), Vec2(0.3, 0.0))};
    merge_slivers(back, kTolerance, 0.0);
    REQUIRE(back.size() == 2);
    for (const Primitive& p : back) CHECK(geometry::length(p) > 0.0);
    // A stroke that is one short piece stays.
    std::vector<Primitive> dot{geometry::make_line(Vec2(0.3, 0.0), Vec2(0.30001, 0.0))};
    merge_slivers(dot, kTolerance, 0.0);
    CHECK(dot.size() == 1);
}

TEST_CASE("Slivers: an imported path's short arc between arcs is merged", "[drawing][slivers]") {
    // Two quarter circles and, between them, an arc of 5 um (a path
    // optimiser's leftover), in millimetres.
    const std::string svg =
        "<svg xmlns='http://www.w3.org/2000/svg' width='100mm' height='100mm' "
        "viewBox='0 0 100 100'><path fill='none' stroke='black' "
        "d='M 10,50 A 20,20 0 0 1 30,30 A 15,15 0 0 1 30.005,30.0000008 A 25,25 0 0 1 "
        "55,55'/></svg>";
    ImportOptions options;
    options.placement.scale = 1e-3;
    const ImportResult r = import_drawing(svg, DrawingFormat::Svg, options);
    REQUIRE(r.strokes.size() == 1);
    for (const Primitive& p : r.strokes[0]) CHECK(geometry::length(p) >= options.tolerance);
    check_joined(r.strokes[0]);
    CHECK(r.deviation <= options.tolerance);
}

TEST_CASE("Slivers: a deadline that has passed stops merging with the time limit's error",
          "[drawing][slivers]") {
    // Half a circle of 2 mm radius drawn as 64 lines of 98 um (a CAD
    // polyline), as one curve and as one stroke of curves joined end to end.
    Curve polyline{"LWPOLYLINE (layer 0, handle 2A)", {}};
    std::vector<Primitive> chain;
    for (int k = 0; k < 64; ++k) {
        const auto at = [](int i) {
            const double a = geometry::kPi * i / 64.0;
            return Vec2(0.3 + 0.002 * std::cos(a), 0.002 * std::sin(a));
        };
        polyline.segments.push_back(LineSegment{at(k), at(k + 1)});
        chain.push_back(geometry::make_line(at(k), at(k + 1)));
    }
    const std::vector<Curve> drawing{polyline};
    // Without one, the run is merged: the work the deadline cuts short.
    std::vector<Primitive> merged = chain;
    merge_slivers(merged, kTolerance, 0.0, drawing);
    CHECK(merged.size() < chain.size());
    for (const Primitive& p : merged) CHECK(geometry::length(p) >= kTolerance);

    std::vector<Primitive> late = chain;
    CHECK_THROWS_WITH(merge_slivers(late, kTolerance, 0.0, drawing, Clock::now()),
                      Catch::Contains("time limit") && Catch::Contains("merging") &&
                          Catch::Contains("LWPOLYLINE (layer 0, handle 2A)"));
    std::vector<std::vector<Primitive>> strokes{chain};
    CHECK_THROWS_AS(merge_stroke_slivers(strokes, kTolerance, 0.0, drawing, Clock::now()),
                    ImportTimeout);
    // A chain with nothing to merge is not held up by it.
    std::vector<Primitive> plain{merged};
    CHECK_NOTHROW(merge_slivers(plain, kTolerance, 0.0, drawing, Clock::now()));
    CHECK(plain.size() == merged.size());
}

TEST_CASE("Slivers: a hairpin whose tip the fitting rounds within the tolerance becomes a cusp",
          "[drawing][slivers]") {
    // A narrow spike of one cubic (an outline of a filled shape): the fit
    // rounds its tip with an arc of a few tens of micrometres and leaves
    // no room to cut it shorter; its sides meet at the drawing's tip.
    for (const std::string path :
         {"M 0,0.3 C 12,0.3 12,-0.3 0,-0.3", "M 0,0.25 C 10,0.25 10,-0.25 0,-0.25",
          "M 0,0.2 C 16,0.2 16,-0.2 0,-0.2"}) {
        INFO(path);
        const std::string svg =
            R"(<svg xmlns="http://www.w3.org/2000/svg" width="40mm" height="40mm" )"
            R"(viewBox="0 0 40 40"><path fill="none" stroke="black" d=")" +
            path + R"("/></svg>)";
        ImportOptions o;
        o.placement.at = Vec2(0.3, 0.0);
        CHECK(import_checked(svg, o).size() == 1);
    }
}

namespace {

/// Each piece as a curve of its own, as a DXF drawing of LINE entities is.
std::vector<Curve> drawn_as_lines(const std::vector<std::vector<Primitive>>& strokes) {
    std::vector<Curve> out;
    for (const auto& stroke : strokes)
        for (const Primitive& p : stroke)
            out.push_back(Curve{"LINE", {LineSegment{p.start, p.end}}});
    return out;
}

}  // namespace

TEST_CASE("Slivers: another stroke keeps drawn what it runs beside", "[drawing][slivers]") {
    // A stroke starting in three lines of 25 um (a letter's serif) before
    // it turns, and another stroke running beside them 90 um to the left
    // (the letter's other side): that stroke's drawing lies within the
    // tolerance of the short lines, and farther than that from whatever
    // replaces them, but it is the other stroke that draws it.
    const std::vector<Primitive> letter{
        geometry::make_line(Vec2(0.3, 0.0), Vec2(0.3, 2.5e-5)),
        geometry::make_line(Vec2(0.3, 2.5e-5), Vec2(0.3, 5e-5)),
        geometry::make_line(Vec2(0.3, 5e-5), Vec2(0.3, 7.5e-5)),
        geometry::make_line(Vec2(0.3, 7.5e-5), Vec2(0.301, 7.5e-5))};
    const std::vector<Primitive> side{
        geometry::make_line(Vec2(0.29991, -1e-3), Vec2(0.29991, 7.5e-5))};
    std::vector<std::vector<Primitive>> strokes{letter, side};
    const std::vector<Curve> drawing = drawn_as_lines(strokes);
    const double deviation = merge_stroke_slivers(strokes, kTolerance, 0.0, drawing);
    CHECK(deviation <= kTolerance);
    REQUIRE(strokes.size() == 2);
    for (const Primitive& p : strokes[0]) CHECK(geometry::length(p) >= kTolerance);
    check_joined(strokes[0]);
    CHECK(far_between(strokes[0], letter) <= kTolerance);
    CHECK(strokes[1].size() == 1);
}

TEST_CASE("Slivers: short pieces before a run merged later are merged once it is",
          "[drawing][slivers]") {
    // A spline's end drawn as 12 lines shrinking from 12 to 1 um (78 um in
    // all), bending into a long line: from its first piece the run is
    // longer than one stretch replaces and shorter than the tolerance as a
    // whole, from its fourth it folds into the line; what is left before
    // is then a short run of its own.
    std::vector<Vec2> pts;
    const auto bend = [](double x) {
        const double u = 1.0 - x / 78e-6;
        return Vec2(0.3 + x, 1e-5 * u * u);
    };
    double x = 0.0;
    for (int gap = 12; gap >= 1; --gap) {
        pts.push_back(bend(x));
        x += gap * 1e-6;
    }
    pts.push_back(bend(x));
    std::vector<Primitive> stroke;
    for (std::size_t k = 1; k < pts.size(); ++k)
        stroke.push_back(geometry::make_line(pts[k - 1], pts[k]));
    stroke.push_back(geometry::make_line(pts.back(), pts.back() + Vec2(5e-4, 0.0)));
    const std::vector<Primitive> before = stroke;
    REQUIRE(before.size() == 13);
    std::vector<std::vector<Primitive>> strokes{stroke};
    const std::vector<Curve> drawing = drawn_as_lines(strokes);
    CHECK(merge_stroke_slivers(strokes, kTolerance, 0.0, drawing) <= kTolerance);
    for (const Primitive& p : strokes[0]) CHECK(geometry::length(p) >= kTolerance);
    check_joined(strokes[0]);
    CHECK(far_between(strokes[0], before) <= kTolerance);
}
