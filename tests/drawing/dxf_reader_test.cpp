// The DXF reader against files that dxflib alone misreads or never finishes:
// every one is read as written or refused naming the entity and the value.
#include <catch2/catch.hpp>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include <modsynth/drawing/biarc_fit.h>
#include <modsynth/drawing/dxf_reader.h>
#include <modsynth/drawing/import.h>
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

/// A DXF in millimetres whose ENTITIES section holds `entities` (group
/// lines, each ending in a newline).
std::string dxf(const std::string& entities) {
    return "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n" +
           entities + "0\nENDSEC\n0\nEOF\n";
}

const std::string kLine = "0\nLINE\n8\n0\n10\n0\n20\n0\n11\n100\n21\n0\n";

}  // namespace

TEST_CASE("DXF: lines longer than dxflib's buffer", "[drawing][dxf]") {
    // A comment of any length is dropped: the rest is read.
    const Drawing d = read_dxf("999\n" + std::string(5000, 'c') + "\n" + dxf(kLine));
    CHECK(d.curves.size() == 1);
    // Any other long line is refused by its number (dxflib would spin).
    const std::string layer(2000, 'L');
    const std::string text = dxf("0\nLINE\n8\n" + layer + "\n10\n0\n20\n0\n11\n1\n21\n0\n");
    CHECK_THAT(message_of([&] { read_dxf(text); }),
               Catch::Contains("LINE (line 18)") && Catch::Contains("2000 characters"));
}

TEST_CASE("DXF: group codes are integers, leading zeros and all", "[drawing][dxf]") {
    // "090" is group code 90: its count is checked as any other.
    const std::string huge =
        dxf("0\nLWPOLYLINE\n8\n0\n090\n200000000\n10\n0\n20\n0\n10\n1\n20\n1\n");
    CHECK_THAT(message_of([&] { read_dxf(huge); }),
               Catch::Contains("LWPOLYLINE (line 20)") && Catch::Contains("declares 200000000"));
    for (const char* code : {"072", "073", "0072"}) {
        const std::string spline =
            dxf(std::string("0\nSPLINE\n8\n0\n71\n3\n") + code + "\n150000000\n");
        CHECK_THAT(message_of([&] { read_dxf(spline); }), Catch::Contains("declares 150000000"));
    }
    // A sound polyline written the same way is read.
    const Drawing d =
        read_dxf(dxf("0\nLWPOLYLINE\n8\n0\n090\n3\n070\n0\n010\n0\n020\n0\n010\n10\n"
                     "020\n0\n010\n10\n020\n10\n"));
    REQUIRE(d.curves.size() == 1);
    CHECK(d.curves[0].segments.size() == 2);
    CHECK_THAT(message_of([&] { read_dxf(dxf("0\nLINE\n1x0\n0\n")); }),
               Catch::Contains("'1x0' is not a group code"));
}

TEST_CASE("DXF: a count is a count of the items that follow", "[drawing][dxf]") {
    CHECK_THAT(message_of([&] { read_dxf(dxf("0\nSPLINE\n8\n0\n71\n3\n72\n-5\n")); }),
               Catch::Contains("SPLINE (line 22)") && Catch::Contains("count of -5") &&
                   Catch::Contains("cannot be negative"));
    // dxflib would overwrite the last vertex with the ones past the count.
    const std::string more =
        dxf("0\nLWPOLYLINE\n8\n0\n90\n2\n10\n0\n20\n0\n10\n1\n20\n0\n10\n2\n20\n5\n");
    CHECK_THAT(message_of([&] { read_dxf(more); }),
               Catch::Contains("declares 2 items, but 3 follow (group code 10)"));
}

