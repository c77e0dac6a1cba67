#include <modsynth/drawing/dxf_reader.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <dxflib/dl_codes.h>
#include <dxflib/dl_creationadapter.h>
#include <dxflib/dl_dxf.h>

#include <modsynth/drawing/hershey_text.h>
#include <modsynth/task/input_error.h>
#include <modsynth/text/printable.h>

#include "dxf_hatch.h"
#include "elliptic_arc.h"

namespace modsynth::drawing {

namespace {

using task::InputError;

constexpr double kDegree = geometry::kPi / 180.0;

/// Metres per unit for the $INSUNITS codes a drawing for a robot may use.
double metres_per_insunit(int code) {
    switch (code) {
        case 1:
            return 0.0254;  // inches
        case 2:
            return 0.3048;  // feet
        case 4:
            return 1e-3;  // millimetres
        case 5:
            return 1e-2;  // centimetres
        case 6:
            return 1.0;  // metres
        case 14:
            return 0.1;  // decimetres
        default:
            return 0.0;  // unitless or exotic: the user says
    }
}

/// Collects entities as dxflib reports them. A polyline's vertices and a
/// spline's knots and control points arrive after the entity itself, so
/// those are kept open until the next entity starts.
class Collector : public DL_CreationAdapter {
public:
    Collector(const ReadOptions& options, std::vector<HatchBoundary> hatches)
        : options_(options), hatches_(std::move(hatches)) {}

    Drawing finish() {
        close_open();
        for (const InsertRef& r : model_inserts_) {
            std::vector<std::string> stack;
            expand(r, Affine{}, r.layer, stack);
        }
        if (!unsupported_.empty()) {
            if (options_.strict) {
                std::string list;
                for (const auto& [name, s] : unsupported_) {
                    list += (list.empty() ? "" : ", ") + name +
                            (s.count > 1 ? " (" + std::to_string(s.count) + "x)" : "");
                }
                throw InputError("(document)",
                                 "entities that cannot be drawn: " + list + " (--strict)");
            }
            drawing_.warnings.push_back("skipped what cannot be traced: " + listed(unsupported_) +
                                        (unsupported_.count("HATCH")
                                             ? " (--hatch-boundaries traces a hatch's outline)"
                                             : ""));
        }
        if (!degenerate_.empty())
            drawing_.warnings.push_back("skipped degenerate pieces: " + listed(degenerate_));
        for (const std::string& layer : options_.layers) {
            if (!drawing_.layers.count(layer)) {
                std::string found;
                for (const auto& [name, count] : drawing_.layers) {
                    found += (found.empty() ? "" : ", ") + text::printable(name) + " (" +
                             std::to_string(count) + ")";
                }
                throw InputError("--layers", "no layer '" + text::printable(layer) +
                                                 "' in the drawing; its layers: " + found);
            }
        }
        if (!options_.obstacle_layer.empty() && !layer_seen_) {
            throw InputError("(document)", "no layer '" + text::printable(options_.obstacle_layer) +
                                               "' (--obstacles-from)");
        }
        if (drawing_.curves.empty()) {
            throw InputError("(document)",
                             "empty drawing: nothing to draw" +
                                 (drawing_.warnings.empty() ? std::string()
                                                            : " (" + drawing_.warnings[0] + ")"));
        }
        drawing_.metres_per_unit = metres_per_insunit(insunits_);
        return std::move(drawing_);
    }

    /// Entities dxflib does not read at all, found before it ran, with the
    /// lines they begin on.
    void add_unread(const std::map<std::string, std::vector<std::size_t>>& unread) {
        for (const auto& [name, lines] : unread) {
            for (std::size_t line : lines)
                note(unsupported_, name, name + " (line " + std::to_string(line) + ")");
        }
    }

    void setVariableInt(const std::string& key, int value, int) override {
        if (key == "$INSUNITS") insunits_ = value;
    }

    // Entities inside a block are drawn only where an INSERT places them:
    // they are kept with the block, and drawn as finish() expands the
    // inserts.
    void addBlock(const DL_BlockData& d) override {
        close_open();
        in_block_ = true;
        block_name_ = d.name;
        block_count_ = 0;
        block_ = &blocks_[d.name];
        *block_ = Block{Vec2(d.bpx, d.bpy), {}, {}, {}};
    }
    void endBlock() override {
        close_open();
        in_block_ = false;
        block_ = nullptr;
    }
    // dxflib calls endSection() after every entity, a POLYLINE's header
    // included: its VERTEX entities come after it. A polyline ends where
    // its vertices do (endEntity: after an LWPOLYLINE's last vertex or a
    // POLYLINE's last VERTEX; endSequence: its SEQEND).
    void endSection() override { close_spline(); }
    void endEntity() override { close_open(); }
    void endSequence() override { close_open(); }

