#include <catch2/catch.hpp>

#include <string>

#include <modsynth/text/markdown.h>
#include <modsynth/text/printable.h>
#include <modsynth/text/scad.h>
#include <modsynth/text/xml.h>

using namespace modsynth::text;

namespace {

/// A name written to break out of every language it lands in.
const std::string kHostile =
    "arm\n--> <!-- x --> cube([500,500,500]); include <inc.scad>\r\x1b[2J\x07"
    "&amp; \"q\" 'a' \xff end-";

bool has_control(const std::string& s, bool allow_line_breaks) {
    for (const char c : s) {
        const auto u = static_cast<unsigned char>(c);
        if (allow_line_breaks && (c == '\n' || c == '\r' || c == '\t')) continue;
        if (u < 0x20 || u == 0x7f) return true;
    }
    return false;
}

}  // namespace

TEST_CASE("text in XML stays character data, and a comment stays one", "[text]") {
    const std::string text = xml_text(kHostile);
    CHECK(text.find('<') == std::string::npos);
    CHECK(text.find('>') == std::string::npos);
    CHECK(text.find('"') == std::string::npos);
    CHECK(text.find("&amp;amp;") != std::string::npos);
    CHECK_FALSE(has_control(text, true));
    CHECK(xml_text("X8-9 & co") == "X8-9 &amp; co");
    const std::string comment = xml_comment(kHostile);
    // Inside <!-- ... --> nothing may hold "--" or end with '-'.
    CHECK(comment.find("--") == std::string::npos);
    CHECK(comment.back() != '-');
    CHECK_FALSE(has_control(comment, true));
    CHECK(xml_comment("X8-9, X5-4") == "X8-9, X5-4");
    CHECK(xml_comment("a---b") == "a- - -b");
}

TEST_CASE("text in an OpenSCAD comment stays on its line", "[text]") {
    const std::string comment = scad_comment(kHostile);
    CHECK(comment.find('\n') == std::string::npos);
    CHECK(comment.find('\r') == std::string::npos);
    CHECK_FALSE(has_control(comment, false));
    CHECK(comment.find("\\x0A") != std::string::npos);
    CHECK(scad_comment("link 1 of 3: X8-9") == "link 1 of 3: X8-9");
    CHECK(scad_comment("\xc3\xa9t\xc3\xa9") == "\xc3\xa9t\xc3\xa9");
}

TEST_CASE("text on a terminal and in Markdown holds no control bytes", "[text]") {
    CHECK_FALSE(has_control(printable(kHostile, 1000), false));
    CHECK_FALSE(has_control(markdown_literal(kHostile), false));
}