TEST_CASE("DXF: numbers are whole, finite numbers", "[drawing][dxf]") {
    for (const char* bad : {"abc", "10xyz", "nan", "inf", "-inf", "1e400", "", "1,5", "0x10"}) {
        INFO(bad);
        const std::string text =
            dxf(std::string("0\nLINE\n8\n0\n10\n") + bad + "\n20\n0\n11\n100\n21\n0\n");
        const std::string m = message_of([&] { read_dxf(text); });
        CHECK_THAT(m, Catch::Contains("LINE (line 20)") &&
                          Catch::Contains("group code 10 is '" + std::string(bad) + "'"));
    }
    const std::string arc = dxf("0\nARC\n8\n0\n10\n0\n20\n0\n40\n5\n50\n0\n51\ninf\n");
    CHECK_THAT(message_of([&] { read_dxf(arc); }),
               Catch::Contains("group code 51 is 'inf', not a finite number"));
    CHECK_THAT(message_of([&] { read_dxf(dxf("0\nLWPOLYLINE\n8\n0\n90\n2.5\n")); }),
               Catch::Contains("group code 90 is '2.5', not an integer"));
    // Spaces around a number and a leading '+' are what dxflib reads too.
    const Drawing d = read_dxf(dxf("0\nLINE\n8\n0\n10\n  +1.5 \n20\n0\n11\n1e2\n21\n0\n"));
    REQUIRE(d.curves.size() == 1);
    CHECK(start_point(d.curves[0].segments[0]).x() == 1.5);
}

TEST_CASE("DXF: entities that would be drawn wrong are refused", "[drawing][dxf]") {
    // A negative radius would turn the arc half a turn.
    CHECK_THAT(
        message_of([&] { read_dxf(dxf("0\nARC\n8\n0\n10\n0\n20\n0\n40\n-5\n50\n0\n51\n90\n")); }),
        Catch::Contains("ARC #1 (layer 0)") && Catch::Contains("radius -5"));
    CHECK_THAT(message_of([&] { read_dxf(dxf("0\nCIRCLE\n8\n0\n10\n0\n20\n0\n40\n-2\n")); }),
               Catch::Contains("CIRCLE #1") && Catch::Contains("radius -2"));
    // A ratio of 0 would draw the major axis back and forth.
    const std::string flat =
        dxf("0\nELLIPSE\n8\n0\n10\n0\n20\n0\n11\n10\n21\n0\n40\n0\n41\n0\n42\n6.283185307179586\n");
    CHECK_THAT(message_of([&] { read_dxf(flat); }),
               Catch::Contains("ELLIPSE #1") && Catch::Contains("axis ratio 0"));
    // Angles many turns apart are still less than a turn of arc.
    const Drawing d = read_dxf(dxf("0\nARC\n8\n0\n10\n0\n20\n0\n40\n5\n50\n720\n51\n810\n"));
    const auto& e = std::get<EllipticArc>(d.curves[0].segments[0]);
    CHECK(e.t1 - e.t0 == Approx(M_PI / 2));
}

TEST_CASE("DXF: a file cut off inside an entity is refused", "[drawing][dxf]") {
    std::string lines;
    for (int i = 0; i < 6; ++i)
        lines += "0\nLINE\n8\n0\n10\n" + std::to_string(10 * i) + "\n20\n0\n11\n" +
                 std::to_string(10 * i + 5) + "\n21\n0\n";
    const std::string whole = dxf(lines);
    CHECK(read_dxf(whole).curves.size() == 6);
    const std::string cut = whole.substr(0, whole.rfind("0\nENDSEC") - 4);
    CHECK_THAT(message_of([&] { read_dxf(cut); }),
               Catch::Contains("LINE") && Catch::Contains("without EOF: it is cut off"));
    const std::string no_endsec = whole.substr(0, whole.rfind("0\nENDSEC")) + "0\nEOF\n";
    CHECK_THAT(message_of([&] { read_dxf(no_endsec); }), Catch::Contains("no ENDSEC"));
}