    void addLine(const DL_LineData& d) override {
        if (!begin("LINE")) return;
        add_curve({LineSegment{Vec2(d.x1, d.y1), Vec2(d.x2, d.y2)}});
    }
    void addArc(const DL_ArcData& d) override {
        if (!begin("ARC") || !positive_radius(d.radius)) return;
        // Counter-clockwise from angle1 to angle2, less than a turn apart
        // (equal angles: a full turn), whatever multiples of 360 they hold.
        const double a1 = std::fmod(d.angle1, 360.0);
        const double sweep = within_turn(d.angle2 - d.angle1, 360.0);
        add_curve({ocs(EllipticArc{Vec2(d.cx, d.cy), Vec2(d.radius, 0.0), Vec2(0.0, d.radius),
                                   a1 * kDegree, (a1 + sweep) * kDegree})});
    }
    void addCircle(const DL_CircleData& d) override {
        if (!begin("CIRCLE") || !positive_radius(d.radius)) return;
        const EllipticArc circle{Vec2(d.cx, d.cy), Vec2(d.radius, 0.0), Vec2(0.0, d.radius), 0.0,
                                 geometry::kTau};
        if (!in_block_ && on_obstacle_layer()) {
            const EllipticArc c = std::get<EllipticArc>(ocs(circle));
            check_point(c.center);
            drawing_.obstacles.push_back({c.center, d.radius});
            return;
        }
        add_curve({ocs(circle)});
    }
    void addEllipse(const DL_EllipseData& d) override {
        if (!begin("ELLIPSE")) return;
        // The minor axis is ratio times the major one: a ratio of 0 would
        // draw the major axis back and forth, a negative one mirror it.
        if (!(d.ratio > 0.0))
            fail("axis ratio " + text::compact(d.ratio) + ": it must be positive");
        const Vec2 major(d.mx, d.my);
        const double a1 = std::fmod(d.angle1, geometry::kTau);
        const double sweep = within_turn(d.angle2 - d.angle1, geometry::kTau);
        add_curve({EllipticArc{Vec2(d.cx, d.cy), major, d.ratio * geometry::perp(major), a1,
                               a1 + sweep}});
    }
    void addPolyline(const DL_PolylineData& d) override {
        // A polygon or polyface mesh is a 3D surface, its vertices faces.
        if (d.flags & (16 | 64)) {
            unsupported("POLYLINE (3D mesh)");
            return;
        }
        // Only an LWPOLYLINE counts its vertices (group 90).
        if (!begin(d.number > 0 ? "LWPOLYLINE" : "POLYLINE")) return;
        polyline_ = OpenPolyline{label_, layer_, (d.flags & 1) != 0, {}};
    }
    void addVertex(const DL_VertexData& d) override {
        if (!polyline_) return;
        if (polyline_->vertices.size() >= kMaxSegments) fail("too many vertices");
        polyline_->vertices.push_back({Vec2(d.x, d.y), d.bulge});
    }
    void addSpline(const DL_SplineData& d) override {
        if (!begin("SPLINE")) return;
        if (d.degree < 1 || static_cast<int>(d.degree) > kMaxSplineDegree) {
            fail("degree " + std::to_string(d.degree) + " is outside 1.." +
                 std::to_string(kMaxSplineDegree));
        }
        if (d.nControl > kMaxSplineControlPoints) fail("too many control points");
        spline_ =
            OpenSpline{label_, layer_, BSpline{static_cast<int>(d.degree), {}, {}, {}}, d.nFit};
    }
    void addControlPoint(const DL_ControlPointData& d) override {
        if (!spline_) return;
        if (spline_->spline.control.size() >= kMaxSplineControlPoints)
            fail("too many control points");
        spline_->spline.control.push_back(Vec2(d.x, d.y));
        spline_->spline.weights.push_back(d.w);
    }
    void addKnot(const DL_KnotData& d) override {
        if (!spline_) return;
        if (spline_->spline.knots.size() >= kMaxSplineControlPoints + kMaxSplineDegree + 1) {
            fail("too many knots");
        }
        spline_->spline.knots.push_back(d.k);
    }

    // What cannot be drawn, by name.
    // A point is a dot, which a stroke of the tool cannot make.
    void addPoint(const DL_PointData&) override { unsupported("POINT"); }
    void addXLine(const DL_XLineData&) override { unsupported("XLINE"); }
    void addRay(const DL_RayData&) override { unsupported("RAY"); }
    void addInsert(const DL_InsertData& d) override {
        if (!begin("INSERT")) return;
        InsertRef r{d, layer_, label_, extrusion_negative_};
        if (block_) {
            block_->inserts.push_back(std::move(r));
        } else {
            model_inserts_.push_back(std::move(r));
        }
    }
    void addTrace(const DL_TraceData&) override { unsupported("TRACE"); }
    void add3dFace(const DL_3dFaceData&) override { unsupported("3DFACE"); }
    void addSolid(const DL_SolidData&) override { unsupported("SOLID"); }
    // Text, in the Hershey font nearest the style's (hershey_text.h).
    void addTextStyle(const DL_StyleData& d) override {
        std::string file = d.primaryFontFile;
        std::transform(file.begin(), file.end(), file.begin(),
                       [](unsigned char c) { return std::tolower(c); });
        file = file.substr(0, file.rfind('.'));
        styles_[d.name] = hershey_font_for(file);
    }
    void addText(const DL_TextData& d) override {
        if (begin("TEXT")) add_text(d);
    }
    void addAttribute(const DL_AttributeData& d) override {
        if (begin("ATTRIB")) add_text(d);
    }
    void addMTextChunk(const std::string& chunk) override {
        if (mtext_chunks_.size() + chunk.size() <= kMaxTextBytes) mtext_chunks_ += chunk;
    }
    void addMText(const DL_MTextData& d) override {
        std::string whole = std::move(mtext_chunks_);
        mtext_chunks_.clear();
        if (!begin("MTEXT")) return;
        whole += d.text;
        TextLayout layout = text_style(d.style, d.height);
        if (!layout_ok(layout)) return;
        layout.line_spacing *=
            d.lineSpacingFactor > 0.0 && d.lineSpacingFactor <= 4.0 ? d.lineSpacingFactor : 1.0;
        // The direction vector, when given, decides the rotation (dxflib
        // turns one pointing left half a turn wrong).
        layout.rotation = d.dirx != 0.0 || d.diry != 0.0 ? std::atan2(d.diry, d.dirx) : d.angle;
        const int attachment =
            d.attachmentPoint >= 1 && d.attachmentPoint <= 9 ? d.attachmentPoint - 1 : 0;
        layout.vertical = attachment / 3 == 0   ? TextLayout::Vertical::Top
                          : attachment / 3 == 1 ? TextLayout::Vertical::Middle
                                                : TextLayout::Vertical::Bottom;
        layout.horizontal = attachment % 3 == 0   ? TextLayout::Horizontal::Left
                            : attachment % 3 == 1 ? TextLayout::Horizontal::Center
                                                  : TextLayout::Horizontal::Right;
        draw_text(mtext_plain(whole), Vec2(d.ipx, d.ipy), layout);
    }
    void addArcAlignedText(const DL_ArcAlignedTextData&) override { unsupported("ARCALIGNEDTEXT"); }
    void addDimAlign(const DL_DimensionData&, const DL_DimAlignedData&) override {
        unsupported("DIMENSION");
    }
    void addDimLinear(const DL_DimensionData&, const DL_DimLinearData&) override {
        unsupported("DIMENSION");
    }
    void addDimRadial(const DL_DimensionData&, const DL_DimRadialData&) override {
        unsupported("DIMENSION");
    }
    void addDimDiametric(const DL_DimensionData&, const DL_DimDiametricData&) override {
        unsupported("DIMENSION");
    }
    void addDimAngular(const DL_DimensionData&, const DL_DimAngular2LData&) override {
        unsupported("DIMENSION");
    }
    void addDimAngular3P(const DL_DimensionData&, const DL_DimAngular3PData&) override {
        unsupported("DIMENSION");
    }
    void addDimOrdinate(const DL_DimensionData&, const DL_DimOrdinateData&) override {
        unsupported("DIMENSION");
    }
    void addLeader(const DL_LeaderData&) override { unsupported("LEADER"); }
    // dxflib's hatch loops are not what the file holds (dxf_hatch.h), and
    // depend on an edge type it leaves uninitialised (tests/valgrind.supp):
    // the pre-scan read every boundary, in the order dxflib reports the
    // hatches.
    void addHatch(const DL_HatchData&) override {
        if (next_hatch_ >= hatches_.size())
            throw InputError("(document)", "a HATCH the reader did not scan");
        HatchBoundary hatch = std::move(hatches_[next_hatch_++]);
        if (hatch.layer != getAttributes().getLayer())
            throw InputError("(document)", "a HATCH read out of step with the reader's scan");
        // Circles of the obstacle layer are obstacles; a hatch there fills
        // one, and is not traced.
        if (!options_.hatch_boundaries || on_obstacle_layer()) {
            unsupported("HATCH");
            return;
        }
        if (!begin("HATCH")) return;
        if (!hatch.problem.empty()) fail(hatch.problem);
        const std::string hatch_label = label_;
        for (const std::string& edge : hatch.left_out) {
            const std::string where = hatch_label + " " + edge;
            if (block_) {
                block_->skips.push_back({false, "HATCH edges", where});
            } else {
                note(unsupported_, "HATCH edges", where);
            }
        }
        for (HatchBoundary::Run& run : hatch.runs) {
            const std::string label = hatch_label + " boundary path " + std::to_string(run.path);
            add_curve(std::move(run.segments), &label, &layer_);
        }
    }
    void addImage(const DL_ImageData&) override { unsupported("IMAGE"); }

private:
    static constexpr std::size_t kMaxTextBytes = 1u << 16;

