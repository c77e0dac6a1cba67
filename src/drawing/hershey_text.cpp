#include <modsynth/drawing/hershey_text.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>

// libhersheyfont is C, without C++ guards, and its paths end in a flexible
// array member.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpedantic"
extern "C" {
#include <hersheyfont.h>
}
#pragma GCC diagnostic pop

#include <modsynth/task/input_error.h>
#include <modsynth/text/printable.h>

namespace modsynth::drawing {

namespace {

using task::InputError;

/// Where hershey-fonts-data installs the fonts (libhersheyfont looks there
/// too, but says nothing of a name it cannot find).
const std::filesystem::path kFontFolder = "/usr/share/hershey-fonts";

struct FontFree {
    void operator()(hershey_font* f) const { hershey_font_free(f); }
};

/// A loaded font and its measures in font units.
struct Font {
    std::unique_ptr<hershey_font, FontFree> glyphs;
    double cap_height = 21.0;  ///< the top of 'H'
    double descent = 7.0;      ///< below the baseline, of 'g'
};

double glyph_extreme(hershey_font* f, unsigned char c, bool top) {
    const hershey_glyph* g = hershey_font_glyph(f, c);
    double extreme = 0.0;
    bool any = false;
    for (const hershey_path* p = g->paths; p; p = p->next) {
        for (unsigned i = 0; i < p->nverts; ++i) {
            const double y = p->verts[i].y;
            extreme = !any ? y : top ? std::max(extreme, y) : std::min(extreme, y);
            any = true;
        }
    }
    return any ? extreme : 0.0;
}

bool valid_font_name(const std::string& name) {
    return !name.empty() && name.size() <= 64 && std::all_of(name.begin(), name.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
    });
}

/// Fonts are loaded once per process and kept: a drawing names a few.
const Font& font(const std::string& name, const std::string& part) {
    static std::mutex mutex;
    static std::map<std::string, Font> loaded;
    const std::lock_guard lock(mutex);
    if (const auto found = loaded.find(name); found != loaded.end()) return found->second;
    const std::filesystem::path file = kFontFolder / (name + ".jhf");
    std::error_code ec;
    if (!valid_font_name(name) || !std::filesystem::is_regular_file(file, ec)) {
        std::string installed;
        for (const std::string& f : hershey_fonts())
            installed += (installed.empty() ? "" : ", ") + f;
        throw InputError(
            part, "no Hershey font '" + text::printable(name) + "' (installed in " +
                      kFontFolder.string() + ": " +
                      (installed.empty() ? "none; install hershey-fonts-data" : installed) + ")");
    }
    Font f;
    // Of what it loads, hershey_glyph::glyphnum is never to be read:
    // libhersheyfont 0.1 parses it with strtoul from a buffer it ends with
    // a NUL only afterwards (hershey_jhf_load_glyph), so it may take a
    // stray digit (tests/valgrind.supp).
    f.glyphs.reset(hershey_jhf_font_load(file.c_str()));
    if (!f.glyphs) throw InputError(part, "the Hershey font '" + name + "' cannot be read");
    const double cap = glyph_extreme(f.glyphs.get(), 'H', true);
    if (cap > 0.0) f.cap_height = cap;
    const double descent = -glyph_extreme(f.glyphs.get(), 'g', false);
    f.descent = descent > 0.0 ? descent : f.cap_height / 3.0;
    return loaded.emplace(name, std::move(f)).first->second;
}

/// The length of the UTF-8 sequence a byte begins (1 for anything else).
std::size_t sequence_length(unsigned char c) {
    if (c >= 0xF0 && c < 0xF8) return 4;
    if (c >= 0xE0) return c < 0xF0 ? 3 : 1;
    if (c >= 0xC0) return 2;
    return 1;
}

}  // namespace

std::vector<std::string> hershey_fonts() {
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(kFontFolder, ec)) {
        if (entry.path().extension() == ".jhf") names.push_back(entry.path().stem().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

TextCurves text_curves(std::string_view text, const Vec2& at, const TextLayout& layout,
                       const std::string& source, const std::string& font_part) {
    const Font& f = font(layout.font, font_part);
    const double scale = layout.height / f.cap_height;

    // The lines' glyphs, and each line's width in font units.
    struct Line {
        std::vector<const hershey_glyph*> glyphs;
        double width = 0.0;
    };
    std::vector<Line> lines(1);
    TextCurves out;
    for (std::size_t i = 0; i < text.size();) {
        const auto c = static_cast<unsigned char>(text[i]);
        const std::size_t n = std::min(sequence_length(c), text.size() - i);
        if (c == '\n') {
            lines.emplace_back();
        } else {
            const hershey_glyph* g =
                n == 1 && c >= 32 && c < 127 ? hershey_font_glyph(f.glyphs.get(), c) : nullptr;
            if (c == '\t') g = hershey_font_glyph(f.glyphs.get(), ' ');
            if (!g || g->width == 0) {
                out.missing += text.substr(i, n);
            } else {
                lines.back().glyphs.push_back(g);
                lines.back().width += g->width;
            }
        }
        i += n;
    }

    const double spacing = layout.line_spacing * f.cap_height;
    const double last_baseline = -spacing * double(lines.size() - 1);
    double dy = 0.0;  // font units, added to every line
    switch (layout.vertical) {
        case TextLayout::Vertical::Baseline:
            break;
        case TextLayout::Vertical::Bottom:
            dy = f.descent - last_baseline;
            break;
        case TextLayout::Vertical::Middle:
            dy = -(f.cap_height + last_baseline) / 2.0;
            break;
        case TextLayout::Vertical::Top:
            dy = -f.cap_height;
            break;
    }
    const double cs = std::cos(layout.rotation), sn = std::sin(layout.rotation);
    const auto place = [&](double x, double y) {
        const Vec2 p(x * scale * layout.width_factor, y * scale);
        return Vec2(at.x() + cs * p.x() - sn * p.y(), at.y() + sn * p.x() + cs * p.y());
    };
    for (std::size_t l = 0; l < lines.size(); ++l) {
        const Line& line = lines[l];
        double x = 0.0;
        if (layout.horizontal == TextLayout::Horizontal::Center) x = -line.width / 2.0;
        if (layout.horizontal == TextLayout::Horizontal::Right) x = -line.width;
        const double y = dy - spacing * double(l);
        for (const hershey_glyph* g : line.glyphs) {
            for (const hershey_path* p = g->paths; p; p = p->next) {
                Curve c;
                c.source = source;
                for (unsigned i = 1; i < p->nverts; ++i) {
                    const Vec2 a = place(x + p->verts[i - 1].x, y + p->verts[i - 1].y);
                    const Vec2 b = place(x + p->verts[i].x, y + p->verts[i].y);
                    if (a != b) c.segments.push_back(LineSegment{a, b});
                }
                if (!c.segments.empty()) out.curves.push_back(std::move(c));
            }
            x += g->width;
        }
    }
    out.advance = lines.back().width * scale * layout.width_factor;
    return out;
}

}  // namespace modsynth::drawing