TEST_CASE("DXF: names from the file are printed escaped", "[drawing][dxf]") {
    const std::string text = dxf("0\nLINE\n8\nla\x1b]0;x\x07yer\n10\n0\n20\n0\n11\n0\n21\n0\n");
    const std::string m = message_of([&] { read_dxf(text); });
    CHECK_THAT(m, Catch::Contains("la\\x1B]0;x\\x07yer"));
    CHECK(m.find('\x1b') == std::string::npos);
}

TEST_CASE("DXF: near-straight bulges import as lines", "[drawing][dxf]") {
    for (const char* bulge : {"1e-10", "1e-6", "-1e-300"}) {
        INFO(bulge);
        const std::string text =
            dxf(std::string("0\nLWPOLYLINE\n8\n0\n90\n2\n70\n0\n10\n0\n20\n0\n42\n") + bulge +
                "\n10\n500\n20\n0\n");
        ImportOptions o;
        const ImportResult r = import_drawing(text, DrawingFormat::Dxf, o);
        REQUIRE(r.strokes.size() == 1);
        CHECK(r.deviation <= o.tolerance);
        // A bulge of 1e-6 is an arc about a centre 125 km out: its end points
        // are computed through it, to about 1e-11 m.
        CHECK((r.strokes[0].front().start - Vec2(0.0, 0.0)).norm() <= 1e-9);
        CHECK((r.strokes[0].back().end - Vec2(0.5, 0.0)).norm() <= 1e-9);
    }
}

TEST_CASE("DXF: entities dxflib does not know are named, not skipped", "[drawing][dxf]") {
    // dxflib skips an entity type it does not know without a word.
    const std::string text = dxf(kLine + "0\nREGION\n8\n0\n0\nREGION\n8\n0\n0\n3DSOLID\n8\n0\n" +
                                 "0\nATTDEF\n8\n0\n0\nVIEWPORT\n8\n0\n");
    ReadOptions strict;
    strict.strict = true;
    CHECK_THAT(message_of([&] { read_dxf(text, strict); }),
               Catch::Contains("entities that cannot be drawn: 3DSOLID, ATTDEF, REGION (2x)"));
    // Without --strict they are skipped, by name and line, and the rest drawn.
    const Drawing d = read_dxf(text);
    CHECK(d.curves.size() == 1);
    REQUIRE(d.warnings.size() == 1);
    CHECK_THAT(d.warnings[0], Catch::Contains("3DSOLID (line 36)") &&
                                  Catch::Contains("REGION (line 28), REGION (line 32)"));
    // Inside a block they are the block's (drawn only where inserted).
    const std::string block =
        "0\nSECTION\n2\nBLOCKS\n0\nBLOCK\n8\n0\n2\nB\n0\nREGION\n8\n0\n0\nENDBLK\n8\n0\n0\nENDSEC"
        "\n";
    std::string blocks_first = dxf(kLine);
    blocks_first.insert(blocks_first.find("0\nSECTION\n2\nENTITIES"), block);
    CHECK(read_dxf(blocks_first).curves.size() == 1);
    // An entity's name with spaces around it is the entity.
    CHECK(read_dxf(dxf("0\n LINE \n8\n0\n10\n0\n20\n0\n11\n100\n21\n0\n")).curves.size() == 1);
}