    /// The Hershey font for an SHX or TrueType font's name: AutoCAD's
    /// roman, script, greek and gothic SHX fonts are Hershey's; anything
    /// else is written in the simplex sans serif.
    static std::string hershey_font_for(const std::string& file) {
        static const std::map<std::string, std::string, std::less<>> kNear = {
            {"romans", "rowmans"},    {"romand", "rowmand"},    {"romant", "rowmant"},
            {"romanc", "timesr"},     {"italicc", "timesi"},    {"italic", "timesi"},
            {"italict", "timesi"},    {"scripts", "scripts"},   {"scriptc", "scriptc"},
            {"greeks", "greeks"},     {"greekc", "greekc"},     {"gothice", "gothiceng"},
            {"gothicg", "gothicger"}, {"gothici", "gothicita"}, {"cyrillic", "cyrillic"},
            {"cyriltlc", "cyrilc_1"}, {"times", "timesr"},      {"timesbd", "timesrb"},
            {"timesi", "timesi"},     {"timesbi", "timesib"}};
        const auto found = kNear.find(file);
        return found == kNear.end() ? kDefaultFont : found->second;
    }

    TextLayout text_style(const std::string& style, double height) const {
        TextLayout layout;
        const auto found = styles_.find(style);
        if (found != styles_.end()) layout.font = found->second;
        layout.height = height;
        return layout;
    }

    /// A text of no height draws nothing; one of a height beyond the
    /// drawing's range is malformed.
    bool layout_ok(const TextLayout& layout) {
        if (layout.height == 0.0) {
            degenerate(label_, "zero text height");
            return false;
        }
        if (!(layout.height > 0.0) || layout.height > kMaxDrawingCoordinate)
            fail("text height " + text::compact(layout.height) + ": it must be positive");
        return true;
    }

    /// TEXT and ATTRIB: one line, placed by its justification (group codes
    /// 72 and 73/74) at the insertion point or the alignment point.
    void add_text(const DL_TextData& d) {
        TextLayout layout = text_style(d.style, d.height);
        if (!layout_ok(layout)) return;
        layout.rotation = d.angle;
        if (std::isfinite(d.xScaleFactor) && d.xScaleFactor > 0.0 && d.xScaleFactor <= 100.0)
            layout.width_factor = d.xScaleFactor;
        if (d.textGenerationFlags & 2) layout.width_factor = -layout.width_factor;  // mirrored
        Vec2 at(d.ipx, d.ipy);
        const std::string line = text_plain(d.text);
        const int h = d.hJustification, v = d.vJustification;
        if (h == 3 || h == 5) {
            // Aligned (3) or fit (5) between the two points: the baseline
            // runs from one to the other; aligned keeps the proportions.
            const Vec2 along = Vec2(d.apx, d.apy) - at;
            if (along.norm() > 0.0) {
                layout.rotation = std::atan2(along.y(), along.x());
                const double natural = text_width(line, layout);
                if (natural > 0.0) {
                    if (h == 5) {
                        layout.width_factor *= along.norm() / natural;
                    } else {
                        layout.height *= along.norm() / natural;
                    }
                }
            }
        } else if (h != 0 || v != 0) {
            at = Vec2(d.apx, d.apy);
            layout.horizontal = h == 1 || h == 4 ? TextLayout::Horizontal::Center
                                : h == 2         ? TextLayout::Horizontal::Right
                                                 : TextLayout::Horizontal::Left;
            layout.vertical = h == 4 || v == 2 ? TextLayout::Vertical::Middle
                              : v == 1         ? TextLayout::Vertical::Bottom
                              : v == 3         ? TextLayout::Vertical::Top
                                               : TextLayout::Vertical::Baseline;
        }
        draw_text(line, at, layout);
    }

    double text_width(const std::string& line, const TextLayout& layout) const {
        TextLayout flat = layout;
        flat.rotation = 0.0;
        double lo = 0.0, hi = 0.0;
        bool any = false;
        for (const Curve& c : text_curves(line, Vec2::Zero(), flat, label_).curves) {
            for (const Segment& s : c.segments) {
                for (const Vec2& p : {start_point(s), end_point(s)}) {
                    lo = any ? std::min(lo, p.x()) : p.x();
                    hi = any ? std::max(hi, p.x()) : p.x();
                    any = true;
                }
            }
        }
        return hi - lo;
    }

    void draw_text(const std::string& text, const Vec2& at, const TextLayout& layout) {
        TextCurves t = text_curves(text, at, layout, label_, label_);
        if (!t.missing.empty())
            note(unsupported_, "characters without a glyph",
                 label_ + " ('" + text::printable(t.missing, 40) + "')");
        for (Curve& c : t.curves) add_curve(std::move(c.segments));
    }

