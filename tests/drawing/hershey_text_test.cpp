// Text in a single-stroke Hershey font: sizes, alignment, rotation, lines,
// characters the font lacks, and fonts that are not installed.
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <string>

#include <modsynth/drawing/hershey_text.h>
#include <modsynth/task/input_error.h>

namespace {

using namespace modsynth::drawing;

struct Bounds {
    Vec2 min = Vec2::Constant(1e300), max = Vec2::Constant(-1e300);
};

Bounds bounds(const TextCurves& t) {
    Bounds b;
    for (const Curve& c : t.curves) {
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

TEST_CASE("text: capitals are the height asked, on the baseline", "[drawing][text]") {
    TextLayout layout;
    layout.height = 0.02;
    const TextCurves t = text_curves("HELLO", Vec2(1, 2), layout, "t");
    CHECK(t.missing.empty());
    CHECK(t.curves.size() == 3 + 4 + 2 + 2 + 1);  // H E L L O, each stroke one curve
    const Bounds b = bounds(t);
    CHECK(b.min.y() == Approx(2.0));
    CHECK(b.max.y() == Approx(2.02));
    CHECK(b.min.x() > 1.0);
    // Right-aligned and vertically centred about the point.
    layout.horizontal = TextLayout::Horizontal::Right;
    layout.vertical = TextLayout::Vertical::Middle;
    const Bounds r = bounds(text_curves("HELLO", Vec2(1, 2), layout, "t"));
    CHECK(r.max.x() < 1.0);
    CHECK(r.max.x() > 0.99);
    CHECK((r.min.y() + r.max.y()) / 2 == Approx(2.0));
}

TEST_CASE("text: turned, on several lines, in another font", "[drawing][text]") {
    TextLayout layout;
    layout.height = 1.0;
    layout.rotation = M_PI / 2;
    const Bounds b = bounds(text_curves("HH", Vec2::Zero(), layout, "t"));
    // A quarter turn: the text runs up the y axis, its capitals to the left.
    CHECK(b.min.x() == Approx(-1.0));
    CHECK(b.max.x() == Approx(0.0).margin(1e-12));
    CHECK(b.max.y() > 1.0);
    layout.rotation = 0.0;
    const Bounds two = bounds(text_curves("H\nH", Vec2::Zero(), layout, "t"));
    CHECK(two.min.y() == Approx(-5.0 / 3.0));
    layout.font = "rowmans";
    CHECK(text_curves("H", Vec2::Zero(), layout, "t").curves.size() == 3);
}

TEST_CASE("text: what a font cannot write is said", "[drawing][text]") {
    TextLayout layout;
    const TextCurves t = text_curves("a\xC3\xA9z", Vec2::Zero(), layout, "t");
    CHECK(t.missing == "\xC3\xA9");
    CHECK(!t.curves.empty());
    layout.font = "nosuchfont";
    try {
        text_curves("a", Vec2::Zero(), layout, "t", "--font");
        FAIL("no error");
    } catch (const modsynth::task::InputError& e) {
        CHECK(e.part() == "--font");
        CHECK_THAT(std::string(e.what()),
                   Catch::Contains("no Hershey font 'nosuchfont'") && Catch::Contains("futural"));
    }
    layout.font = "../etc/passwd";
    CHECK_THROWS_AS(text_curves("a", Vec2::Zero(), layout, "t"), modsynth::task::InputError);
}

TEST_CASE("text: the advance is where text that continues the line starts", "[drawing][text]") {
    TextLayout layout;
    layout.height = 0.02;
    const TextCurves h = text_curves("H", Vec2::Zero(), layout, "t");
    const TextCurves hh = text_curves("HH", Vec2::Zero(), layout, "t");
    CHECK(h.advance > 0.02);
    CHECK(hh.advance == Approx(2.0 * h.advance));
    // Right-aligned text ends where left-aligned text's pen stops.
    layout.horizontal = TextLayout::Horizontal::Right;
    const TextCurves right = text_curves("HH", Vec2::Zero(), layout, "t");
    CHECK(bounds(right).min.x() == Approx(bounds(hh).min.x() - hh.advance));
    // Only the last line counts.
    CHECK(text_curves("HHHH\nH", Vec2::Zero(), layout, "t").advance == Approx(h.advance));
}