TEST_CASE("DXF: a POLYLINE's VERTEX entities are its vertices", "[drawing][dxf]") {
    // The classic (R12) form: the header, one VERTEX entity per vertex, SEQEND.
    std::string vertices;
    const double xs[] = {0, 10, 10, 0};
    const double ys[] = {0, 0, 10, 10};
    for (int i = 0; i < 4; ++i) {
        vertices += "0\nVERTEX\n8\n0\n10\n" + std::to_string(xs[i]) + "\n20\n" +
                    std::to_string(ys[i]) + "\n30\n0\n" + (i == 1 ? "42\n1\n" : "");
    }
    const std::string closed = dxf("0\nPOLYLINE\n8\n0\n66\n1\n10\n0\n20\n0\n30\n0\n70\n1\n" +
                                   vertices + "0\nSEQEND\n8\n0\n" + kLine);
    const Drawing d = read_dxf(closed);
    REQUIRE(d.curves.size() == 2);
    CHECK(d.curves[0].source.rfind("POLYLINE #1", 0) == 0);
    REQUIRE(d.curves[0].segments.size() == 4);
    // The bulge of 1 at the second vertex: a half circle from (10,0) to (10,10).
    CHECK(std::holds_alternative<EllipticArc>(d.curves[0].segments[1]));
    CHECK((end_point(d.curves[0].segments[3]) - Vec2(0, 0)).norm() < 1e-12);
    // Open, and the last entity of its section.
    const std::string open =
        dxf("0\nPOLYLINE\n8\n0\n66\n1\n10\n0\n20\n0\n30\n0\n70\n0\n" + vertices + "0\nSEQEND\n");
    REQUIRE(read_dxf(open).curves.size() == 1);
    CHECK(read_dxf(open).curves[0].segments.size() == 3);
    CHECK_THAT(message_of([&] {
                   read_dxf(
                       dxf("0\nPOLYLINE\n8\n0\n66\n1\n70\n0\n0\nVERTEX\n8\n0\n10\n1\n20\n1\n"
                           "0\nSEQEND\n"));
               }),
               Catch::Contains("POLYLINE #1") && Catch::Contains("at least 2 vertices"));
}

TEST_CASE("DXF: what cannot be traced is skipped with one warning, or refused with strict",
          "[drawing][dxf]") {
    std::string entities = kLine;
    for (int i = 0; i < 5; ++i) entities += "0\nHATCH\n8\nfill\n10\n0\n20\n0\n";
    entities += "0\nPOINT\n8\n0\n10\n5\n20\n5\n";
    entities += "0\nDIMENSION\n8\ndim\n70\n0\n";
    // One zero-length line among the rest, and a circle of radius 0.
    entities += "0\nLINE\n8\n0\n10\n7\n20\n7\n11\n7\n21\n7\n";
    entities += "0\nCIRCLE\n8\n0\n10\n0\n20\n0\n40\n0\n";
    entities += kLine;
    const Drawing d = read_dxf(dxf(entities));
    CHECK(d.curves.size() == 2);
    REQUIRE(d.warnings.size() == 2);
    CHECK_THAT(d.warnings[0],
               Catch::StartsWith("skipped what cannot be traced: ") &&
                   Catch::Contains("HATCH #2 (layer fill), HATCH #3 (layer fill), HATCH #4 "
                                   "(layer fill) and 2 more") &&
                   Catch::Contains("POINT #7 (layer 0)") &&
                   Catch::Contains("DIMENSION #8 (layer dim)"));
    CHECK_THAT(d.warnings[1], Catch::Contains("LINE #9 (layer 0) (zero-length curve)") &&
                                  Catch::Contains("CIRCLE #10 (layer 0) (zero radius)"));
    ReadOptions strict;
    strict.strict = true;
    // A degenerate piece is refused where it is read; what cannot be
    // traced, all together at the end.
    CHECK_THAT(message_of([&] { read_dxf(dxf(entities), strict); }),
               Catch::Contains("LINE #9 (layer 0): zero-length curve"));
    const std::string untraceable = entities.substr(0, entities.find("0\nLINE\n8\n0\n10\n7"));
    CHECK_THAT(message_of([&] { read_dxf(dxf(untraceable), strict); }),
               Catch::Contains("DIMENSION, HATCH (5x), POINT"));
    // Nothing left to draw is an error that says what was skipped.
    CHECK_THAT(message_of([&] { read_dxf(dxf("0\nHATCH\n8\n0\n")); }),
               Catch::Contains("nothing to draw") && Catch::Contains("HATCH #1"));
}