    /// DXF's control codes in a TEXT: %%d, %%p and %%c are the degree,
    /// plus-minus and diameter signs (which a Hershey ASCII font lacks:
    /// they are reported), %%u and %%o toggle under- and overlining
    /// (not drawn), %%% is a percent sign.
    static std::string text_plain(const std::string& in) {
        std::string out;
        for (std::size_t i = 0; i < in.size(); ++i) {
            if (in.compare(i, 2, "%%") == 0 && i + 2 < in.size()) {
                const char code = static_cast<char>(std::tolower(in[i + 2]));
                if (code == 'u' || code == 'o') {
                    i += 2;
                    continue;
                }
                if (code == '%' || code == 'd' || code == 'p' || code == 'c') {
                    out += code == '%'   ? "%"
                           : code == 'd' ? "\xC2\xB0"
                           : code == 'p' ? "\xC2\xB1"
                                         : "\xC3\x98";
                    i += 2;
                    continue;
                }
            }
            out += in[i];
        }
        return out;
    }

    static void append_utf8(std::string& out, unsigned code) {
        if (code < 0x80) {
            out += static_cast<char>(code);
        } else if (code < 0x800) {
            out += static_cast<char>(0xC0 | (code >> 6));
            out += static_cast<char>(0x80 | (code & 0x3F));
        } else {
            out += static_cast<char>(0xE0 | (code >> 12));
            out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (code & 0x3F));
        }
    }

    /// MTEXT's inline formatting reduced to its text: \P breaks the line,
    /// \~ is a space, \S stacks a fraction (written a/b), \U+XXXX is a
    /// character; font, height, colour, width, tracking, slant and
    /// alignment codes (\f..; \H..; \C..; ...), the underline and
    /// overline toggles and the {} groups are formatting only.
    static std::string mtext_plain(const std::string& in) {
        std::string out;
        for (std::size_t i = 0; i < in.size(); ++i) {
            const char c = in[i];
            if (c == '{' || c == '}') continue;
            if (c != '\\' || i + 1 >= in.size()) {
                out += c;
                continue;
            }
            const char k = in[++i];
            switch (k) {
                case 'P':
                case 'X':
                    out += '\n';
                    break;
                case '~':
                    out += ' ';
                    break;
                case '\\':
                case '{':
                case '}':
                    out += k;
                    break;
                case 'L':
                case 'l':
                case 'O':
                case 'o':
                case 'K':
                case 'k':
                case 'N':
                    break;
                case 'S': {
                    const std::size_t end = in.find(';', i);
                    std::string stacked = in.substr(
                        i + 1, end == std::string::npos ? std::string::npos : end - i - 1);
                    std::replace(stacked.begin(), stacked.end(), '^', '/');
                    std::replace(stacked.begin(), stacked.end(), '#', '/');
                    out += stacked;
                    i = end == std::string::npos ? in.size() : end;
                    break;
                }
                case 'U':
                    if (in.compare(i + 1, 1, "+") == 0 && i + 6 <= in.size()) {
                        unsigned code = 0;
                        const auto [p, ec] =
                            std::from_chars(in.data() + i + 2, in.data() + i + 6, code, 16);
                        if (ec == std::errc() && p == in.data() + i + 6) {
                            append_utf8(out, code);
                            i += 5;
                            break;
                        }
                    }
                    out += k;
                    break;
                default: {
                    // \f, \F, \H, \C, \c, \A, \W, \Q, \T, \p: up to ';'
                    const std::size_t end = in.find(';', i);
                    i = end == std::string::npos ? in.size() : end;
                    break;
                }
            }
        }
        return text_plain(out);
    }

    /// What was skipped, of one kind: how many, and the first few by name.
    struct Skipped {
        std::size_t count = 0;
        std::vector<std::string> where;
    };
    static constexpr std::size_t kNamedSkips = 3;

    static void note(std::map<std::string, Skipped>& to, const std::string& kind,
                     const std::string& where) {
        Skipped& s = to[kind];
        ++s.count;
        if (s.where.size() < kNamedSkips) s.where.push_back(where);
    }

    /// "HATCH #4 (layer 0), HATCH #9 (layer 0) and 3 more; POINT #2 (layer 0)"
    static std::string listed(const std::map<std::string, Skipped>& skipped) {
        std::string out;
        for (const auto& [kind, s] : skipped) {
            std::string these;
            for (const std::string& w : s.where) these += (these.empty() ? "" : ", ") + w;
            if (s.count > s.where.size())
                these += " and " + std::to_string(s.count - s.where.size()) + " more";
            out += (out.empty() ? "" : "; ") + these;
        }
        return out;
    }

    /// A block's own curves with their layers ("0": the layer of the
    /// INSERT that places them), the blocks it inserts, and what it holds
    /// that cannot be traced, reported where it is inserted.
    struct BlockCurve {
        Curve curve;
        std::string layer;
    };
    struct InsertRef {
        DL_InsertData data;
        std::string layer;
        std::string label;
        bool mirrored = false;
    };
    struct BlockSkip {
        bool degenerate = false;
        std::string kind, label;
    };
    struct Block {
        Vec2 base = Vec2::Zero();
        std::vector<BlockCurve> curves;
        std::vector<InsertRef> inserts;
        std::vector<BlockSkip> skips;
    };
    /// Block instances drawn, whatever they hold: nested arrays of empty
    /// blocks would otherwise take as long as they multiply.
    static constexpr std::size_t kMaxInstances = 100000;

    bool layer_chosen(const std::string& layer) const {
        return options_.layers.empty() || layer == options_.obstacle_layer ||
               std::find(options_.layers.begin(), options_.layers.end(), layer) !=
                   options_.layers.end();
    }

