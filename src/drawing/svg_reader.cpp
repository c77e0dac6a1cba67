#include <modsynth/drawing/svg_reader.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <map>
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

/// "path#p3 (line 12)": how messages name an element.
std::string element_label(XmlElement e) {
    std::string label = text::printable(svg_xml::local_name(e->Name()), 40);
    if (const char* id = e->Attribute("id")) label += "#" + text::printable(id, 40);
    return label + " (line " + svg_use::line_of(e) + ")";
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
            if (own.drawn() && own.outline_only()) outlines.insert(c);
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
        if (name == "text") why = " (convert text to paths first)";
        if (name == "image") why = " (a bitmap has no strokes)";
        unsupported.push_back(element_label(c) + why);
    }
}

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
        clips_.push_back(state_->clips.size());
        state_->clips.push_back(clip_region(found->second, ctm_, element_label(e), *state_));
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
                    for (Curve& q : svg_clip::clipped(p, state.clips[clip]))
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
