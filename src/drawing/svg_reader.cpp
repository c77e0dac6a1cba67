#include <modsynth/drawing/svg_reader.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>
#include <string>
#include <vector>

// SVG++ nests Boost.Parameter lists deeper than Boost's default arity.
#define BOOST_PARAMETER_MAX_ARITY 11
#include <tinyxml2.h>
#include <boost/array.hpp>
#include <boost/exception/get_error_info.hpp>
#include <svgpp/svgpp.hpp>

#include <modsynth/task/input_error.h>

#include "elliptic_arc.h"
#include "svg_xml_policy.h"

namespace modsynth::drawing {

namespace {

using task::InputError;
using XmlElement = const tinyxml2::XMLElement*;

/// CSS pixels per inch: SVG's user unit is the CSS pixel.
constexpr double kPxPerInch = 96.0;
constexpr double kMmPerPx = 25.4 / kPxPerInch;

/// "path#p3 (line 12)": how messages name an element.
std::string element_label(XmlElement e) {
    std::string label = svg_xml::local_name(e->Name());
    if (const char* id = e->Attribute("id")) label += std::string("#") + id;
    return label + " (line " + std::to_string(e->GetLineNum()) + ")";
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

/// Walks what SVG++ will walk, before it does: every element must be one
/// that can be drawn (or one that draws nothing), so that nothing in the
/// drawing is dropped without a word. Returns whether the obstacle layer
/// was seen.
void check_elements(XmlElement e, const ReadOptions& options, std::vector<std::string>& unsupported,
                    bool& layer_seen, std::size_t& count) {
    for (XmlElement c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
        if (!svg_xml::is_svg_element(c)) continue;
        if (++count > kMaxCurves) {
            throw InputError("(document)", "more than " + std::to_string(kMaxCurves) +
                                               " elements: too large for a drawing");
        }
        const std::string_view name = svg_xml::local_name(c->Name());
        if (kNotDrawn.count(name)) continue;
        if (kShapes.count(name)) continue;
        if (kContainers.count(name)) {
            if (!options.obstacle_layer.empty() && name == "g") {
                const char* id = c->Attribute("id");
                const char* label = c->Attribute("inkscape:label");
                if ((id && options.obstacle_layer == id) ||
                    (label && options.obstacle_layer == label)) {
                    layer_seen = true;
                }
            }
            check_elements(c, options, unsupported, layer_seen, count);
            continue;
        }
        std::string why;
        if (name == "text") why = " (convert text to paths first)";
        if (name == "image") why = " (a bitmap has no strokes)";
        if (name == "use") why = " (unlink clones first)";
        unsupported.push_back(element_label(c) + why);
    }
}

/// Shared by every element's context: what has been read so far.
struct SvgState {
    const ReadOptions* options = nullptr;
    std::vector<Curve> curves;  ///< in the outer viewport's pixels, y down
    std::vector<geometry::Disc> obstacles;
    std::size_t segments = 0;
    double page_width = 0.0, page_height = 0.0;  ///< the outer viewport, px
    bool have_page = false;
};

class BaseContext {
public:
    explicit BaseContext(SvgState& state) : state_(&state) {
        length_factory_.set_absolute_units_coefficient(kPxPerInch, svgpp::tag::length_units::in());
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
    length_factory_type length_factory_;
    bool hidden_ = false;
};

class GroupContext : public BaseContext {
public:
    template <class Parent>
    GroupContext(Parent& parent, XmlElement) : BaseContext(parent) {}
};

class ShapeContext : public BaseContext {
public:
    template <class Parent>
    ShapeContext(Parent& parent, XmlElement element)
        : BaseContext(parent), element_(element), label_(element_label(element)) {
        obstacle_ = !state_->options->obstacle_layer.empty() &&
                    in_layer(element, state_->options->obstacle_layer);
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
        } else {
            add(LineSegment{current_, end});  // zero radius: a line (SVG 1.1 F.6.2)
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
        if (!(rx > 0.0) || !(ry > 0.0)) throw InputError(label_, "zero-length curve (radius 0)");
        EllipticArc e{Vec2(cx, cy), Vec2(rx, 0.0), Vec2(0.0, ry), 0.0, geometry::kTau};
        if (obstacle_) {
            const EllipticArc placed = std::get<EllipticArc>(transformed(e, ctm_));
            if (!is_circular(placed)) {
                throw InputError(label_, "an obstacle must be a circle, not an ellipse");
            }
            state_->obstacles.push_back({placed.center, placed.u.norm()});
            ++commands_;
            return;
        }
        ++commands_;
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
        if (c.segments.empty()) throw InputError(label_, "zero-length curve");
        state_->curves.push_back(std::move(c));
    }

    XmlElement element_;
    std::string label_;
    bool obstacle_ = false;
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

std::string quoted(const std::string& value) {
    constexpr std::size_t kShown = 60;
    std::string shown = value.size() > kShown ? value.substr(0, kShown) + "..." : value;
    for (char& c : shown) {
        if (static_cast<unsigned char>(c) < 0x20) c = ' ';
    }
    return "'" + shown + "'";
}

}  // namespace

Drawing read_svg(std::string_view text, const ReadOptions& options) {
    if (text.size() > kMaxDrawingBytes) {
        throw InputError("(document)", "the file is larger than " +
                                           std::to_string(kMaxDrawingBytes >> 20) + " MB");
    }
    tinyxml2::XMLDocument doc;
    if (doc.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS) {
        throw InputError("(document)", std::string("not an SVG file: XML error at line ") +
                                           std::to_string(doc.ErrorLineNum()) + ": " +
                                           doc.ErrorName());
    }
    XmlElement root = doc.RootElement();
    if (!root || std::strcmp(svg_xml::local_name(root->Name()), "svg") != 0) {
        throw InputError("(document)", std::string("not an SVG file: the root element is <") +
                                           (root ? root->Name() : "") + ">, not <svg>");
    }
    std::vector<std::string> unsupported;
    bool layer_seen = false;
    std::size_t count = 0;
    check_elements(root, options, unsupported, layer_seen, count);
    if (!unsupported.empty()) {
        std::string list;
        for (const std::string& u : unsupported) list += (list.empty() ? "" : ", ") + u;
        throw InputError(element_label(root), "elements that cannot be drawn: " + list);
    }
    if (!options.obstacle_layer.empty() && !layer_seen) {
        throw InputError("(document)", "no layer or group with id or label '" +
                                           options.obstacle_layer + "' (--obstacles-from)");
    }

    SvgState state;
    state.options = &options;
    BaseContext context(state);
    // An outer svg without width and height is as large as its viewBox, in
    // pixels (what browsers show).
    double vb[4] = {0, 0, 0, 0};
    if (const char* v = root->Attribute("viewBox")) {
        std::sscanf(v, "%lf%*[ ,]%lf%*[ ,]%lf%*[ ,]%lf", &vb[0], &vb[1], &vb[2], &vb[3]);
    }
    const double ref_w = vb[2] > 0.0 ? vb[2] : 1000.0, ref_h = vb[3] > 0.0 ? vb[3] : 1000.0;
    context.set_reference_size(ref_w, ref_h);
    try {
        DocumentTraversal::load_document(root, context);
    } catch (const svgpp::exception_base& e) {
        typedef boost::error_info<svgpp::tag::error_info::xml_element, XmlElement> ElementInfo;
        const XmlElement* where = boost::get_error_info<ElementInfo>(e);
        const std::string part = where ? element_label(*where) : "(document)";
        if (const auto* bad = dynamic_cast<const svgpp::invalid_value_error<char>*>(&e)) {
            if (bad->name() == "d")
                throw InputError(part, "malformed path data " + quoted(bad->value()));
            throw InputError(part,
                             "malformed attribute " + bad->name() + "=" + quoted(bad->value()));
        }
        throw InputError(part, e.what());
    }
    if (state.curves.empty()) throw InputError("(document)", "empty drawing: nothing to draw");

    // Outer viewport pixels, y down -> millimetres, y up from the page's
    // bottom-left corner.
    Affine to_mm;
    to_mm.m << kMmPerPx, 0.0, 0.0, -kMmPerPx;
    to_mm.offset = Vec2(0.0, kMmPerPx * state.page_height);
    Drawing out;
    out.metres_per_unit = 1e-3;
    out.page_size = Vec2(state.page_width, state.page_height);
    out.page_to_units = to_mm;
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
