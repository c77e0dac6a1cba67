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

#include <modsynth/task/input_error.h>
#include <modsynth/text/printable.h>

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
    explicit Collector(const ReadOptions& options) : options_(options) {}

    Drawing finish() {
        close_open();
        if (!unsupported_.empty()) {
            std::string list;
            for (const auto& [name, count] : unsupported_) {
                list += (list.empty() ? "" : ", ") + name +
                        (count > 1 ? " (" + std::to_string(count) + "x)" : "");
            }
            throw InputError("(document)", "entities that cannot be drawn: " + list);
        }
        if (!options_.obstacle_layer.empty() && !layer_seen_) {
            throw InputError("(document)", "no layer '" + text::printable(options_.obstacle_layer) +
                                               "' (--obstacles-from)");
        }
        if (drawing_.curves.empty())
            throw InputError("(document)", "empty drawing: nothing to draw");
        drawing_.metres_per_unit = metres_per_insunit(insunits_);
        return std::move(drawing_);
    }

    /// Entities dxflib does not read at all, counted before it ran.
    void add_unread(const std::map<std::string, int>& unread) {
        for (const auto& [name, count] : unread) unsupported_[name] += count;
    }

    void setVariableInt(const std::string& key, int value, int) override {
        if (key == "$INSUNITS") insunits_ = value;
    }

    // Entities inside a block are drawn only where an INSERT places them,
    // which is not supported: they are not part of the drawing itself.
    void addBlock(const DL_BlockData&) override {
        close_open();
        in_block_ = true;
    }
    void endBlock() override { in_block_ = false; }
    void endSection() override { close_open(); }

    void addLine(const DL_LineData& d) override {
        if (!begin("LINE")) return;
        add_curve({LineSegment{Vec2(d.x1, d.y1), Vec2(d.x2, d.y2)}});
    }
    void addArc(const DL_ArcData& d) override {
        if (!begin("ARC")) return;
        require_positive_radius(d.radius);
        // Counter-clockwise from angle1 to angle2, less than a turn apart
        // (equal angles: a full turn), whatever multiples of 360 they hold.
        const double a1 = std::fmod(d.angle1, 360.0);
        const double sweep = within_turn(d.angle2 - d.angle1, 360.0);
        add_curve({ocs(EllipticArc{Vec2(d.cx, d.cy), Vec2(d.radius, 0.0), Vec2(0.0, d.radius),
                                   a1 * kDegree, (a1 + sweep) * kDegree})});
    }
    void addCircle(const DL_CircleData& d) override {
        if (!begin("CIRCLE")) return;
        require_positive_radius(d.radius);
        const EllipticArc circle{Vec2(d.cx, d.cy), Vec2(d.radius, 0.0), Vec2(0.0, d.radius), 0.0,
                                 geometry::kTau};
        if (on_obstacle_layer()) {
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
        if (!begin("LWPOLYLINE")) return;
        polyline_ = OpenPolyline{label_, (d.flags & 1) != 0, {}};
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
        spline_ = OpenSpline{label_, BSpline{static_cast<int>(d.degree), {}, {}, {}}, d.nFit};
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
    void addPoint(const DL_PointData&) override { unsupported("POINT"); }
    void addXLine(const DL_XLineData&) override { unsupported("XLINE"); }
    void addRay(const DL_RayData&) override { unsupported("RAY"); }
    void addInsert(const DL_InsertData&) override { unsupported("INSERT (block reference)"); }
    void addTrace(const DL_TraceData&) override { unsupported("TRACE"); }
    void add3dFace(const DL_3dFaceData&) override { unsupported("3DFACE"); }
    void addSolid(const DL_SolidData&) override { unsupported("SOLID"); }
    void addMText(const DL_MTextData&) override { unsupported("MTEXT (explode text first)"); }
    void addText(const DL_TextData&) override { unsupported("TEXT (explode text first)"); }
    void addAttribute(const DL_AttributeData&) override {
        unsupported("ATTRIB (explode text first)");
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
    void addHatch(const DL_HatchData&) override { unsupported("HATCH"); }
    void addImage(const DL_ImageData&) override { unsupported("IMAGE"); }

private:
    struct Vertex {
        Vec2 p;
        double bulge = 0.0;
    };
    struct OpenPolyline {
        std::string label;
        bool closed = false;
        std::vector<Vertex> vertices;
    };
    struct OpenSpline {
        std::string label;
        BSpline spline;
        unsigned fit_points = 0;
    };

    /// Starts an entity: closes the open one, names this one. False inside
    /// a block definition (skipped).
    bool begin(const char* type) {
        close_open();
        if (in_block_) return false;
        ++count_;
        const DL_Attributes a = getAttributes();
        if (!options_.obstacle_layer.empty() && a.getLayer() == options_.obstacle_layer) {
            layer_seen_ = true;
        }
        label_ = std::string(type) + " #" + std::to_string(count_) + " (layer " +
                 text::printable(a.getLayer()) + ")";
        if (drawing_.curves.size() >= kMaxCurves) {
            throw InputError(label_, "more than " + std::to_string(kMaxCurves) +
                                         " entities: too large for a drawing");
        }
        extrusion_negative_ = getExtrusion() && getExtrusion()->getDirection()[2] < 0.0;
        return true;
    }

    bool on_obstacle_layer() {
        return !options_.obstacle_layer.empty() &&
               getAttributes().getLayer() == options_.obstacle_layer;
    }

    void unsupported(const std::string& what) {
        close_open();
        if (!in_block_) ++unsupported_[what];
    }

    [[noreturn]] void fail(const std::string& problem) const { throw InputError(label_, problem); }

    /// A negative radius would draw the arc turned half a turn.
    void require_positive_radius(double radius) const {
        if (!(radius > 0.0)) fail("radius " + text::compact(radius) + ": it must be positive");
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

    void add_curve(std::vector<Segment> segments, const std::string* label = nullptr) {
        const std::string& name = label ? *label : label_;
        if (on_obstacle_layer() && !label) {
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
        if (c.segments.empty()) throw InputError(name, "zero-length curve");
        total_segments_ += c.segments.size();
        if (total_segments_ > kMaxSegments)
            throw InputError(name, "too many segments in the drawing");
        drawing_.curves.push_back(std::move(c));
    }

    void close_open() {
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
            add_curve(std::move(segments), &p.label);
        }
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
            add_curve({b}, &s.label);
        }
    }

    const ReadOptions& options_;
    Drawing drawing_;
    std::map<std::string, int> unsupported_;
    std::optional<OpenPolyline> polyline_;
    std::optional<OpenSpline> spline_;
    std::string label_;
    std::size_t count_ = 0;
    std::size_t total_segments_ = 0;
    int insunits_ = 0;
    bool in_block_ = false;
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
    /// how many of each.
    std::map<std::string, int> unread;
};

/// The file's groups as dxflib is to read them, after every check dxflib
/// does not make: group codes are integers ("090" is 90), numbers are whole
/// and finite numbers, declared counts fit in the file and match what
/// follows, no line is longer than dxflib's buffer (its read loop never ends
/// on one), and the file ends with EOF (one cut off inside an entity would
/// lose that entity). Comments (999) are dropped, whatever their length.
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
    Context context;
    std::string section;
    bool started = false, in_section = false, section_named = false;
    while (const auto code_line = lines.next()) {
        const std::size_t code_number = lines.number();
        const auto value_line = lines.next();
        const std::size_t value_number = lines.number();
        const std::optional<long long> code = parse_integer(*code_line);
        if (!started) {
            if (code == 999 && value_line) continue;
            if (code != 0 || !value_line || trimmed(*value_line) != "SECTION")
                throw InputError("(document)", "not a DXF file: it does not begin with a SECTION");
            started = true;
        }
        if (!code || *code < -5 || *code > 1071) {
            throw InputError(context.at(code_number),
                             "'" + text::printable(*code_line) + "' is not a group code");
        }
        if (!value_line) break;  // a code without its value: cut off
        if (*code == 999) continue;
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
        switch (value_type(*code)) {
            case ValueType::Real: {
                std::string why;
                if (!parse_real(value, why))
                    throw InputError(context.at(value_number), what() + ", " + why);
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
                ++checked.unread[text::printable(name)];
            }
            context = Context{};
            context.name = text::printable(name);
            context.line = value_number;
            const auto counts = kCounts.find(name);
            if (counts != kCounts.end()) context.counts = &counts->second;
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
    Collector collector(options);
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
