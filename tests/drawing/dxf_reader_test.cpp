// The DXF reader against files that dxflib alone misreads or never finishes:
// every one is read as written or refused naming the entity and the value.
#include <catch2/catch.hpp>
#include <functional>
#include <string>

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
    CHECK_THAT(message_of([&] { read_dxf(text); }),
               Catch::Contains("entities that cannot be drawn: 3DSOLID, ATTDEF, REGION (2x)"));
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
