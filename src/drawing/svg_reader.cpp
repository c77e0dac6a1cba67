#include <modsynth/drawing/svg_reader.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
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

#include <modsynth/task/input_error.h>
#include <modsynth/text/printable.h>

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
    std::string label = text::printable(svg_xml::local_name(e->Name()), 40);
    if (const char* id = e->Attribute("id")) label += "#" + text::printable(id, 40);
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
std::string property(XmlElement e, std::string_view name) {
    std::string value;
    if (const char* a = e->Attribute(std::string(name).c_str())) value = lower(trimmed(a));
    const char* style = e->Attribute("style");
    for (std::string_view rest = style ? style : ""; !rest.empty();) {
        const auto semi = rest.find(';');
        const std::string_view declaration = rest.substr(0, semi);
        rest = semi == std::string_view::npos ? std::string_view{} : rest.substr(semi + 1);
        const auto colon = declaration.find(':');
        if (colon == std::string_view::npos || lower(trimmed(declaration.substr(0, colon))) != name)
            continue;
        value = lower(trimmed(declaration.substr(colon + 1)));
        const auto important = value.find("!important");
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

    Rendering of(XmlElement e) const {
        Rendering r = *this;
        if (property(e, "display") == "none") r.displayed = false;
        const std::string v = property(e, "visibility");
        if (v == "hidden" || v == "collapse") r.visible = false;
        if (v == "visible") r.visible = true;
        return r;
    }
    bool drawn() const { return displayed && visible; }
};

/// Walks what SVG++ will walk, before it does: every element must be one
/// that can be drawn (or one that draws nothing), so that nothing in the
/// drawing is dropped without a word. Elements that are not rendered
/// (display none, visibility hidden) are not drawn: the shapes among them
/// go to `not_drawn`, and an element that cannot be drawn is no error there.
/// Sets `layer_seen` when the obstacle layer was seen.
void check_elements(XmlElement e, const Rendering& rendering, const ReadOptions& options,
                    std::vector<std::string>& unsupported, std::set<XmlElement>& not_drawn,
                    bool& layer_seen, std::size_t& count) {
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
            check_elements(c, own, options, unsupported, not_drawn, layer_seen, count);
            continue;
        }
        if (!own.drawn()) continue;
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
    /// Shapes that are not rendered (display none, visibility hidden).
    std::set<XmlElement> not_drawn;
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

}  // namespace

Drawing read_svg(std::string_view text, const ReadOptions& options) {
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
    std::vector<std::string> unsupported;
    SvgState state;
    state.options = &options;
    bool layer_seen = false;
    std::size_t count = 0;
    check_elements(root, Rendering{}.of(root), options, unsupported, state.not_drawn, layer_seen,
                   count);
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
    try {
        DocumentTraversal::load_document(root, context);
    } catch (const svgpp::exception_base& e) {
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