TEST_CASE("DXF: --layers reads only those layers and the layers are counted", "[drawing][dxf]") {
    std::string entities;
    for (const char* layer : {"walls", "walls", "doors", "text"})
        entities += std::string("0\nLINE\n8\n") + layer + "\n10\n0\n20\n0\n11\n10\n21\n0\n";
    const Drawing all = read_dxf(dxf(entities));
    CHECK(all.curves.size() == 4);
    CHECK(all.layers ==
          std::map<std::string, std::size_t>{{"doors", 1}, {"text", 1}, {"walls", 2}});
    ReadOptions o;
    o.layers = {"walls", "doors"};
    const Drawing some = read_dxf(dxf(entities), o);
    CHECK(some.curves.size() == 3);
    CHECK(some.layers.size() == 3);
    o.layers = {"wall"};
    CHECK_THAT(message_of([&] { read_dxf(dxf(entities), o); }),
               Catch::Contains("no layer 'wall'") && Catch::Contains("walls (2)"));
}

namespace {

/// A DXF whose BLOCKS section holds `blocks` and ENTITIES `entities`.
std::string dxf_with_blocks(const std::string& blocks, const std::string& entities) {
    return "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nBLOCKS\n" +
           blocks + "0\nENDSEC\n0\nSECTION\n2\nENTITIES\n" + entities + "0\nENDSEC\n0\nEOF\n";
}

std::string block(const std::string& name, double bx, double by, const std::string& body) {
    return "0\nBLOCK\n8\n0\n2\n" + name + "\n70\n0\n10\n" + std::to_string(bx) + "\n20\n" +
           std::to_string(by) + "\n3\n" + name + "\n" + body + "0\nENDBLK\n8\n0\n";
}

std::string insert(const std::string& name, const std::string& groups) {
    return "0\nINSERT\n8\n0\n2\n" + name + "\n" + groups;
}

}  // namespace

TEST_CASE("DXF: INSERT draws its block, placed, scaled, turned and arrayed", "[drawing][dxf]") {
    // A unit line from the block's base point (1,1) to (2,1).
    const std::string blocks =
        block("bar", 1, 1, "0\nLINE\n8\n0\n10\n1\n20\n1\n11\n2\n21\n1\n") +
        block("pair", 0, 0, insert("bar", "10\n0\n20\n0\n") + insert("bar", "10\n0\n20\n5\n"));
    // Scaled by 2 and turned a quarter turn about the insertion point (10,0).
    const Drawing one =
        read_dxf(dxf_with_blocks(blocks, insert("bar", "10\n10\n20\n0\n41\n2\n42\n2\n50\n90\n")));
    REQUIRE(one.curves.size() == 1);
    const Segment& s = one.curves[0].segments[0];
    CHECK((start_point(s) - Vec2(10, 0)).norm() < 1e-12);
    CHECK((end_point(s) - Vec2(10, 2)).norm() < 1e-12);
    CHECK_THAT(one.curves[0].source, Catch::Contains("LINE #1 of block bar in INSERT #1"));
    // A 3 x 2 array, 5 apart in columns and 7 in rows.
    const Drawing array = read_dxf(
        dxf_with_blocks(blocks, insert("bar", "10\n0\n20\n0\n70\n3\n71\n2\n44\n5\n45\n7\n")));
    REQUIRE(array.curves.size() == 6);
    CHECK((start_point(array.curves[5].segments[0]) - Vec2(10, 7)).norm() < 1e-12);
    // Nested: a block of two bars, inserted twice.
    const Drawing nested = read_dxf(dxf_with_blocks(
        blocks, insert("pair", "10\n0\n20\n0\n") + insert("pair", "10\n100\n20\n0\n")));
    REQUIRE(nested.curves.size() == 4);
    CHECK((start_point(nested.curves[3].segments[0]) - Vec2(100, 5)).norm() < 1e-12);
}