    /// Draws an INSERT: the block's curves through its transform, once per
    /// cell of its column and row array, nested inserts within.
    void expand(const InsertRef& r, const Affine& outer, const std::string& outer_layer,
                std::vector<std::string>& stack) {
        const DL_InsertData& d = r.data;
        const auto found = blocks_.find(d.name);
        if (found == blocks_.end())
            throw InputError(r.label, "no block named '" + text::printable(d.name) + "'");
        if (std::find(stack.begin(), stack.end(), d.name) != stack.end()) {
            std::string chain;
            for (const std::string& n : stack) chain += text::printable(n) + " -> ";
            throw InputError(r.label, "block '" + text::printable(d.name) + "' inserts itself (" +
                                          chain + text::printable(d.name) + ")");
        }
        for (double v : {d.ipx, d.ipy, d.sx, d.sy, d.angle, d.colSp, d.rowSp}) {
            if (!std::isfinite(v) || std::abs(v) > kMaxDrawingCoordinate)
                throw InputError(r.label, "a placement value out of range");
        }
        if (d.sx == 0.0 || d.sy == 0.0) {
            skipped_piece(true, "zero scale", r.label);
            return;
        }
        const long long cols = std::max(1, d.cols), rows = std::max(1, d.rows);
        if (cols * rows > static_cast<long long>(kMaxInstances))
            throw InputError(r.label, "an array of " + std::to_string(cols * rows) +
                                          " copies: too many to draw");
        const Block& block = found->second;
        const std::string layer = r.layer == "0" ? outer_layer : r.layer;
        const double a = d.angle * kDegree;
        Eigen::Matrix2d rotation;
        rotation << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
        const Eigen::Matrix2d m = rotation * Eigen::Vector2d(d.sx, d.sy).asDiagonal();
        stack.push_back(d.name);
        for (long long row = 0; row < rows; ++row) {
            for (long long col = 0; col < cols; ++col) {
                if (++instances_ > kMaxInstances)
                    throw InputError(r.label, "more than " + std::to_string(kMaxInstances) +
                                                  " block copies: too many to draw");
                Affine local;
                local.m = m;
                local.offset = Vec2(d.ipx, d.ipy) +
                               rotation * Vec2(double(col) * d.colSp, double(row) * d.rowSp) -
                               m * block.base;
                if (r.mirrored) {
                    Affine mirror;
                    mirror.m << -1.0, 0.0, 0.0, 1.0;
                    local = mirror.after(local);
                }
                const Affine world = outer.after(local);
                for (const BlockCurve& bc : block.curves) {
                    if (!layer_chosen(bc.layer == "0" ? layer : bc.layer)) continue;
                    Curve c;
                    c.source = bc.curve.source + " in " + r.label;
                    for (const Segment& seg : bc.curve.segments)
                        c.segments.push_back(transformed(seg, world));
                    add_model_curve(std::move(c));
                }
                // Copies of a block of many skipped entities count as much.
                instances_ += block.skips.size();
                if (instances_ > kMaxInstances)
                    throw InputError(r.label, "more than " + std::to_string(kMaxInstances) +
                                                  " block copies and entities: too many to draw");
                for (const BlockSkip& skip : block.skips)
                    skipped_piece(skip.degenerate, skip.kind, skip.label + " in " + r.label);
                for (const InsertRef& inner : block.inserts) expand(inner, world, layer, stack);
            }
        }
        stack.pop_back();
    }

    void skipped_piece(bool is_degenerate, const std::string& kind, const std::string& label) {
        if (is_degenerate) {
            if (options_.strict) throw InputError(label, kind);
            note(degenerate_, kind, label + " (" + kind + ")");
        } else {
            note(unsupported_, kind, label);
        }
    }

    /// A curve of the drawing itself, within the caps.
    void add_model_curve(Curve c) {
        for (const Segment& s : c.segments) {
            for (const Vec2& p : {start_point(s), end_point(s)}) {
                if (!std::isfinite(p.x()) || !std::isfinite(p.y()) ||
                    p.cwiseAbs().maxCoeff() > kMaxDrawingCoordinate) {
                    throw InputError(c.source, "coordinate out of range (beyond 1e9 units)");
                }
            }
        }
        if (drawing_.curves.size() >= kMaxCurves) {
            throw InputError(c.source, "more than " + std::to_string(kMaxCurves) +
                                           " curves: too large for a drawing");
        }
        total_segments_ += c.segments.size();
        if (total_segments_ > kMaxSegments)
            throw InputError(c.source, "too many segments in the drawing");
        drawing_.curves.push_back(std::move(c));
    }

    struct Vertex {
        Vec2 p;
        double bulge = 0.0;
    };
    struct OpenPolyline {
        std::string label, layer;
        bool closed = false;
        std::vector<Vertex> vertices;
    };
    struct OpenSpline {
        std::string label, layer;
        BSpline spline;
        unsigned fit_points = 0;
    };

    /// Starts an entity: closes the open one, names this one. False inside
    /// a block definition (skipped).
    bool begin(const char* type) {
        close_open();
        extrusion_negative_ = getExtrusion() && getExtrusion()->getDirection()[2] < 0.0;
        if (in_block_) {
            layer_ = getAttributes().getLayer();
            label_ = std::string(type) + " #" + std::to_string(++block_count_) + " of block " +
                     text::printable(block_name_);
            return block_ != nullptr;
        }
        ++count_;
        const DL_Attributes a = getAttributes();
        ++drawing_.layers[a.getLayer()];
        if (!options_.layers.empty() && a.getLayer() != options_.obstacle_layer &&
            std::find(options_.layers.begin(), options_.layers.end(), a.getLayer()) ==
                options_.layers.end()) {
            return false;
        }
        if (!options_.obstacle_layer.empty() && a.getLayer() == options_.obstacle_layer) {
            layer_seen_ = true;
        }
        layer_ = a.getLayer();
        label_ = std::string(type) + " #" + std::to_string(count_) + " (layer " +
                 text::printable(a.getLayer()) + ")";
        if (drawing_.curves.size() >= kMaxCurves) {
            throw InputError(label_, "more than " + std::to_string(kMaxCurves) +
                                         " entities: too large for a drawing");
        }
        return true;
    }

    bool on_obstacle_layer() {
        return !options_.obstacle_layer.empty() &&
               getAttributes().getLayer() == options_.obstacle_layer;
    }

    void unsupported(const std::string& what) {
        if (!begin(what.c_str())) return;
        if (block_) {
            block_->skips.push_back({false, what, label_});
        } else {
            note(unsupported_, what, label_);
        }
    }

    /// A piece that draws nothing (zero length, zero radius): skipped, or
    /// refused with --strict.
    void degenerate(const std::string& label, const std::string& why) {
        if (block_) {
            block_->skips.push_back({true, why, label});
        } else {
            skipped_piece(true, why, label);
        }
    }

    [[noreturn]] void fail(const std::string& problem) const { throw InputError(label_, problem); }

    /// A negative radius would draw the arc turned half a turn; a zero one
    /// draws nothing (false).
    bool positive_radius(double radius) {
        if (radius == 0.0) {
            degenerate(label_, "zero radius");
            return false;
        }
        if (!(radius > 0.0)) fail("radius " + text::compact(radius) + ": it must be positive");
        return true;
    }

    /// An angle difference as a sweep in (0, turn]: 0 is a whole turn.
    static double within_turn(double difference, double turn) {
        const double sweep = std::fmod(difference, turn);
        return sweep > 0.0 ? sweep : sweep + turn;
    }

