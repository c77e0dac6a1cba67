#include <modsynth/text/printable.h>

#include <cstddef>
#include <limits>
#include <string>
#include <string_view>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

using modsynth::text::compact;

namespace {
std::string printable(std::string_view s) { return modsynth::text::printable(s, std::size_t(-1)); }
}  // namespace

TEST_CASE("printable keeps valid UTF-8 and escapes everything else") {
    CHECK(printable("/api/jobs") == "/api/jobs");
    CHECK(printable("caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80") ==
          "caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80");
    CHECK(printable("/\xFF") == "/\\xFF");
    CHECK(printable("\xC3(") == "\\xC3(");                           // a lead byte without its tail
    CHECK(printable("\xC0\xAF") == "\\xC0\\xAF");                    // overlong '/'
    CHECK(printable("\xED\xA0\x80") == "\\xED\\xA0\\x80");           // a surrogate
    CHECK(printable("\xF4\x90\x80\x80") == "\\xF4\\x90\\x80\\x80");  // past U+10FFFF
    CHECK(printable("\xE2\x82") == "\\xE2\\x82");                    // cut short at the end
    CHECK(printable(std::string("a\0b\r\n\x7F", 6)) == "a\\x00b\\x0D\\x0A\\x7F");
}

TEST_CASE("whatever the bytes, printable text goes into JSON") {
    std::string all;
    for (int c = 0; c < 256; ++c) all += static_cast<char>(c);
    const nlohmann::json doc = {{"error", printable(all + all.substr(128) + "\xE2\x82")}};
    CHECK_NOTHROW(doc.dump());
}

TEST_CASE("printable cuts at a number of characters, not bytes") {
    CHECK(modsynth::text::printable("abcdef", 3) == "abc...");
    CHECK(modsynth::text::printable("\xC3\xA9\xC3\xA9\xC3\xA9", 2) == "\xC3\xA9\xC3\xA9...");
    CHECK(modsynth::text::printable("abc", 3) == "abc");
}

TEST_CASE("compact numbers never run to hundreds of digits") {
    CHECK(compact(1e300) == "1e+300");
    CHECK(compact(0.5) == "0.5");
    CHECK(compact(std::numeric_limits<double>::quiet_NaN()) == "NaN");
    CHECK(compact(-std::numeric_limits<double>::infinity()) == "-infinity");
}