TEST_CASE("DXF: a block that inserts itself is refused by name", "[drawing][dxf]") {
    const std::string blocks = block("A", 0, 0, insert("B", "10\n1\n20\n0\n")) +
                               block("B", 0, 0, kLine + insert("A", "10\n1\n20\n0\n"));
    CHECK_THAT(message_of([&] { read_dxf(dxf_with_blocks(blocks, insert("A", ""))); }),
               Catch::Contains("block 'A' inserts itself (A -> B -> A)"));
    CHECK_THAT(message_of([&] { read_dxf(dxf_with_blocks(blocks, insert("C", "") + kLine)); }),
               Catch::Contains("INSERT #1 (layer 0)") && Catch::Contains("no block named 'C'"));
    // Arrays of a block of things not drawn cannot take long either.
    std::string points;
    for (int i = 0; i < 10; ++i) points += "0\nPOINT\n8\n0\n10\n1\n20\n1\n";
    const std::string many = dxf_with_blocks(
        block("P", 0, 0, points), kLine + insert("P", "10\n0\n20\n0\n70\n200\n71\n100\n"));
    CHECK_THAT(message_of([&] { read_dxf(many); }), Catch::Contains("too many to draw"));
}

TEST_CASE("DXF: TEXT and MTEXT are written in a Hershey font", "[drawing][dxf][text]") {
    // "HI" 10 units tall at (100, 50), then turned a quarter turn.
    const Drawing d = read_dxf(dxf("0\nTEXT\n8\n0\n10\n100\n20\n50\n40\n10\n1\nHI\n"));
    REQUIRE(d.curves.size() == 4);  // H: three strokes, I: one
    double top = -1e9, bottom = 1e9, left = 1e9;
    for (const Curve& c : d.curves) {
        for (const Segment& s : c.segments) {
            for (const Vec2& p : {start_point(s), end_point(s)}) {
                top = std::max(top, p.y());
                bottom = std::min(bottom, p.y());
                left = std::min(left, p.x());
            }
        }
    }
    CHECK(top == Approx(60.0));
    CHECK(bottom == Approx(50.0));
    CHECK(left >= 100.0);
    CHECK(left < 102.0);
    // MTEXT: two paragraphs, its formatting codes not drawn.
    const Drawing m = read_dxf(
        dxf("0\nMTEXT\n8\n0\n10\n0\n20\n0\n40\n10\n71\n1\n1\n{\\fArial|b0;\\H1.5x;I}\\PI\n"));
    REQUIRE(m.curves.size() == 2);
    // Attachment 1 (top left): the first line's capitals hang below the point.
    CHECK(std::max(start_point(m.curves[0].segments[0]).y(),
                   end_point(m.curves[0].segments[0]).y()) == Approx(0.0).margin(1e-9));
    // A character the font has no glyph for is reported, the rest drawn.
    const Drawing deg = read_dxf(dxf("0\nTEXT\n8\n0\n10\n0\n20\n0\n40\n10\n1\n90%%d\n"));
    CHECK(!deg.curves.empty());
    REQUIRE(deg.warnings.size() == 1);
    CHECK_THAT(deg.warnings[0],
               Catch::Contains("TEXT #1 (layer 0)") && Catch::Contains("('\xC2\xB0')"));
}

namespace {

/// Leaves `byte` in the stack the next call's frames will take: what a
/// reader leaves uninitialised then holds it.
[[gnu::noinline]] void fill_stack(unsigned char byte) {
    volatile unsigned char area[1 << 16];
    for (std::size_t i = 0; i < sizeof area; ++i) area[i] = byte;
}

/// The points a drawing's curves pass through, in order.
std::vector<Vec2> points_of(const Drawing& d) {
    std::vector<Vec2> out;
    for (const Curve& c : d.curves) {
        for (const Segment& s : c.segments) {
            out.push_back(start_point(s));
            out.push_back(end_point(s));
        }
    }
    return out;
}

/// The extent of the points along x and along y.
Vec2 extent(const std::vector<Vec2>& points) {
    Vec2 lo = points.front(), hi = points.front();
    for (const Vec2& p : points) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    return hi - lo;
}

}  // namespace