    /// ARC, CIRCLE and LWPOLYLINE are written in their object coordinate
    /// system: with the extrusion pointing down (a mirrored entity), x is
    /// negated.
    Segment ocs(const Segment& s) const {
        if (!extrusion_negative_) return s;
        Affine mirror;
        mirror.m << -1.0, 0.0, 0.0, 1.0;
        return transformed(s, mirror);
    }

    void check_point(const Vec2& p) const {
        if (!std::isfinite(p.x()) || !std::isfinite(p.y()) ||
            p.cwiseAbs().maxCoeff() > kMaxDrawingCoordinate) {
            fail("coordinate out of range (beyond 1e9 units)");
        }
    }

    void add_curve(std::vector<Segment> segments, const std::string* label = nullptr,
                   const std::string* layer = nullptr) {
        const std::string& name = label ? *label : label_;
        if (!in_block_ && on_obstacle_layer() && !label) {
            throw InputError(name, "only circles can be obstacles (layer " +
                                       text::printable(options_.obstacle_layer) + ")");
        }
        Curve c;
        c.source = name;
        for (const Segment& s : segments) {
            for (const Vec2& p : {start_point(s), end_point(s)}) {
                if (!std::isfinite(p.x()) || !std::isfinite(p.y()) ||
                    p.cwiseAbs().maxCoeff() > kMaxDrawingCoordinate) {
                    throw InputError(name, "coordinate out of range (beyond 1e9 units)");
                }
            }
            if (approximate_length(s, 8) > 0.0) c.segments.push_back(s);
        }
        if (c.segments.empty()) {
            degenerate(name, "zero-length curve");
            return;
        }
        if (block_) {
            block_->curves.push_back({std::move(c), layer ? *layer : layer_});
            return;
        }
        add_model_curve(std::move(c));
    }

    void close_open() {
        close_polyline();
        close_spline();
    }

    void close_polyline() {
        if (polyline_) {
            OpenPolyline p = std::move(*polyline_);
            polyline_.reset();
            std::vector<Segment> segments;
            const std::size_t n = p.vertices.size();
            if (n < 2) throw InputError(p.label, "a polyline needs at least 2 vertices");
            const std::size_t count = p.closed ? n : n - 1;
            for (std::size_t i = 0; i < count; ++i) {
                const Vertex& a = p.vertices[i];
                const Vec2 b = p.vertices[(i + 1) % n].p;
                if (!std::isfinite(a.bulge) || std::abs(a.bulge) > 1e6) {
                    throw InputError(p.label, "bulge out of range at vertex " + std::to_string(i));
                }
                if (const auto arc = arc_from_bulge(a.p, b, a.bulge)) {
                    segments.push_back(ocs(*arc));
                } else {
                    segments.push_back(ocs(LineSegment{a.p, b}));
                }
            }
            add_curve(std::move(segments), &p.label, &p.layer);
        }
    }

    void close_spline() {
        if (spline_) {
            OpenSpline s = std::move(*spline_);
            spline_.reset();
            BSpline& b = s.spline;
            const std::size_t n = b.control.size();
            if (n == 0) {
                throw InputError(s.label, s.fit_points > 0
                                              ? "a spline given by fit points only is not "
                                                "supported (save it with control points)"
                                              : "a spline without control points");
            }
            if (n < static_cast<std::size_t>(b.degree) + 1) {
                throw InputError(s.label, "fewer control points than degree + 1");
            }
            if (b.knots.size() != n + b.degree + 1) {
                throw InputError(s.label, std::to_string(b.knots.size()) + " knots, expected " +
                                              std::to_string(n + b.degree + 1));
            }
            for (std::size_t i = 0; i < b.knots.size(); ++i) {
                if (!std::isfinite(b.knots[i]) || (i > 0 && b.knots[i] < b.knots[i - 1])) {
                    throw InputError(s.label, "knots must be finite and non-decreasing");
                }
            }
            if (!(b.knots[n] > b.knots[b.degree])) throw InputError(s.label, "empty knot range");
            for (double& w : b.weights) {
                if (w == 0.0) w = 1.0;  // dxflib's default for an absent weight
                if (!(w > 0.0) || !std::isfinite(w))
                    throw InputError(s.label, "weights must be positive");
            }
            add_curve({b}, &s.label, &s.layer);
        }
    }

    const ReadOptions& options_;
    std::vector<HatchBoundary> hatches_;  ///< every HATCH's, in file order
    std::size_t next_hatch_ = 0;
    Drawing drawing_;
    std::map<std::string, Skipped> unsupported_;
    std::map<std::string, Skipped> degenerate_;
    std::optional<OpenPolyline> polyline_;
    std::optional<OpenSpline> spline_;
    std::string label_;
    std::size_t count_ = 0;
    std::size_t total_segments_ = 0;
    int insunits_ = 0;
    bool in_block_ = false;
    std::map<std::string, Block> blocks_;
    Block* block_ = nullptr;  ///< the block being defined
    std::string block_name_;
    std::size_t block_count_ = 0;
    std::vector<InsertRef> model_inserts_;
    std::size_t instances_ = 0;
    std::string layer_;                          ///< the layer of the entity being read
    std::map<std::string, std::string> styles_;  ///< text style -> Hershey font
    std::string mtext_chunks_;
    bool layer_seen_ = false;
    bool extrusion_negative_ = false;
};

/// What a group's value holds, by its code (the DXF reference's "group code
/// value types"). Only numbers are checked: dxflib reads them with
/// operator>>, which takes "abc" for 0, "10xyz" for 10 and "nan" or "inf"
/// for 0, silently.
enum class ValueType { Text, Real, Integer };

ValueType value_type(long long code) {
    const auto in = [code](long long lo, long long hi) { return code >= lo && code <= hi; };
    if (in(10, 59) || in(110, 149) || in(210, 239) || in(460, 469) || in(1010, 1059))
        return ValueType::Real;
    if (in(60, 79) || in(90, 99) || in(160, 179) || in(270, 299) || in(370, 389) || in(400, 409) ||
        in(420, 429) || in(440, 459) || in(1060, 1071))
        return ValueType::Integer;
    return ValueType::Text;
}

std::string_view trimmed(std::string_view v) {
    const auto b = v.find_first_not_of(" \t");
    if (b == std::string_view::npos) return {};
    return v.substr(b, v.find_last_not_of(" \t") - b + 1);
}

/// A whole integer (spaces around it and a leading '+' allowed, as dxflib's
/// strtol takes them; "090" is 90), or nothing.
std::optional<long long> parse_integer(std::string_view v) {
    v = trimmed(v);
    if (!v.empty() && v.front() == '+') v.remove_prefix(1);
    if (v.empty() || v.front() == '+') return std::nullopt;
    long long n = 0;
    const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), n);
    if (ec != std::errc() || end != v.data() + v.size()) return std::nullopt;
    return n;
}

