#include <modsynth/drawing/dxf_reader.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <dxflib/dl_creationadapter.h>
#include <dxflib/dl_dxf.h>

#include <modsynth/task/input_error.h>

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
            throw InputError("(document)",
                             "no layer '" + options_.obstacle_layer + "' (--obstacles-from)");
        }
        if (drawing_.curves.empty())
            throw InputError("(document)", "empty drawing: nothing to draw");
        drawing_.metres_per_unit = metres_per_insunit(insunits_);
        return std::move(drawing_);
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
        double a1 = d.angle1, a2 = d.angle2;
        if (a2 <= a1) a2 += 360.0;
        add_curve({ocs(EllipticArc{Vec2(d.cx, d.cy), Vec2(d.radius, 0.0), Vec2(0.0, d.radius),
                                   a1 * kDegree, a2 * kDegree})});
    }
    void addCircle(const DL_CircleData& d) override {
        if (!begin("CIRCLE")) return;
        const EllipticArc circle{Vec2(d.cx, d.cy), Vec2(d.radius, 0.0), Vec2(0.0, d.radius), 0.0,
                                 geometry::kTau};
        if (on_obstacle_layer()) {
            if (!(d.radius > 0.0) || !std::isfinite(d.radius)) fail("radius must be positive");
            const EllipticArc c = std::get<EllipticArc>(ocs(circle));
            check_point(c.center);
            drawing_.obstacles.push_back({c.center, d.radius});
            return;
        }
        add_curve({ocs(circle)});
    }
    void addEllipse(const DL_EllipseData& d) override {
        if (!begin("ELLIPSE")) return;
        const Vec2 major(d.mx, d.my);
        double a1 = d.angle1, a2 = d.angle2;
        if (a2 <= a1) a2 += geometry::kTau;
        add_curve({EllipticArc{Vec2(d.cx, d.cy), major, d.ratio * geometry::perp(major), a1, a2}});
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
        label_ =
            std::string(type) + " #" + std::to_string(count_) + " (layer " + a.getLayer() + ")";
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
            throw InputError(
                name, "only circles can be obstacles (layer " + options_.obstacle_layer + ")");
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

/// A DXF file opens with group code 0 and SECTION (after optional 999
/// comments): anything else is not one.
bool looks_like_dxf(std::string_view text) {
    std::istringstream in{std::string(text.substr(0, 4096))};
    std::string code, value;
    auto trim = [](std::string s) {
        s.erase(0, s.find_first_not_of(" \t\r\n\xEF\xBB\xBF"));
        s.erase(s.find_last_not_of(" \t\r\n") + 1);
        return s;
    };
    while (std::getline(in, code) && std::getline(in, value)) {
        code = trim(code);
        if (code == "999") continue;
        return code == "0" && trim(value) == "SECTION";
    }
    return false;
}

/// dxflib sizes its arrays from counts the file declares (a LWPOLYLINE's
/// vertex count, a SPLINE's knot, control and fit point counts, a HATCH's
/// loops and edges, a LEADER's vertices) before reading the items. A few
/// bytes declaring 200 million vertices would take gigabytes, so every such
/// count must be one the file could hold: at most one item per two lines
/// (each item takes at least one group code and value).
void check_declared_counts(std::string_view text) {
    static const std::map<std::string, std::vector<std::string>> kCounts = {
        {"LWPOLYLINE", {"90"}},
        {"SPLINE", {"72", "73", "74"}},
        {"HATCH", {"91", "93"}},
        {"LEADER", {"76"}}};
    const auto trim = [](std::string_view v) {
        const auto b = v.find_first_not_of(" \t\r");
        if (b == std::string_view::npos) return std::string_view{};
        return v.substr(b, v.find_last_not_of(" \t\r") - b + 1);
    };
    std::vector<std::string_view> lines;
    for (std::size_t at = 0; at <= text.size();) {
        const std::size_t end = std::min(text.find('\n', at), text.size());
        lines.push_back(trim(text.substr(at, end - at)));
        at = end + 1;
    }
    const long long room = static_cast<long long>(lines.size() / 2);
    const std::vector<std::string>* codes = nullptr;
    std::string entity;
    for (std::size_t i = 0; i + 1 < lines.size(); i += 2) {
        const std::string code(lines[i]);
        if (code == "0") {
            entity = std::string(lines[i + 1]);
            const auto it = kCounts.find(entity);
            codes = it == kCounts.end() ? nullptr : &it->second;
            continue;
        }
        if (!codes || std::find(codes->begin(), codes->end(), code) == codes->end()) continue;
        long long n = 0;
        std::istringstream in{std::string(lines[i + 1])};
        if (!(in >> n) || n < 0 || n > room) {
            throw InputError(entity + " (line " + std::to_string(i + 2) + ")",
                             "group code " + code + " declares " + std::string(lines[i + 1]) +
                                 " items, more than the file's " + std::to_string(lines.size()) +
                                 " lines can hold");
        }
    }
}

}  // namespace

Drawing read_dxf(std::string_view text, const ReadOptions& options) {
    if (text.size() > kMaxDrawingBytes) {
        throw InputError("(document)", "the file is larger than " +
                                           std::to_string(kMaxDrawingBytes >> 20) + " MB");
    }
    if (!looks_like_dxf(text)) {
        throw InputError("(document)", "not a DXF file: it does not begin with a SECTION");
    }
    check_declared_counts(text);
    Collector collector(options);
    DL_Dxf dxf;
    std::stringstream stream{std::string(text)};
    try {
        if (!dxf.in(stream, &collector)) throw InputError("(document)", "not a readable DXF file");
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        throw InputError("(document)", std::string("malformed DXF: ") + e.what());
    }
    return collector.finish();
}

}  // namespace modsynth::drawing
