#include <modsynth/text/format.h>
#include <modsynth/text/markdown.h>

#include <string>

#include <catch2/catch.hpp>

using modsynth::text::format;
using modsynth::text::markdown_literal;
using modsynth::text::markdown_text;

TEST_CASE("format writes printf patterns of any length") {
    CHECK(format("%d links, %.3f m", 3, 1.5) == "3 links, 1.500 m");
    CHECK(format("%s", "") == "");
    const std::string long_text(5000, 'x');
    CHECK(format("<%s>", long_text.c_str()) == "<" + long_text + ">");
}

TEST_CASE("append_fixed and append_general write what printf writes") {
    using modsynth::text::append_fixed;
    using modsynth::text::append_general;
    using modsynth::text::format;
    for (double v : {0.0, -0.0, 1.0, -2.5, 0.125, 1.0 / 3.0, 1e-7, -1e-300, 123456.789, 1e21,
                     -1.7e308, 0.0049999, 2.675, 1e300}) {
        for (int digits : {0, 2, 6, 9}) {
            std::string fixed, general;
            append_fixed(fixed, v, digits);
            append_general(general, v, digits);
            CHECK(fixed == format("%.*f", digits, v));
            CHECK(general == format("%.*g", digits, v));
        }
    }
}

TEST_CASE("markdown_literal shows markup as the characters it is") {
    CHECK(markdown_literal("rose") == "rose");
    CHECK(markdown_literal("*bold* _x_ [a](b)") == "\\*bold\\* \\_x\\_ \\[a\\]\\(b\\)");
    CHECK(markdown_literal("<script>") == "&lt;script&gt;");
    CHECK(markdown_literal("a & \"b\" 'c'") == "a &amp; &quot;b&quot; &#39;c&#39;");
    // A line break would end a heading or a table row.
    CHECK(markdown_literal("a\nb|c").find('\n') == std::string::npos);
    CHECK(markdown_literal("a|b") == "a\\|b");
    // Bytes of UTF-8 text are kept.
    CHECK(markdown_literal("caf\xC3\xA9") == "caf\xC3\xA9");
}

TEST_CASE("markdown_text leaves a sentence readable as plain text, markup escaped") {
    const std::string proof =
        "Proved infeasible: obstacles 0-5 close in base_regions[0], and the path "
        "(trajectory[0] at (0.600, 0.000, 0.200)) is outside them.";
    CHECK(markdown_text(proof) == proof);
    CHECK(markdown_text("a *b* `c` x|y [l](u) <i> & ~~s~~") ==
          "a \\*b\\* \\`c\\` x\\|y [l\\](u) &lt;i&gt; &amp; \\~\\~s\\~\\~");
    CHECK(markdown_text("_a_ snake_case") == "\\_a\\_ snake_case");
    CHECK(markdown_text("- not a list") == "\\- not a list");
    CHECK(markdown_text("# not a heading") == "\\# not a heading");
    CHECK(markdown_text("a\nb").find('\n') == std::string::npos);
}