/// A whole decimal number, finite, or nothing; `why` says what is wrong.
std::optional<double> parse_real(std::string_view v, std::string& why) {
    v = trimmed(v);
    if (!v.empty() && v.front() == '+') v.remove_prefix(1);
    double x = 0.0;
    const auto [end, ec] = v.empty() || v.front() == '+'
                               ? std::from_chars_result{v.data(), std::errc::invalid_argument}
                               : std::from_chars(v.data(), v.data() + v.size(), x);
    if (ec == std::errc::result_out_of_range) {
        why = "beyond the range of a number";
        return std::nullopt;
    }
    if (ec != std::errc() || end != v.data() + v.size()) {
        why = "not a number";
        return std::nullopt;
    }
    if (!std::isfinite(x)) {
        why = "not a finite number";
        return std::nullopt;
    }
    return x;
}

/// The counts dxflib sizes its arrays from before it reads the items, and
/// the group code of the items each count counts (0: not checked against
/// them; a HATCH or LEADER is refused as a whole later).
struct DeclaredCount {
    int code;
    int item_code;
};
const std::map<std::string, std::vector<DeclaredCount>, std::less<>> kCounts = {
    {"LWPOLYLINE", {{90, 10}}},
    {"SPLINE", {{72, 40}, {73, 10}, {74, 11}}},
    {"HATCH", {{91, 0}, {93, 0}}},
    {"LEADER", {{76, 0}}}};

/// The lines of a text: split at '\n', a '\r' before it dropped (dxflib
/// strips both), numbered from 1.
class Lines {
public:
    explicit Lines(std::string_view text) : text_(text) {
        if (text_.substr(0, 3) == "\xEF\xBB\xBF") text_.remove_prefix(3);
    }
    std::optional<std::string_view> next() {
        if (at_ > text_.size() || (at_ == text_.size() && number_ > 0)) return std::nullopt;
        const std::size_t end = std::min(text_.find('\n', at_), text_.size());
        std::string_view line = text_.substr(at_, end - at_);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        at_ = end + 1;
        ++number_;
        return line;
    }
    std::size_t number() const { return number_; }

private:
    std::string_view text_;
    std::size_t at_ = 0;
    std::size_t number_ = 0;
};

/// The entity (or header variable, or section) whose groups are being read,
/// and what its counts declared.
struct Context {
    std::string name = "(document)";
    const std::vector<DeclaredCount>* counts = nullptr;
    std::map<int, long long> declared;  ///< count code -> the count
    std::map<int, long long> items;     ///< item code -> how many came
    std::size_t line = 0;               ///< where it starts

    std::string at(std::size_t line_number) const {
        return name + " (line " + std::to_string(line_number) + ")";
    }

    /// Declared counts must match the items that follow: dxflib overwrites
    /// its last vertex with any beyond the count, and fills a spline's
    /// missing control points with zeros.
    void check_counts() const {
        if (!counts) return;
        for (const DeclaredCount& c : *counts) {
            if (c.item_code == 0) continue;
            const auto d = declared.find(c.code);
            const auto i = items.find(c.item_code);
            const long long came = i == items.end() ? 0 : i->second;
            if (d != declared.end() && d->second != came) {
                throw InputError(at(line), "group code " + std::to_string(c.code) + " declares " +
                                               std::to_string(d->second) + " items, but " +
                                               std::to_string(came) + " follow (group code " +
                                               std::to_string(c.item_code) + ")");
            }
        }
    }
};

/// What dxflib makes of an entity in the ENTITIES section; any other type
/// it skips without a word, so the check below names it instead. VIEWPORT
/// draws nothing of the drawing (it is a view of paper space).
const std::set<std::string, std::less<>> kEntitiesRead = {
    "LINE",   "ARC",    "CIRCLE", "ELLIPSE", "LWPOLYLINE", "POLYLINE",  "VERTEX",
    "SEQEND", "SPLINE", "POINT",  "XLINE",   "RAY",        "INSERT",    "TRACE",
    "3DFACE", "SOLID",  "MTEXT",  "TEXT",    "ATTRIB",     "DIMENSION", "LEADER",
    "HATCH",  "IMAGE",  "ENDSEC", "EOF",     "SECTION",    "VIEWPORT"};

struct CheckedGroups {
    std::string text;  ///< the groups to hand dxflib
    /// Entity types of the ENTITIES section that dxflib does not read, and
    /// the lines where they begin.
    std::map<std::string, std::vector<std::size_t>> unread;
    /// The boundaries of every HATCH (in ENTITIES and in blocks), in file
    /// order.
    std::vector<HatchBoundary> hatches;
};

/// The dxflib version a comment names ("dxflib 2.0.4.8"), written in the
/// four parts dxflib's parser needs (DL_Dxf::getLibVersion, given three,
/// ends the third where memory it never set says), or nothing.
std::optional<std::string> dxflib_version(std::string_view comment) {
    comment = trimmed(comment);
    constexpr std::string_view kPrefix = "dxflib ";
    if (comment.substr(0, kPrefix.size()) != kPrefix) return std::nullopt;
    std::string_view rest = comment.substr(kPrefix.size());
    std::string version;
    int parts = 0;
    for (;;) {
        const std::size_t dot = rest.find('.');
        const std::string_view part = rest.substr(0, dot);
        unsigned n = 0;
        const auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), n);
        // Each part is a byte of an int: the first must leave its sign.
        if (part.empty() || ec != std::errc() || end != part.data() + part.size() ||
            n > (parts == 0 ? 127u : 255u) || ++parts > 4)
            return std::nullopt;
        version += (parts > 1 ? "." : "") + std::to_string(n);
        if (dot == std::string_view::npos) break;
        rest.remove_prefix(dot + 1);
    }
    for (; parts < 4; ++parts) version += ".0";
    return std::string(kPrefix) + version;
}

