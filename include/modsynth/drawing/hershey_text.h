#pragma once
// Text as a pen plotter writes it: each glyph a few single strokes of a
// Hershey font (Debian's hershey-fonts-data, read through libhersheyfont),
// so that a robot draws a letter's centrelines rather than its outline.
#include <string>
#include <string_view>
#include <vector>

#include <modsynth/drawing/curve.h>

namespace modsynth::drawing {

/// The font every text is written in unless it names another: the simplex
/// sans serif, one stroke per line of a letter.
inline constexpr const char* kDefaultFont = "futural";

struct TextLayout {
    std::string font = kDefaultFont;
    double height = 1.0;              ///< of a capital letter, drawing units
    double rotation = 0.0;            ///< radians, counter-clockwise
    double width_factor = 1.0;        ///< horizontal stretch of every glyph
    double line_spacing = 5.0 / 3.0;  ///< baseline to baseline, in heights
    enum class Horizontal { Left, Center, Right } horizontal = Horizontal::Left;
    /// Which line of the text block lies on the alignment point: the first
    /// line's baseline, the bottom of the last line's descenders, the
    /// block's middle, or the top of the first line's capitals.
    enum class Vertical { Baseline, Bottom, Middle, Top } vertical = Vertical::Baseline;
};

struct TextCurves {
    std::vector<Curve> curves;  ///< one per stroke of a glyph
    /// The characters the font has no glyph for (left out), as in the text.
    std::string missing;
    /// How far the last line moves the pen, drawing units: where text that
    /// continues it starts.
    double advance = 0.0;
};

/// `text` (lines separated by '\n') laid out about the alignment point `at`;
/// every curve's source is `source`. Throws task::InputError naming
/// `font_part` when the font is not installed.
TextCurves text_curves(std::string_view text, const Vec2& at, const TextLayout& layout,
                       const std::string& source, const std::string& font_part = "font");

/// The names of the installed Hershey fonts ("futural", "rowmans", ...).
std::vector<std::string> hershey_fonts();

}  // namespace modsynth::drawing
