#include <modsynth/drawing/svg_reader.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <initializer_list>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

// SVG++ nests Boost.Parameter lists deeper than Boost's default arity.
#define BOOST_PARAMETER_MAX_ARITY 11
#include <tinyxml2.h>
#include <boost/array.hpp>
#include <boost/exception/get_error_info.hpp>
#include <svgpp/svgpp.hpp>

#include <modsynth/drawing/hershey_text.h>
#include <modsynth/task/input_error.h>
#include <modsynth/text/printable.h>

#include "elliptic_arc.h"
#include "svg_clip.h"
#include "svg_use.h"
#include "svg_xml_policy.h"

namespace modsynth::drawing {

namespace {

using task::InputError;
using XmlElement = const tinyxml2::XMLElement*;

/// CSS pixels per inch: SVG's user unit is the CSS pixel.
constexpr double kPxPerInch = 96.0;
constexpr double kMmPerPx = 25.4 / kPxPerInch;

/// The paths a text's glyphs become keep the text's (or tspan's) name in
/// this foreign attribute, which the walk skips.
constexpr const char* kNameAttribute = "modsynth:name";

/// "path#p3": an element's name and id.
std::string element_name(XmlElement e) {
    if (const char* named = e->Attribute(kNameAttribute)) return named;
    std::string label = text::printable(svg_xml::local_name(e->Name()), 40);
    if (const char* id = e->Attribute("id")) label += "#" + text::printable(id, 40);
    return label;
}

/// "path#p3 (line 12)": how messages name an element.
std::string element_label(XmlElement e) {
    return element_name(e) + " (line " + svg_use::line_of(e) + ")";
}

/// Elements that draw nothing by themselves: skipped with what they hold.
const std::set<std::string, std::less<>> kNotDrawn = {
    "defs",           "metadata",       "title",  "desc",   "style",     "script",
    "symbol",         "clipPath",       "mask",   "marker", "pattern",   "filter",
    "linearGradient", "radialGradient", "cursor", "font",   "font-face", "color-profile"};
const std::set<std::string, std::less<>> kContainers = {"svg", "g"};
const std::set<std::string, std::less<>> kShapes = {"path", "rect",     "circle", "ellipse",
                                                    "line", "polyline", "polygon"};

bool in_layer(XmlElement e, const std::string& layer) {
    for (const tinyxml2::XMLNode* n = e->Parent(); n; n = n->Parent()) {
        const auto* g = n->ToElement();
        if (!g || std::strcmp(svg_xml::local_name(g->Name()), "g") != 0) continue;
        const char* id = g->Attribute("id");
        const char* label = g->Attribute("inkscape:label");
        if ((id && layer == id) || (label && layer == label)) return true;
    }
    return false;
}

std::string_view trimmed(std::string_view v) {
    const auto b = v.find_first_not_of(" \t\r\n");
    if (b == std::string_view::npos) return {};
    return v.substr(b, v.find_last_not_of(" \t\r\n") - b + 1);
}

std::string lower(std::string_view v) {
    std::string out(v);
    std::transform(out.begin(), out.end(), out.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return out;
}

/// The value an element gives a presentation property, in lower case: its
/// style attribute's declaration (which wins) or the attribute of that
/// name; empty when it gives none. Style sheets are not read.
std::string property(XmlElement e, std::string_view name, bool keep_case = false) {
    const auto as_read = [keep_case](std::string_view v) {
        return keep_case ? std::string(trimmed(v)) : lower(trimmed(v));
    };
    std::string value;
    if (const char* a = e->Attribute(std::string(name).c_str())) value = as_read(a);
    const char* style = e->Attribute("style");
    for (std::string_view rest = style ? style : ""; !rest.empty();) {
        const auto semi = rest.find(';');
        const std::string_view declaration = rest.substr(0, semi);
        rest = semi == std::string_view::npos ? std::string_view{} : rest.substr(semi + 1);
        const auto colon = declaration.find(':');
        if (colon == std::string_view::npos || lower(trimmed(declaration.substr(0, colon))) != name)
            continue;
        value = as_read(declaration.substr(colon + 1));
        const auto important = lower(value).find("!important");
        if (important != std::string::npos)
            value = std::string(trimmed(value.substr(0, important)));
    }
    return value;
}

/// Whether an element is rendered, as far as its parent's state and its own
/// display and visibility say: display none hides it and all it holds;
/// visibility is inherited, and a child may turn it back on.
struct Rendering {
    bool displayed = true;
    bool visible = true;
    /// Fill and stroke, inherited (SVG's initial values: filled, not
    /// stroked). A shape whose fill is none and whose stroke is set to
    /// none shows nothing (an icon's frame); one that leaves its stroke
    /// unset is drawn, as drawings written by hand mean it to be. A shape
    /// only filled is traced along its outline. Clip paths ignore paint.
    bool filled = true;
    bool stroked = false;
    bool stroke_none = false;
    bool paint_matters = true;

    Rendering of(XmlElement e) const {
        Rendering r = *this;
        if (property(e, "display") == "none") r.displayed = false;
        const std::string v = property(e, "visibility");
        if (v == "hidden" || v == "collapse") r.visible = false;
        if (v == "visible") r.visible = true;
        const std::string fill = property(e, "fill"), stroke = property(e, "stroke");
        if (!fill.empty() && fill != "inherit") r.filled = fill != "none";
        if (!stroke.empty() && stroke != "inherit") {
            r.stroked = stroke != "none";
            r.stroke_none = stroke == "none";
        }
        return r;
    }
    bool drawn() const {
        return displayed && visible && (!paint_matters || filled || !stroke_none);
    }
    bool outline_only() const { return paint_matters && filled && !stroked; }
};

/// SVG text, written as a pen plotter writes it: in a single-stroke
/// Hershey font. Before the walk, each rendered `text` becomes a group of
/// paths (one per run of characters, within groups for its tspans) that
/// keeps the text's attributes, so that its transform, clip, paint and
/// visibility act as on any shape.
namespace svg_text {

using tinyxml2::XMLElement;

constexpr double kMediumFontSize = 16.0;  ///< px, CSS's initial font size
/// Hershey glyphs are drawn on a body 32 units high whose capitals are 21
/// high: the share of a font size a capital letter takes.
constexpr double kCapPerEm = 21.0 / 32.0;

/// The fonts hershey-fonts-data ships: a family naming one of them (or
/// "Hershey NAME") asks for that font and nothing else.
const std::set<std::string, std::less<>> kHersheyFonts = {
    "astrology", "cursive",   "cyrilc_1",  "cyrillic",  "futural", "futuram",     "gothgbt",
    "gothgrt",   "gothiceng", "gothicger", "gothicita", "gothitt", "greek",       "greekc",
    "greeks",    "japanese",  "markers",   "mathlow",   "mathupp", "meteorology", "music",
    "rowmand",   "rowmans",   "rowmant",   "scriptc",   "scripts", "symbolic",    "timesg",
    "timesi",    "timesib",   "timesr",    "timesrb"};

/// The nearest Hershey font for the families browsers fall back on.
const std::map<std::string, std::string, std::less<>> kNearest = {
    {"sansserif", "futural"},
    {"arial", "futural"},
    {"helvetica", "futural"},
    {"verdana", "futural"},
    {"dejavusans", "futural"},
    {"liberationsans", "futural"},
    {"opensans", "futural"},
    {"roboto", "futural"},
    {"bitstreamverasans", "futural"},
    // Hershey has no fixed-pitch font: the plain simplex is the nearest.
    {"monospace", "futural"},
    {"courier", "futural"},
    {"couriernew", "futural"},
    {"dejavusansmono", "futural"},
    {"serif", "timesr"},
    {"times", "timesr"},
    {"timesnewroman", "timesr"},
    {"georgia", "timesr"},
    {"dejavuserif", "timesr"},
    {"liberationserif", "timesr"},
    {"script", "scripts"},
    {"comicsansms", "scripts"}};

/// The value of an inherited property at `e`: its own or the nearest
/// ancestor's; empty when none sets it.
std::string inherited(XmlElement e, std::string_view name, bool keep_case = false) {
    for (const tinyxml2::XMLNode* n = e; n && n->ToElement(); n = n->Parent()) {
        const std::string v = property(n->ToElement(), name, keep_case);
        if (!v.empty() && lower(v) != "inherit") return v;
    }
    return {};
}

/// A length in user units, or nothing when `v` is not one; `em` is the
/// font size that em, ex and (when `percent_of_em`) % refer to.
std::optional<double> length_of(std::string_view v, double em, bool percent_of_em) {
    const std::string s(trimmed(v));
    char* end = nullptr;
    const double x = std::strtod(s.c_str(), &end);
    if (end == s.c_str() || !std::isfinite(x)) return std::nullopt;
    const std::string unit = lower(trimmed(std::string_view(end)));
    static const std::map<std::string, double, std::less<>> kPx = {{"", 1.0},
                                                                   {"px", 1.0},
                                                                   {"pt", kPxPerInch / 72.0},
                                                                   {"pc", kPxPerInch / 6.0},
                                                                   {"mm", kPxPerInch / 25.4},
                                                                   {"cm", kPxPerInch / 2.54},
                                                                   {"in", kPxPerInch}};
    if (unit == "em") return x * em;
    if (unit == "ex") return x * em / 2.0;
    if (unit == "%" && percent_of_em) return x * em / 100.0;
    const auto found = kPx.find(unit);
    if (found == kPx.end()) return std::nullopt;
    return x * found->second;
}

/// The font size at `e`, in user units (0 draws nothing).
double font_size(XmlElement e, const std::string& label) {
    const tinyxml2::XMLNode* up = e->Parent();
    const double parent =
        up && up->ToElement() ? font_size(up->ToElement(), label) : kMediumFontSize;
    const std::string v = property(e, "font-size");
    if (v.empty() || v == "inherit") return parent;
    static const std::map<std::string, double, std::less<>> kKeywords = {
        {"xx-small", 9.0}, {"x-small", 10.0}, {"small", 13.0},   {"medium", 16.0},
        {"large", 18.0},   {"x-large", 24.0}, {"xx-large", 32.0}};
    if (const auto k = kKeywords.find(v); k != kKeywords.end()) return k->second;
    if (v == "larger") return parent * 1.2;
    if (v == "smaller") return parent / 1.2;
    const auto size = length_of(v, parent, true);
    if (!size || *size < 0.0 || *size > kMaxDrawingCoordinate)
        throw InputError(label, "font-size '" + text::printable(v, 40) + "' cannot be honoured");
    return *size;
}

/// The Hershey font for the font-family at `e`: the first family that
/// names one or has a nearest one; the default otherwise.
std::string font_for(XmlElement e, const std::string& label) {
    const std::string families = inherited(e, "font-family", true);
    static const std::vector<std::string> installed = hershey_fonts();
    const auto is_installed = [&](const std::string& f) {
        return std::find(installed.begin(), installed.end(), f) != installed.end();
    };
    for (std::string_view rest = families; !rest.empty();) {
        const auto comma = rest.find(',');
        std::string_view family = trimmed(rest.substr(0, comma));
        rest = comma == std::string_view::npos ? std::string_view{} : rest.substr(comma + 1);
        if (family.size() >= 2 && (family.front() == '"' || family.front() == '\'') &&
            family.back() == family.front())
            family = family.substr(1, family.size() - 2);
        std::string key;  // "Hershey Sans-Serif" -> "hersheysansserif"
        for (const char c : lower(family)) {
            if (std::isalnum(static_cast<unsigned char>(c)) || c == '_') key += c;
        }
        const bool hershey = key.rfind("hershey", 0) == 0;
        if (hershey) key = key.substr(7);
        if (is_installed(key)) return key;
        if (hershey || kHersheyFonts.count(key)) {
            std::string list;
            for (const std::string& f : installed) list += (list.empty() ? "" : ", ") + f;
            throw InputError(label, "font-family '" + text::printable(std::string(family), 40) +
                                        "' names a Hershey font that is not installed (" +
                                        (list.empty() ? "none is; install hershey-fonts-data"
                                                      : "installed: " + list) +
                                        ")");
        }
        if (const auto near = kNearest.find(key); near != kNearest.end()) {
            if (is_installed(near->second)) return near->second;
        }
    }
    return kDefaultFont;
}

/// The text of the document with its white space as SVG renders it: runs
/// of spaces, tabs and line breaks as one space (none at the text's
/// start or end), unless xml:space is "preserve".
void collapse_space(XMLElement* text, bool preserve,
                    std::map<const tinyxml2::XMLNode*, std::string>& out) {
    std::vector<const tinyxml2::XMLNode*> order;
    const std::function<void(const tinyxml2::XMLNode*)> walk = [&](const tinyxml2::XMLNode* n) {
        for (const tinyxml2::XMLNode* c = n->FirstChild(); c; c = c->NextSibling()) {
            if (c->ToText()) order.push_back(c);
            if (c->ToElement()) walk(c);
        }
    };
    walk(text);
    bool after_space = true;
    for (const tinyxml2::XMLNode* n : order) {
        std::string s;
        for (const char c : std::string_view(n->Value())) {
            const bool space = c == ' ' || c == '\t' || c == '\n' || c == '\r';
            if (preserve) {
                s += space ? ' ' : c;
            } else if (!space || !after_space) {
                s += space ? ' ' : c;
                after_space = space;
            }
        }
        out[n] = s;
    }
    if (preserve) return;
    for (auto n = order.rbegin(); n != order.rend(); ++n) {
        std::string& s = out[*n];
        while (!s.empty() && s.back() == ' ') s.pop_back();
        if (!s.empty()) break;
    }
}

class Writer {
public:
    Writer(tinyxml2::XMLDocument& doc, std::vector<std::string>& missing)
        : doc_(&doc), missing_(&missing) {}

    /// Lays `text` out into `out`, a group that replaces it.
    void write(XMLElement* text, XMLElement* out) {
        const std::string label = element_label(text);
        const std::string mode = inherited(text, "writing-mode");
        if (!mode.empty() && mode != "lr" && mode != "lr-tb" && mode != "horizontal-tb")
            throw InputError(label,
                             "vertical writing (writing-mode " + mode + ") cannot be honoured");
        bool preserve = false;
        for (const tinyxml2::XMLNode* n = text; n && n->ToElement(); n = n->Parent()) {
            if (const char* v = n->ToElement()->Attribute("xml:space")) {
                preserve = std::string_view(v) == "preserve";
                break;
            }
        }
        collapse_space(text, preserve, text_);
        anchor_ = inherited(text, "text-anchor");
        run(text, out, 0);
        flush_chunk();
    }

private:
    struct Run {
        XMLElement* path;
        std::vector<Curve> curves;  ///< in the text's user space, y down
    };

    /// A position attribute: the lengths of its list (a position per
    /// character, the first for the element's first character), none when
    /// absent.
    std::vector<double> positions(XMLElement* e, const char* name, double em,
                                  const std::string& label) {
        std::vector<double> out;
        const char* v = e->Attribute(name);
        if (!v) return out;
        std::string_view rest = v;
        while (!rest.empty()) {
            const auto begin = rest.find_first_not_of(" ,\t\n\r");
            if (begin == std::string_view::npos) break;
            rest.remove_prefix(begin);
            const auto end = std::min(rest.find_first_of(" ,\t\n\r"), rest.size());
            const auto length = length_of(rest.substr(0, end), em, false);
            if (!length || std::abs(*length) > kMaxDrawingCoordinate)
                throw InputError(label, "malformed attribute " + std::string(name) + "='" +
                                            text::printable(v, 40) + "'");
            out.push_back(*length);
            rest.remove_prefix(end);
        }
        return out;
    }

    /// letter-spacing or word-spacing at `e`: a length added after each
    /// character (each space), 0 when "normal".
    static double spacing(XMLElement* e, const char* name, double em, const std::string& label) {
        const std::string v = inherited(e, name);
        if (v.empty() || v == "normal") return 0.0;
        const auto length = length_of(v, em, false);
        if (!length || std::abs(*length) > kMaxDrawingCoordinate)
            throw InputError(label, std::string(name) + " '" + text::printable(v, 40) +
                                        "' cannot be honoured (a length or normal)");
        return *length;
    }

    /// Properties that move glyphs in ways the layout does not follow:
    /// refused by name rather than drawn elsewhere than a browser shows.
    static void refuse_unhonoured(XMLElement* e, const std::string& label) {
        for (const char* refused : {"rotate", "textLength"}) {
            if (e->Attribute(refused))
                throw InputError(label, std::string(refused) + " cannot be honoured");
        }
        const auto refuse = [&](const char* name, std::initializer_list<std::string_view> fine) {
            const std::string v = property(e, name);
            if (v.empty() || v == "inherit") return;
            if (std::find(fine.begin(), fine.end(), v) != fine.end()) return;
            throw InputError(label, std::string(name) + " '" + text::printable(v, 40) +
                                        "' cannot be honoured (glyphs are written on the "
                                        "alphabetic baseline, left to right)");
        };
        refuse("baseline-shift", {"baseline", "0", "0px"});
        refuse("dominant-baseline", {"auto", "alphabetic"});
        refuse("alignment-baseline", {"auto", "baseline", "alphabetic"});
        refuse("direction", {"ltr"});
        refuse("unicode-bidi", {"normal", "embed", "isolate"});
        refuse("kerning", {"auto", "0"});
    }

    /// The x, y, dx and dy lists of the text and the tspans being written,
    /// outermost first, and how many of each one's characters came: a
    /// character takes the innermost value given for it (SVG 1.1, 10.5).
    struct Positions {
        std::vector<double> x, y, dx, dy;
        std::size_t next = 0;
    };

    std::optional<double> position_of(std::vector<double> Positions::*list) const {
        for (auto l = levels_.rbegin(); l != levels_.rend(); ++l) {
            const std::vector<double>& values = (*l).*list;
            if (l->next < values.size()) return values[l->next];
        }
        return std::nullopt;
    }

    void run(XMLElement* e, XMLElement* out, int depth) {
        const std::string label = element_label(e);
        if (depth > 32) throw InputError(label, "tspans nested too deeply");
        refuse_unhonoured(e, label);
        const double size = font_size(e, label);
        levels_.push_back({positions(e, "x", size, label), positions(e, "y", size, label),
                           positions(e, "dx", size, label), positions(e, "dy", size, label)});
        const double letter = spacing(e, "letter-spacing", size, label);
        const double word = spacing(e, "word-spacing", size, label);
        TextLayout layout;
        layout.font = font_for(e, label);
        layout.height = size * kCapPerEm;
        for (tinyxml2::XMLNode* n = e->FirstChild(); n; n = n->NextSibling()) {
            if (n->ToText()) {
                const std::string& s = text_[n];
                std::string missing;
                Run r{nullptr, {}};
                for (std::size_t i = 0; i < s.size();) {
                    const std::size_t len = std::min(utf8_length(s[i]), s.size() - i);
                    const std::string_view ch(s.data() + i, len);
                    i += len;
                    const auto x = position_of(&Positions::x), y = position_of(&Positions::y);
                    if (x || y) {
                        // An absolute position starts a chunk, anchored on
                        // its own.
                        emit(std::move(r), e, out);
                        r = Run{nullptr, {}};
                        flush_chunk();
                        if (x) pen_.x() = *x;
                        if (y) pen_.y() = *y;
                        chunk_start_ = pen_.x();
                        anchor_ = inherited(e, "text-anchor");
                    }
                    if (const auto dx = position_of(&Positions::dx)) pen_.x() += *dx;
                    if (const auto dy = position_of(&Positions::dy)) pen_.y() += *dy;
                    for (Positions& l : levels_) ++l.next;
                    if (size == 0.0) continue;
                    TextCurves t = text_curves(ch, Vec2::Zero(), layout, "", label);
                    missing += t.missing;
                    for (Curve& c : t.curves) {
                        for (Segment& seg : c.segments) {
                            auto& l = std::get<LineSegment>(seg);
                            l.a = Vec2(pen_.x() + l.a.x(), pen_.y() - l.a.y());
                            l.b = Vec2(pen_.x() + l.b.x(), pen_.y() - l.b.y());
                        }
                        r.curves.push_back(std::move(c));
                    }
                    pen_.x() += t.advance + letter + (ch == " " ? word : 0.0);
                }
                if (!missing.empty() && missing_->size() < 3)
                    missing_->push_back(label + " ('" + text::printable(missing, 40) + "')");
                emit(std::move(r), e, out);
                continue;
            }
            XMLElement* c = n->ToElement();
            if (!c || !svg_xml::is_svg_element(c)) continue;
            const std::string_view name = svg_xml::local_name(c->Name());
            if (name == "tspan" || name == "a") {
                XMLElement* g = doc_->NewElement("g");
                for (const char* a : {"style", "fill", "stroke", "display", "visibility"}) {
                    if (const char* v = c->Attribute(a)) g->SetAttribute(a, v);
                }
                named_after(g, c);
                out->InsertEndChild(g);
                run(c, g, depth + 1);
            } else if (!kNotDrawn.count(name)) {
                throw InputError(element_label(c),
                                 "text " + std::string(name) + " cannot be honoured (only tspan)");
            }
        }
        // Its characters were counted as its ancestors' characters too.
        levels_.pop_back();
    }

    /// The length of the UTF-8 sequence a byte begins (1 for anything else):
    /// a list's value places one character, not one byte.
    static std::size_t utf8_length(char byte) {
        const auto c = static_cast<unsigned char>(byte);
        if (c >= 0xF0 && c < 0xF8) return 4;
        if (c >= 0xE0) return c < 0xF0 ? 3 : 1;
        if (c >= 0xC0) return 2;
        return 1;
    }

    /// A run of characters of one text node within one chunk becomes a path.
    void emit(Run&& r, XMLElement* e, XMLElement* out) {
        if (r.curves.empty()) return;
        r.path = doc_->NewElement("path");
        named_after(r.path, e);
        out->InsertEndChild(r.path);
        chunk_.push_back(std::move(r));
    }

    void named_after(XMLElement* made, XMLElement* e) {
        made->SetAttribute(kNameAttribute, element_name(e).c_str());
        made->SetAttribute("modsynth:line", e->IntAttribute("modsynth:line", e->GetLineNum()));
        if (const char* use = e->Attribute("modsynth:use-line"))
            made->SetAttribute("modsynth:use-line", use);
    }

    /// The chunk ends: its runs move by its anchor, and are written.
    void flush_chunk() {
        const double width = pen_.x() - chunk_start_;
        const double shift = anchor_ == "middle" ? -width / 2.0 : anchor_ == "end" ? -width : 0.0;
        for (const Run& r : chunk_) {
            std::string d;
            char number[64];
            const auto put = [&](char command, const Vec2& p) {
                std::snprintf(number, sizeof number, "%c%.12g,%.12g ", command, p.x() + shift,
                              p.y());
                d += number;
            };
            for (const Curve& c : r.curves) {
                put('M', std::get<LineSegment>(c.segments.front()).a);
                for (const Segment& s : c.segments) put('L', std::get<LineSegment>(s).b);
            }
            r.path->SetAttribute("d", d.c_str());
        }
        chunk_.clear();
        chunk_start_ = pen_.x();
    }

    tinyxml2::XMLDocument* doc_;
    std::vector<std::string>* missing_;
    std::map<const tinyxml2::XMLNode*, std::string> text_;
    Vec2 pen_ = Vec2::Zero();
    double chunk_start_ = 0.0;
    std::string anchor_;
    std::vector<Run> chunk_;
    std::vector<Positions> levels_;
};

/// Replaces every rendered `text` under `e` by the paths of its glyphs;
/// one that is not rendered is left for the check to pass over. Notes in
/// `missing` (the first few) the texts with characters the font lacks.
void render(XMLElement* e, const Rendering& rendering, tinyxml2::XMLDocument& doc,
            std::vector<std::string>& missing) {
    for (XMLElement* c = e->FirstChildElement(); c;) {
        XMLElement* next = c->NextSiblingElement();
        const std::string_view name = svg_xml::local_name(c->Name());
        if (!svg_xml::is_svg_element(c) || kNotDrawn.count(name)) {
            c = next;
            continue;
        }
        const Rendering own = rendering.of(c);
        if (name == "text" && own.drawn()) {
            XMLElement* g = doc.NewElement("g");
            for (const tinyxml2::XMLAttribute* a = c->FirstAttribute(); a; a = a->Next()) {
                const std::string_view n = a->Name();
                if (n != "x" && n != "y" && n != "dx" && n != "dy")
                    g->SetAttribute(a->Name(), a->Value());
            }
            if (!c->Attribute("modsynth:line")) g->SetAttribute("modsynth:line", c->GetLineNum());
            Writer(doc, missing).write(c, g);
            e->InsertAfterChild(c, g);
            e->DeleteChild(c);
        } else if (name != "text") {
            render(c, own, doc, missing);
        }
        c = next;
    }
}

}  // namespace svg_text

/// Walks what SVG++ will walk, before it does: every element must be one
/// that can be drawn (or one that draws nothing), so that nothing in the
/// drawing is dropped without a word. Elements that are not rendered
/// (display none, visibility hidden) are not drawn: the shapes among them
/// go to `not_drawn`, and an element that cannot be drawn is no error there.
/// Sets `layer_seen` when the obstacle layer was seen.
void check_elements(XmlElement e, const Rendering& rendering, const ReadOptions& options,
                    std::vector<std::string>& unsupported, std::set<XmlElement>& not_drawn,
                    std::set<XmlElement>& outlines, bool& layer_seen, std::size_t& count) {
    for (XmlElement c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
        if (!svg_xml::is_svg_element(c)) continue;
        if (++count > kMaxCurves) {
            throw InputError("(document)", "more than " + std::to_string(kMaxCurves) +
                                               " elements: too large for a drawing");
        }
        const std::string_view name = svg_xml::local_name(c->Name());
        if (kNotDrawn.count(name)) continue;
        const Rendering own = rendering.of(c);
        if (kShapes.count(name)) {
            if (!own.drawn()) not_drawn.insert(c);
            // A text's glyphs are centrelines already, however it is painted.
            if (own.drawn() && own.outline_only() && !c->Attribute(kNameAttribute))
                outlines.insert(c);
            continue;
        }
        if (kContainers.count(name)) {
            if (!options.obstacle_layer.empty() && name == "g") {
                const char* id = c->Attribute("id");
                const char* label = c->Attribute("inkscape:label");
                if ((id && options.obstacle_layer == id) ||
                    (label && options.obstacle_layer == label)) {
                    layer_seen = true;
                }
            }
            check_elements(c, own, options, unsupported, not_drawn, outlines, layer_seen, count);
            continue;
        }
        if (!own.drawn()) continue;
        std::string why;
        if (name == "image") why = " (a bitmap has no strokes)";
        unsupported.push_back(element_label(c) + why);
    }
}

/// Points of clip outline a drawing may take in all (a curve of a clip path
/// is 256 of them): 64 MB, where a hundred clipped letters take a few
/// thousand.
constexpr std::size_t kMaxClipPoints = 4'000'000;

/// Shared by every element's context: what has been read so far.
struct SvgState {
    const ReadOptions* options = nullptr;
    /// Shapes that are not rendered (display none, visibility hidden).
    std::set<XmlElement> not_drawn;
    /// Shapes filled and not stroked: their outlines are traced.
    std::set<XmlElement> outlines;
    std::size_t outlines_traced = 0;
    std::vector<Curve> curves;  ///< in the outer viewport's pixels, y down
    /// For each curve, the element that drew it and the clip regions
    /// (indices in `clips`) that apply to it.
    std::vector<XmlElement> curve_elements;
    std::vector<std::vector<std::size_t>> curve_clips;
    /// The file's clipPath elements by id, and the regions they clip to
    /// where they are used.
    std::map<std::string, XmlElement, std::less<>> clip_paths;
    std::vector<svg_clip::Region> clips;
    /// The region of each clipPath in each user space it was used in, an
    /// index in `clips`: elements clipped alike share one region, however
    /// many there are.
    std::map<std::pair<XmlElement, std::array<double, 6>>, std::size_t> clip_of;
    /// Points of every region's outline: the clipping's memory and work.
    std::size_t clip_points = 0;
    std::vector<geometry::Disc> obstacles;
    /// Subpaths of zero length (an icon's dots, drawn by round caps),
    /// skipped: a stroke of the tool cannot make a dot.
    std::vector<std::string> dots;
    std::size_t dot_count = 0;
    std::size_t segments = 0;
    double page_width = 0.0, page_height = 0.0;  ///< the outer viewport, px
    bool have_page = false;
};

/// The region `clip_path` clips to, in the outer viewport's pixels, for an
/// element whose user space maps there by `ctm`; `user` names that element.
svg_clip::Region clip_region(XmlElement clip_path, const Affine& ctm, const std::string& user,
                             const SvgState& state);

class BaseContext {
public:
    explicit BaseContext(SvgState& state) : state_(&state) {
        length_factory_.set_absolute_units_coefficient(kPxPerInch, svgpp::tag::length_units::in());
    }

    /// The element's clip-path, if any, applies to all it draws, in its
    /// user space: resolved once that is known (its transform read).
    void clip_by(XmlElement e) {
        if (!property(e, "clip-path").empty() && property(e, "clip-path") != "none")
            clip_element_ = e;
    }
    /// This context, its clip resolved: what a child starts from.
    BaseContext& resolved() {
        if (!clip_element_) return *this;
        const XmlElement e = clip_element_;
        clip_element_ = nullptr;
        const std::string value = property(e, "clip-path", true);
        std::string id;
        if (value.size() > 6 && lower(value.substr(0, 4)) == "url(" && value.back() == ')') {
            std::string_view ref = trimmed(std::string_view(value).substr(4, value.size() - 5));
            if (ref.size() >= 2 && (ref.front() == '"' || ref.front() == '\'') &&
                ref.back() == ref.front())
                ref = ref.substr(1, ref.size() - 2);
            if (!ref.empty() && ref.front() == '#') id = std::string(ref.substr(1));
        }
        const auto found = state_->clip_paths.find(id);
        if (found == state_->clip_paths.end()) {
            throw InputError(element_label(e), "clip-path '" + text::printable(value, 60) +
                                                   "' does not name a clipPath of the file");
        }
        const std::array<double, 6> space = {ctm_.m(0, 0), ctm_.m(0, 1),    ctm_.m(1, 0),
                                             ctm_.m(1, 1), ctm_.offset.x(), ctm_.offset.y()};
        const auto key = std::make_pair(found->second, space);
        if (const auto known = state_->clip_of.find(key); known != state_->clip_of.end()) {
            clips_.push_back(known->second);
            return *this;
        }
        check_deadline(state_->options->deadline, "reading the clip paths");
        svg_clip::Region region = clip_region(found->second, ctm_, element_label(e), *state_);
        for (const auto& shape : region.shapes)
            for (const auto& ring : shape.rings) state_->clip_points += ring.size();
        if (state_->clip_points > kMaxClipPoints)
            throw InputError(element_label(e),
                             "its clip paths take more than " + std::to_string(kMaxClipPoints) +
                                 " points of outline in all: too large for a drawing");
        state_->clip_of.emplace(key, state_->clips.size());
        clips_.push_back(state_->clips.size());
        state_->clips.push_back(std::move(region));
        return *this;
    }

    void on_exit_element() {}

    void transform_matrix(const boost::array<double, 6>& m) {
        Affine a;
        a.m << m[0], m[2], m[1], m[3];
        a.offset = Vec2(m[4], m[5]);
        ctm_ = ctm_.after(a);
    }

    void set_viewport(double x, double y, double width, double height) {
        length_factory_.set_viewport_size(width, height);
        if (!state_->have_page) {
            state_->have_page = true;
            state_->page_width = x + width;
            state_->page_height = y + height;
        }
    }
    void set_viewbox_size(double width, double height) {
        length_factory_.set_viewport_size(width, height);
    }
    void get_reference_viewport_size(double&, double&) {}
    /// A viewport of zero width or height shows nothing (SVG 1.1, 7.7).
    void disable_rendering() { hidden_ = true; }

    typedef svgpp::factory::length::unitless<> length_factory_type;
    const length_factory_type& length_factory() const { return length_factory_; }
    /// The outer svg's percentages refer to a viewport of this size.
    void set_reference_size(double width, double height) {
        length_factory_.set_viewport_size(width, height);
    }

protected:
    SvgState* state_;
    Affine ctm_;
    /// The clip regions (indices in SvgState::clips) of the element and
    /// its ancestors; an element whose clip-path is not resolved yet.
    std::vector<std::size_t> clips_;
    XmlElement clip_element_ = nullptr;
    length_factory_type length_factory_;
    bool hidden_ = false;
};

class GroupContext : public BaseContext {
public:
    template <class Parent>
    GroupContext(Parent& parent, XmlElement e) : BaseContext(parent.resolved()) {
        clip_by(e);
    }
};

class ShapeContext : public BaseContext {
public:
    template <class Parent>
    ShapeContext(Parent& parent, XmlElement element)
        : BaseContext(parent.resolved()), element_(element), label_(element_label(element)) {
        clip_by(element);
        obstacle_ = !state_->options->obstacle_layer.empty() &&
                    in_layer(element, state_->options->obstacle_layer);
        if (state_->not_drawn.count(element)) hidden_ = true;
    }

    void path_move_to(double x, double y, svgpp::tag::coordinate::absolute) {
        flush();
        current_ = start_ = Vec2(x, y);
        ++commands_;
    }
    void path_line_to(double x, double y, svgpp::tag::coordinate::absolute) {
        add(LineSegment{current_, Vec2(x, y)});
    }
    void path_cubic_bezier_to(double x1, double y1, double x2, double y2, double x, double y,
                              svgpp::tag::coordinate::absolute) {
        add(CubicBezier{current_, Vec2(x1, y1), Vec2(x2, y2), Vec2(x, y)});
    }
    void path_quadratic_bezier_to(double x1, double y1, double x, double y,
                                  svgpp::tag::coordinate::absolute) {
        // Degree elevation: the same curve, exactly.
        const Vec2 q(x1, y1), end(x, y);
        add(CubicBezier{current_, current_ + 2.0 / 3.0 * (q - current_),
                        end + 2.0 / 3.0 * (q - end), end});
    }
    void path_elliptical_arc_to(double rx, double ry, double rotation, bool large, bool sweep,
                                double x, double y, svgpp::tag::coordinate::absolute) {
        const Vec2 end(x, y);
        if (const auto arc = arc_from_endpoints(current_, end, rx, ry, rotation, large, sweep)) {
            add(*arc);
        } else if (rx == 0.0 || ry == 0.0 || end == current_) {
            add(LineSegment{current_, end});  // zero radius: a line (SVG 1.1 F.6.2)
        } else {
            throw InputError(label_, "an arc of radii " + text::compact(rx) + " and " +
                                         text::compact(ry) + " that no ellipse can draw");
        }
    }
    void path_close_subpath() {
        if (!pending_.empty() && (current_ - start_).norm() > 0.0) {
            add(LineSegment{current_, start_});
        }
        flush();
        current_ = start_;
    }
    void path_exit() { flush(); }

    void set_circle(double cx, double cy, double r) { set_ellipse(cx, cy, r, r); }
    void set_ellipse(double cx, double cy, double rx, double ry) {
        ++commands_;
        if (hidden_) return;
        if (!(rx > 0.0) || !(ry > 0.0)) throw InputError(label_, "zero-length curve (radius 0)");
        EllipticArc e{Vec2(cx, cy), Vec2(rx, 0.0), Vec2(0.0, ry), 0.0, geometry::kTau};
        if (obstacle_) {
            const EllipticArc placed = std::get<EllipticArc>(transformed(e, ctm_));
            if (!is_circular(placed)) {
                throw InputError(label_, "an obstacle must be a circle, not an ellipse");
            }
            state_->obstacles.push_back({placed.center, placed.u.norm()});
            return;
        }
        pending_.push_back(e);
        flush();
    }

    void on_exit_element() {
        flush();
        if (commands_ == 0 && !hidden_)
            throw InputError(label_, "zero-length curve (nothing to draw)");
    }

private:
    void add(const Segment& s) {
        ++commands_;
        if (++state_->segments > kMaxSegments) {
            throw InputError(label_, "more than " + std::to_string(kMaxSegments) +
                                         " segments in the drawing: too large");
        }
        current_ = end_point(s);
        pending_.push_back(s);
    }

    /// Ends the subpath: its non-degenerate segments, mapped to the outer
    /// viewport, become one curve.
    void flush() {
        if (pending_.empty()) return;
        if (hidden_) {
            pending_.clear();
            return;
        }
        if (obstacle_) throw InputError(label_, "only circles can be obstacles");
        Curve c;
        c.source = label_;
        for (const Segment& s : pending_) {
            for (const Vec2& p : {start_point(s), end_point(s)}) {
                if (!std::isfinite(p.x()) || !std::isfinite(p.y()) ||
                    p.cwiseAbs().maxCoeff() > kMaxDrawingCoordinate) {
                    throw InputError(label_, "coordinate out of range (beyond 1e9 units)");
                }
            }
            // A zero-length piece draws nothing (Inkscape closes a path on
            // its last point); the whole subpath must still draw something.
            if (approximate_length(s, 8) > 0.0) c.segments.push_back(transformed(s, ctm_));
        }
        pending_.clear();
        if (c.segments.empty()) {
            if (state_->options->strict) throw InputError(label_, "zero-length curve");
            if (state_->dots.size() < 3) state_->dots.push_back(label_);
            ++state_->dot_count;
            return;
        }
        resolved();
        if (!outline_counted_ && state_->outlines.count(element_)) {
            outline_counted_ = true;
            ++state_->outlines_traced;
        }
        state_->curves.push_back(std::move(c));
        state_->curve_elements.push_back(element_);
        state_->curve_clips.push_back(clips_);
    }

    XmlElement element_;
    std::string label_;
    bool obstacle_ = false;
    bool outline_counted_ = false;
    std::vector<Segment> pending_;
    Vec2 current_ = Vec2::Zero(), start_ = Vec2::Zero();
    int commands_ = 0;
};

struct ChildContextFactories {
    template <class ParentContext, class ElementTag, class Enable = void>
    struct apply {
        typedef svgpp::factory::context::on_stack_with_xml_element<GroupContext> type;
    };
};

template <class ParentContext, class ElementTag>
struct ChildContextFactories::apply<ParentContext, ElementTag,
                                    typename boost::enable_if<boost::mpl::has_key<
                                        svgpp::traits::shape_elements, ElementTag>>::type> {
    typedef svgpp::factory::context::on_stack_with_xml_element<ShapeContext> type;
};

struct AttributeTraversal : svgpp::policy::attribute_traversal::default_policy {
    // Styles hold nothing the strokes need, and Inkscape's hold properties
    // SVG++ does not know.
    static const bool parse_style = false;
    typedef boost::mpl::if_<
        boost::mpl::has_key<boost::mpl::set<svgpp::tag::element::svg>, boost::mpl::_1>,
        boost::mpl::vector<
            svgpp::tag::attribute::x, svgpp::tag::attribute::y, svgpp::tag::attribute::width,
            svgpp::tag::attribute::height, svgpp::tag::attribute::viewBox,
            svgpp::tag::attribute::preserveAspectRatio,
            svgpp::notify_context<svgpp::tag::event::after_viewport_attributes>>::type,
        boost::mpl::empty_sequence>
        get_priority_attributes_by_element;
};

/// Circles and ellipses arrive whole (exact elliptic arcs, and obstacles);
/// the other shapes as paths.
struct BasicShapes {
    typedef boost::mpl::set4<svgpp::tag::element::rect, svgpp::tag::element::line,
                             svgpp::tag::element::polyline, svgpp::tag::element::polygon>
        convert_to_path;
    typedef boost::mpl::set2<svgpp::tag::element::circle, svgpp::tag::element::ellipse>
        collect_attributes;
    static const bool convert_only_rounded_rect_to_path = false;
};

/// Every command arrives absolute, without shorthands; quadratic Béziers
/// and arcs as themselves.
struct PathPolicy {
    static const bool absolute_coordinates_only = true;
    static const bool no_ortho_line_to = true;
    static const bool no_quadratic_bezier_shorthand = true;
    static const bool no_cubic_bezier_shorthand = true;
    static const bool quadratic_bezier_as_cubic = false;
    static const bool arc_as_cubic_bezier = false;
};

/// SVG++'s errors, except that attributes it does not know (data-*, ...)
/// are ignored like those of other namespaces.
template <class Context>
struct ErrorPolicy : svgpp::policy::error::raise_exception<Context> {
    template <class XMLAttribute, class AttributeName>
    static bool unknown_attribute(const Context&, const XMLAttribute&, const AttributeName&,
                                  BOOST_SCOPED_ENUM(svgpp::detail::namespace_id),
                                  svgpp::tag::source::attribute) {
        return true;
    }
    template <class XMLAttribute, class AttributeName>
    static bool unknown_attribute(const Context&, const XMLAttribute&, const AttributeName&,
                                  svgpp::tag::source::css) {
        return true;
    }
};

typedef boost::mpl::fold<svgpp::traits::shape_elements,
                         boost::mpl::set<svgpp::tag::element::svg, svgpp::tag::element::g>::type,
                         boost::mpl::insert<boost::mpl::_1, boost::mpl::_2>>::type
    ProcessedElements;

typedef boost::mpl::fold<
    boost::mpl::protect<boost::mpl::joint_view<svgpp::traits::shapes_attributes_by_element,
                                               svgpp::traits::viewport_attributes>>,
    boost::mpl::set<svgpp::tag::attribute::transform>::type,
    boost::mpl::insert<boost::mpl::_1, boost::mpl::_2>>::type ProcessedAttributes;

typedef svgpp::document_traversal<
    svgpp::processed_elements<ProcessedElements>, svgpp::processed_attributes<ProcessedAttributes>,
    svgpp::viewport_policy<svgpp::policy::viewport::as_transform>,
    svgpp::context_factories<ChildContextFactories>,
    svgpp::length_policy<svgpp::policy::length::forward_to_method<BaseContext>>,
    svgpp::attribute_traversal_policy<AttributeTraversal>, svgpp::basic_shapes_policy<BasicShapes>,
    svgpp::path_policy<PathPolicy>, svgpp::error_policy<ErrorPolicy<BaseContext>>>
    DocumentTraversal;

/// tinyxml2 compares each attribute with the element's earlier ones (an
/// element of a million attributes takes hours) and spends far more memory
/// on a node than its bytes: elements and attributes are counted before it
/// parses, delimited as it delimits them.
void check_xml_size(std::string_view text) {
    constexpr std::size_t kMaxElements = 8 * kMaxCurves;
    constexpr std::size_t kMaxAttributes = 16 * kMaxCurves;
    constexpr std::size_t kMaxOwnAttributes = 256;
    const auto line_of = [&](std::size_t at) {
        return std::to_string(1 + std::count(text.begin(), text.begin() + at, '\n'));
    };
    std::size_t elements = 0, attributes = 0;
    for (std::size_t at = text.find('<'); at != std::string_view::npos; at = text.find('<', at)) {
        const std::string_view rest = text.substr(at);
        const auto skip_past = [&](std::string_view end) {
            const auto found = text.find(end, at + 1);
            return found == std::string_view::npos ? text.size() : found + end.size();
        };
        if (rest.substr(0, 4) == "<!--") {
            at = skip_past("-->");
        } else if (rest.substr(0, 9) == "<![CDATA[") {
            at = skip_past("]]>");
        } else if (rest.substr(0, 2) == "<?") {
            at = skip_past("?>");
        } else if (rest.substr(0, 2) == "<!" || rest.substr(0, 2) == "</") {
            at = skip_past(">");
        } else {
            // A start tag: name="value" pairs, a quoted value holding anything
            // but its quote.
            std::size_t own = 0, k = at + 1;
            for (; k < text.size() && text[k] != '>'; ++k) {
                if (text[k] == '"' || text[k] == '\'') {
                    k = std::min(text.find(text[k], k + 1), text.size() - 1);
                } else if (text[k] == '=') {
                    ++own;
                }
            }
            if (own > kMaxOwnAttributes) {
                throw InputError("(document)", "an element (line " + line_of(at) +
                                                   ") with more than " +
                                                   std::to_string(kMaxOwnAttributes) +
                                                   " attributes: too large for a drawing");
            }
            attributes += own;
            if (++elements > kMaxElements || attributes > kMaxAttributes) {
                throw InputError("(document)", "more than " + std::to_string(kMaxElements) +
                                                   " elements or " +
                                                   std::to_string(kMaxAttributes) +
                                                   " attributes: too large for a drawing");
            }
            at = k;
        }
    }
}

std::string quoted(const std::string& value) { return "'" + text::printable(value, 60) + "'"; }

/// What SVG++ throws, as an error naming the element it was reading.
[[noreturn]] void rethrow_svgpp(const svgpp::exception_base& e) {
    typedef boost::error_info<svgpp::tag::error_info::xml_element, XmlElement> ElementInfo;
    const XmlElement* where = boost::get_error_info<ElementInfo>(e);
    const std::string part = where ? element_label(*where) : "(document)";
    if (const auto* bad = dynamic_cast<const svgpp::invalid_value_error<char>*>(&e)) {
        if (bad->name() == "d")
            throw InputError(part, "malformed path data " + quoted(bad->value()));
        throw InputError(part, "malformed attribute " + text::printable(bad->name()) + "=" +
                                   quoted(bad->value()));
    }
    throw InputError(part, text::printable(e.what(), 200));
}

/// A rect without a width or height is as large as auto, which is 0 for
/// a rect: not rendered (SVG 2, 10.4), so taken out before the walk (which
/// requires both).
void drop_unsized_rects(tinyxml2::XMLElement* e) {
    for (tinyxml2::XMLElement* c = e->FirstChildElement(); c;) {
        tinyxml2::XMLElement* next = c->NextSiblingElement();
        if (svg_xml::is_svg_element(c) &&
            std::strcmp(svg_xml::local_name(c->Name()), "rect") == 0 &&
            (!c->Attribute("width") || !c->Attribute("height"))) {
            e->DeleteChild(c);
        } else {
            drop_unsized_rects(c);
        }
        c = next;
    }
}

void index_clip_paths(XmlElement e, std::map<std::string, XmlElement, std::less<>>& out) {
    for (XmlElement c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
        if (!svg_xml::is_svg_element(c)) continue;
        const char* id = c->Attribute("id");
        if (id && std::strcmp(svg_xml::local_name(c->Name()), "clipPath") == 0) out.emplace(id, c);
        index_clip_paths(c, out);
    }
}

svg_clip::Region clip_region(XmlElement clip_path, const Affine& ctm, const std::string& user,
                             const SvgState& state) {
    const std::string what = "its clip-path " + element_label(clip_path);
    const char* units = clip_path->Attribute("clipPathUnits");
    if (units && trimmed(units) == "objectBoundingBox") {
        throw InputError(user, what + " is in objectBoundingBox units, which cannot be honoured");
    }
    if (!property(clip_path, "clip-path").empty() && property(clip_path, "clip-path") != "none")
        throw InputError(user, what + " is clipped itself, which cannot be honoured");
    // Nor can a shape of it that has a clip of its own (wherever that clip
    // is defined): said so, not called missing.
    const std::function<void(XmlElement)> no_inner_clips = [&](XmlElement e) {
        for (XmlElement c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
            const std::string inner = property(c, "clip-path");
            if (!inner.empty() && inner != "none")
                throw InputError(user, what + " holds " + element_label(c) + " clipped by '" +
                                           text::printable(inner, 60) +
                                           "', a clip inside a clip, which cannot be honoured");
            no_inner_clips(c);
        }
    };
    no_inner_clips(clip_path);
    // The clip path's shapes are read as a drawing of their own, in the
    // user space of the element they clip.
    tinyxml2::XMLDocument doc;
    tinyxml2::XMLElement* root = doc.NewElement("svg");
    doc.InsertEndChild(root);
    tinyxml2::XMLElement* g = doc.NewElement("g");
    root->InsertEndChild(g);
    for (const char* inherited : {"transform", "clip-rule", "display", "visibility", "style"}) {
        if (const char* v = clip_path->Attribute(inherited)) g->SetAttribute(inherited, v);
    }
    for (XmlElement c = clip_path->FirstChildElement(); c; c = c->NextSiblingElement())
        g->InsertEndChild(svg_use::copy_of(c, doc));
    const ReadOptions options;
    SvgState sub;
    sub.options = &options;
    std::vector<std::string> unsupported;
    bool layer_seen = false;
    std::size_t count = 0;
    Rendering any_paint;
    any_paint.paint_matters = false;
    check_elements(root, any_paint, options, unsupported, sub.not_drawn, sub.outlines, layer_seen,
                   count);
    if (!unsupported.empty()) {
        throw InputError(
            user, what + " holds " + unsupported.front() + ", which cannot be honoured as a clip");
    }
    BaseContext context(sub);
    context.set_reference_size(state.page_width > 0.0 ? state.page_width : 1000.0,
                               state.page_height > 0.0 ? state.page_height : 1000.0);
    DocumentTraversal::load_document(static_cast<XmlElement>(root), context);

    svg_clip::Region region;
    std::map<XmlElement, std::size_t> shape_of;
    double extent = 1.0;
    for (std::size_t i = 0; i < sub.curves.size(); ++i) {
        const XmlElement e = sub.curve_elements[i];
        auto [at, added] = shape_of.emplace(e, region.shapes.size());
        if (added) {
            svg_clip::Shape shape;
            // clip-rule is inherited: the nearest element that sets it.
            for (const tinyxml2::XMLNode* n = e; n && n->ToElement(); n = n->Parent()) {
                const std::string rule = property(n->ToElement(), "clip-rule");
                if (rule.empty() || rule == "inherit") continue;
                shape.even_odd = rule == "evenodd";
                break;
            }
            region.shapes.push_back(std::move(shape));
        }
        std::vector<Vec2> ring;
        const Curve& c = sub.curves[i];
        if (c.segments.empty()) continue;
        ring.push_back(start_point(c.segments.front()));
        for (const Segment& s : c.segments) svg_clip::flatten(s, ring);
        for (Vec2& p : ring) {
            p = ctm(p);
            extent = std::max(extent, p.cwiseAbs().maxCoeff());
        }
        region.shapes[at->second].rings.push_back(std::move(ring));
    }
    region.margin = 1e-9 * extent;
    return region;
}

}  // namespace

Drawing read_svg(std::string_view text, const ReadOptions& options) {
    if (!options.layers.empty())
        throw InputError("--layers", "layers are chosen in DXF files only, not in an SVG");
    if (text.size() > kMaxDrawingBytes) {
        throw InputError("(document)", "the file is larger than " +
                                           std::to_string(kMaxDrawingBytes >> 20) + " MB");
    }
    check_xml_size(text);
    tinyxml2::XMLDocument doc;
    if (doc.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS) {
        throw InputError("(document)", std::string("not an SVG file: XML error at line ") +
                                           std::to_string(doc.ErrorLineNum()) + ": " +
                                           doc.ErrorName());
    }
    XmlElement root = doc.RootElement();
    if (!root || std::strcmp(svg_xml::local_name(root->Name()), "svg") != 0) {
        throw InputError("(document)", "not an SVG file: the root element is <" +
                                           text::printable(root ? root->Name() : "") +
                                           ">, not <svg>");
    }
    svg_use::expand(doc);
    drop_unsized_rects(doc.RootElement());
    std::vector<std::string> missing_glyphs;
    svg_text::render(doc.RootElement(), Rendering{}.of(root), doc, missing_glyphs);
    std::vector<std::string> unsupported;
    SvgState state;
    state.options = &options;
    bool layer_seen = false;
    std::size_t count = 0;
    check_elements(root, Rendering{}.of(root), options, unsupported, state.not_drawn,
                   state.outlines, layer_seen, count);
    if (!unsupported.empty()) {
        // The first few by name; a message is for reading, not a list of
        // thousands.
        constexpr std::size_t kNamed = 10;
        std::string list;
        for (std::size_t i = 0; i < std::min(unsupported.size(), kNamed); ++i)
            list += (list.empty() ? "" : ", ") + unsupported[i];
        if (unsupported.size() > kNamed)
            list += " and " + std::to_string(unsupported.size() - kNamed) + " more";
        throw InputError(element_label(root), "elements that cannot be drawn: " + list);
    }
    if (!options.obstacle_layer.empty() && !layer_seen) {
        throw InputError("(document)", "no layer or group with id or label '" +
                                           text::printable(options.obstacle_layer) +
                                           "' (--obstacles-from)");
    }

    BaseContext context(state);
    // An outer svg without width and height is as large as its viewBox, in
    // pixels (what browsers show).
    double vb[4] = {0, 0, 0, 0};
    if (const char* v = root->Attribute("viewBox")) {
        std::sscanf(v, "%lf%*[ ,]%lf%*[ ,]%lf%*[ ,]%lf", &vb[0], &vb[1], &vb[2], &vb[3]);
    }
    const double ref_w = vb[2] > 0.0 ? vb[2] : 1000.0, ref_h = vb[3] > 0.0 ? vb[3] : 1000.0;
    context.set_reference_size(ref_w, ref_h);
    index_clip_paths(root, state.clip_paths);
    context.clip_by(root);
    try {
        DocumentTraversal::load_document(root, context);
    } catch (const svgpp::exception_base& e) {
        rethrow_svgpp(e);
    }
    // Clip paths cut the centrelines: what lies outside is not drawn.
    if (!state.clips.empty()) {
        std::vector<Curve> kept;
        for (std::size_t i = 0; i < state.curves.size(); ++i) {
            std::vector<Curve> pieces{std::move(state.curves[i])};
            for (const std::size_t clip : state.curve_clips[i]) {
                std::vector<Curve> inner;
                for (const Curve& p : pieces) {
                    for (Curve& q : svg_clip::clipped(p, state.clips[clip], options.deadline))
                        inner.push_back(std::move(q));
                }
                pieces = std::move(inner);
            }
            for (Curve& p : pieces) kept.push_back(std::move(p));
            if (kept.size() > kMaxCurves) {
                throw InputError("(document)", "more than " + std::to_string(kMaxCurves) +
                                                   " curves once clipped: too large for a drawing");
            }
        }
        state.curves = std::move(kept);
    }
    std::vector<std::string> warnings;
    if (!missing_glyphs.empty()) {
        std::string list;
        for (const std::string& m : missing_glyphs) list += (list.empty() ? "" : ", ") + m;
        warnings.push_back("left out characters without a glyph in the font: " + list);
    }
    if (state.dot_count > 0) {
        std::string list;
        for (const std::string& d : state.dots) list += (list.empty() ? "" : ", ") + d;
        if (state.dot_count > state.dots.size())
            list += " and " + std::to_string(state.dot_count - state.dots.size()) + " more";
        warnings.push_back("skipped dots (zero-length subpaths, which a stroke cannot draw): " +
                           list);
    }
    if (state.curves.empty()) {
        throw InputError("(document)",
                         "empty drawing: nothing to draw" +
                             (warnings.empty() ? std::string() : " (" + warnings[0] + ")"));
    }

    // Outer viewport pixels, y down -> millimetres, y up from the page's
    // bottom-left corner.
    Affine to_mm;
    to_mm.m << kMmPerPx, 0.0, 0.0, -kMmPerPx;
    to_mm.offset = Vec2(0.0, kMmPerPx * state.page_height);
    Drawing out;
    out.metres_per_unit = 1e-3;
    out.page_size = Vec2(state.page_width, state.page_height);
    out.page_to_units = to_mm;
    out.warnings = std::move(warnings);
    out.filled_outlines = state.outlines_traced;
    for (Curve& c : state.curves) {
        for (Segment& s : c.segments) s = transformed(s, to_mm);
        out.curves.push_back(std::move(c));
    }
    for (const geometry::Disc& d : state.obstacles) {
        out.obstacles.push_back({to_mm(d.center), kMmPerPx * d.radius});
    }
    return out;
}

}  // namespace modsynth::drawing