TEST_CASE("DXF: an MTEXT's angle does not depend on what memory held", "[drawing][dxf][text]") {
    // dxflib reads group 50 in radians when the file was written by dxflib
    // 2.0.2.0 or older, from a version it leaves uninitialised unless a
    // comment names it (LibreCAD's A4_1_draw.dxf came out different from
    // run to run). An "I" 10 units tall turned a quarter turn lies along x.
    const std::string degrees = dxf("0\nMTEXT\n8\n0\n10\n0\n20\n0\n40\n10\n71\n7\n50\n90\n1\nI\n");
    const std::string in_radians =
        dxf("0\nMTEXT\n8\n0\n10\n0\n20\n0\n40\n10\n71\n7\n50\n1.5707963267948966\n1\nI\n");
    const std::string radians = "999\ndxflib 2.0.2.0\n" + in_radians;
    // dxflib would end a version's third part where memory it never set says.
    const std::string radians_short = "999\ndxflib 2.0.2\n" + in_radians;
    const std::string later = "999\ndxflib 2.0.4.8\n" + degrees;
    const std::string no_version = "999\ndxflib of 2.0.1\n" + degrees;
    for (const std::string* text : {&degrees, &radians, &radians_short, &later, &no_version}) {
        std::vector<Vec2> first;
        for (const unsigned char byte : {0x00, 0xFF, 0x7F, 0x01, 0x55}) {
            fill_stack(byte);
            const std::vector<Vec2> points = points_of(read_dxf(*text));
            REQUIRE(!points.empty());
            const Vec2 size = extent(points);
            CHECK(size.x() == Approx(10.0));
            CHECK(size.y() < 1.0);
            if (first.empty()) first = points;
            CHECK(points == first);
        }
    }
}

TEST_CASE("import: a piece smaller than the fitting resolves is skipped among others",
          "[drawing][dxf]") {
    // As LibreCAD's library holds them: an ellipse 1e-12 mm across.
    const std::string text =
        dxf(kLine + "0\nELLIPSE\n8\n0\n10\n5\n20\n5\n11\n1e-12\n21\n0\n40\n0.5\n41\n0\n42\n1\n");
    ImportOptions o;
    const ImportResult r = import_drawing(text, DrawingFormat::Dxf, o);
    CHECK(r.strokes.size() == 1);
    REQUIRE(r.warnings.size() == 1);
    CHECK_THAT(r.warnings[0], Catch::Contains("ELLIPSE #2 (layer 0)"));
    o.read.strict = true;
    CHECK_THAT(message_of([&] { import_drawing(text, DrawingFormat::Dxf, o); }),
               Catch::Contains("ELLIPSE #2 (layer 0)"));
}

TEST_CASE("import: an arc nearly straight, its centre beyond reach, is its chord",
          "[drawing][dxf]") {
    // Radius 999.9 m (kept as an arc), its centre 1000.1 m out once placed,
    // 0.004 degrees of it: 70 mm long, 0.6 um from its chord.
    const std::string text =
        dxf("0\nARC\n8\n0\n10\n0\n20\n-1000100\n40\n999900\n50\n89.998\n51\n90.002\n");
    ImportOptions o;
    const ImportResult r = import_drawing(text, DrawingFormat::Dxf, o);
    REQUIRE(r.strokes.size() == 1);
    REQUIRE(r.strokes[0].size() == 1);
    CHECK(r.strokes[0][0].kind == modsynth::geometry::PrimitiveKind::Line);
    CHECK(r.deviation == Approx(6.09e-7).epsilon(0.01));
    CHECK((r.strokes[0][0].end - r.strokes[0][0].start).norm() == Approx(0.0698).epsilon(1e-3));
    // Where the chord would stray beyond the tolerance, the centre is refused.
    o.tolerance = 1e-7;
    CHECK_THAT(message_of([&] { import_drawing(text, DrawingFormat::Dxf, o); }),
               Catch::Contains("beyond 1000 m"));
}