/// The file's groups as dxflib is to read them, after every check dxflib
/// does not make: group codes are integers ("090" is 90), numbers are whole
/// and finite numbers, declared counts fit in the file and match what
/// follows, no line is longer than dxflib's buffer (its read loop never ends
/// on one), and the file ends with EOF (one cut off inside an entity would
/// lose that entity). Comments (999) are dropped, whatever their length,
/// but for the dxflib version one (see below).
/// Entity names are written without the spaces around them, as dxflib
/// compares them. Every error names the entity and the line.
CheckedGroups checked_groups(std::string_view text) {
    const std::size_t total_lines = std::count(text.begin(), text.end(), '\n') + 1;
    const auto room = static_cast<long long>(total_lines / 2);
    constexpr std::size_t kLongestLine = DL_DXF_MAXLINE - 1;
    Lines lines(text);
    CheckedGroups checked;
    std::string& out = checked.text;
    out.reserve(text.size());
    // dxflib reads an MTEXT's angle (group 50) in radians if dxflib 2.0.2.0
    // or older wrote the file, as a comment says, and in degrees otherwise;
    // but it knows the writer's version only from that comment: without
    // one, it compares a value it never set (DL_Dxf's constructor leaves
    // libVersion out, DL_Dxf::addMText reads it), and the drawing changed
    // from run to run. Every file says a version first, the reader's own,
    // and the file's own comment, written whole, then takes its place.
    out += "999\ndxflib " DL_VERSION "\n";
    const auto keep_version = [&out](std::string_view comment) {
        if (const auto version = dxflib_version(comment)) out += "999\n" + *version + '\n';
    };
    Context context;
    std::string section;
    bool started = false, in_section = false, section_named = false;
    std::optional<HatchReader> hatch;
    while (const auto code_line = lines.next()) {
        const std::size_t code_number = lines.number();
        const auto value_line = lines.next();
        const std::size_t value_number = lines.number();
        const std::optional<long long> code = parse_integer(*code_line);
        if (!started) {
            if (code == 999 && value_line) {
                keep_version(*value_line);
                continue;
            }
            if (code != 0 || !value_line || trimmed(*value_line) != "SECTION")
                throw InputError("(document)", "not a DXF file: it does not begin with a SECTION");
            started = true;
        }
        if (!code || *code < -5 || *code > 1071) {
            throw InputError(context.at(code_number),
                             "'" + text::printable(*code_line) + "' is not a group code");
        }
        if (!value_line) break;  // a code without its value: cut off
        if (*code == 999) {
            keep_version(*value_line);
            continue;
        }
        const std::string_view value = *value_line;
        if (value.size() > kLongestLine) {
            throw InputError(context.at(value_number), "a line of " + std::to_string(value.size()) +
                                                           " characters, more than the " +
                                                           std::to_string(kLongestLine) +
                                                           " a DXF reader takes");
        }
        const auto what = [&] {
            return "group code " + std::to_string(*code) + " is '" + text::printable(value) + "'";
        };
        std::optional<long long> integer;
        std::optional<double> real;
        switch (value_type(*code)) {
            case ValueType::Real: {
                std::string why;
                real = parse_real(value, why);
                if (!real) throw InputError(context.at(value_number), what() + ", " + why);
                break;
            }
            case ValueType::Integer:
                integer = parse_integer(value);
                if (!integer)
                    throw InputError(context.at(value_number), what() + ", not an integer");
                if ((*code < 160 || *code > 169) &&
                    (*integer < std::numeric_limits<std::int32_t>::min() ||
                     *integer > std::numeric_limits<std::int32_t>::max()))
                    throw InputError(context.at(value_number),
                                     what() + ", beyond the range of a 32-bit integer");
                break;
            case ValueType::Text:
                break;
        }
        if (*code == 0) {
            context.check_counts();
            if (hatch) {
                checked.hatches.push_back(hatch->finish());
                hatch.reset();
            }
            const std::string_view name = trimmed(value);
            section_named = false;
            if (name == "SECTION") {
                if (in_section)
                    throw InputError(context.at(code_number),
                                     "a SECTION begins before the last one ended (ENDSEC)");
                in_section = section_named = true;
            } else if (name == "ENDSEC") {
                in_section = false;
                section.clear();
            } else if (section == "ENTITIES" && !kEntitiesRead.count(name)) {
                checked.unread[text::printable(name)].push_back(value_number);
            }
            context = Context{};
            context.name = text::printable(name);
            context.line = value_number;
            const auto counts = kCounts.find(name);
            if (counts != kCounts.end()) context.counts = &counts->second;
            if (name == "HATCH" && (section == "ENTITIES" || section == "BLOCKS")) hatch.emplace();
            out += "0\n";
            out += name;
            out += '\n';
            if (name == "EOF") {
                if (in_section)
                    throw InputError(context.at(code_number),
                                     "the file ends inside a section (no ENDSEC)");
                return checked;
            }
            continue;
        }
        if (*code == 2 && section_named) {
            section = trimmed(value);
            context.name = text::printable(section) + " section";
        }
        section_named = false;
        if (hatch) {
            if (real) {
                hatch->number(static_cast<int>(*code), *real, value_number);
            } else if (integer) {
                hatch->number(static_cast<int>(*code), static_cast<double>(*integer), value_number);
            } else {
                hatch->text(static_cast<int>(*code), std::string(value));
            }
        }
        if (context.counts) {
            for (const DeclaredCount& c : *context.counts) {
                if (*code == c.item_code) ++context.items[c.item_code];
                if (*code != c.code) continue;
                if (*integer < 0) {
                    throw InputError(context.at(value_number),
                                     "group code " + std::to_string(c.code) + " gives a count of " +
                                         std::to_string(*integer) + ": a count cannot be negative");
                }
                if (*integer > room) {
                    throw InputError(context.at(value_number),
                                     "group code " + std::to_string(c.code) + " declares " +
                                         std::to_string(*integer) +
                                         " items, more than the file's " +
                                         std::to_string(total_lines) + " lines can hold");
                }
                context.declared[c.code] = *integer;
            }
        }
        out += std::to_string(*code);
        out += '\n';
        out += value;
        out += '\n';
    }
    if (!started)
        throw InputError("(document)", "not a DXF file: it does not begin with a SECTION");
    throw InputError(context.at(lines.number()), "the file ends here, without EOF: it is cut off");
}

}  // namespace

Drawing read_dxf(std::string_view text, const ReadOptions& options) {
    if (text.size() > kMaxDrawingBytes) {
        throw InputError("(document)", "the file is larger than " +
                                           std::to_string(kMaxDrawingBytes >> 20) + " MB");
    }
    CheckedGroups checked = checked_groups(text);
    std::stringstream stream{std::move(checked.text)};
    Collector collector(options, std::move(checked.hatches));
    collector.add_unread(checked.unread);
    DL_Dxf dxf;
    try {
        if (!dxf.in(stream, &collector)) throw InputError("(document)", "not a readable DXF file");
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        throw InputError("(document)", "malformed DXF: " + text::printable(e.what(), 200));
    }
    return collector.finish();
}

}  // namespace modsynth::drawing
