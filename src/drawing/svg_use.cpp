#include "svg_use.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <modsynth/drawing/drawing.h>
#include <modsynth/task/input_error.h>
#include <modsynth/text/printable.h>

#include "svg_xml_policy.h"

namespace modsynth::drawing::svg_use {

namespace {

using task::InputError;
using tinyxml2::XMLElement;

// A copy has no line of its own in the file: these foreign attributes (which
// the walk skips as it skips inkscape:) keep the original's and the use's.
constexpr const char* kLine = "modsynth:line";
constexpr const char* kUseLine = "modsynth:use-line";
/// On the group a use became: the id it drew.
constexpr const char* kUseOf = "modsynth:use-of";

/// Uses within what a use draws, within what ...: beyond this the file is
/// refused rather than nested deeper than the walks' stacks should go.
constexpr std::size_t kMaxDepth = 64;
/// Elements all the copies may add, as many as a file may hold.
constexpr std::size_t kMaxCopied = 8 * kMaxCurves;

std::string label(const XMLElement* e) {
    std::string out = text::printable(svg_xml::local_name(e->Name()), 40);
    if (const char* id = e->Attribute("id")) out += "#" + text::printable(id, 40);
    return out + " (line " + line_of(e) + ")";
}

const char* href(const XMLElement* e) {
    const char* h = e->Attribute("href");
    return h ? h : e->Attribute("xlink:href");
}

void index_ids(XMLElement* e, std::map<std::string, XMLElement*, std::less<>>& ids) {
    if (const char* id = e->Attribute("id")) ids.emplace(id, e);
    for (XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) index_ids(c, ids);
}

std::size_t element_count(const XMLElement* e) {
    std::size_t n = 1;
    for (const XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement())
        n += element_count(c);
    return n;
}

/// Gives every element of `copy` the line of its original in `source`.
/// And, when `use_line` is given, the line of the use that copies it.
void keep_lines(const XMLElement* source, XMLElement* copy, int use_line = 0) {
    copy->SetAttribute(kLine, source->IntAttribute(kLine, source->GetLineNum()));
    if (const char* u = source->Attribute(kUseLine)) {
        copy->SetAttribute(kUseLine, u);
    } else if (use_line > 0) {
        copy->SetAttribute(kUseLine, use_line);
    }
    const XMLElement* s = source->FirstChildElement();
    XMLElement* c = copy->FirstChildElement();
    for (; s && c; s = s->NextSiblingElement(), c = c->NextSiblingElement())
        keep_lines(s, c, use_line);
}

/// A use's x or y in user units: a number, in px or an absolute unit.
double user_length(const XMLElement* use, const char* name) {
    const char* value = use->Attribute(name);
    if (!value) return 0.0;
    char* end = nullptr;
    const double v = std::strtod(value, &end);
    std::string_view unit(end);
    while (!unit.empty() && std::strchr(" \t\r\n", unit.back())) unit.remove_suffix(1);
    static const std::map<std::string_view, double> kUnits = {
        {"", 1.0},           {"px", 1.0},         {"in", 96.0}, {"cm", 96.0 / 2.54},
        {"mm", 96.0 / 25.4}, {"pt", 96.0 / 72.0}, {"pc", 16.0}};
    const auto unit_factor = kUnits.find(unit);
    if (end == value || unit_factor == kUnits.end() || !std::isfinite(v) ||
        std::abs(v) > kMaxDrawingCoordinate) {
        throw InputError(label(use), std::string(name) + "='" + text::printable(value, 40) +
                                         "' is not a length in user units");
    }
    return v * unit_factor->second;
}

class Expander {
public:
    explicit Expander(tinyxml2::XMLDocument& doc) : doc_(doc) {
        if (doc.RootElement()) index_ids(doc.RootElement(), ids_);
    }

    /// `unrendered`: inside defs (or another element that draws nothing by
    /// itself), where a use that cannot be resolved is left as it is: it is
    /// drawn only through a use of what holds it, which resolves it then.
    void walk(XMLElement* e, std::vector<std::string>& chain, bool unrendered = false) {
        static const std::set<std::string, std::less<>> kUnrendered = {"defs", "symbol", "clipPath",
                                                                       "mask", "marker", "pattern"};
        for (XMLElement* c = e->FirstChildElement(); c;) {
            XMLElement* next = c->NextSiblingElement();
            const bool svg = svg_xml::is_svg_element(c);
            if (svg && std::strcmp(svg_xml::local_name(c->Name()), "use") == 0) {
                if (!unrendered) {
                    replace(c, chain, false);
                } else {
                    try {
                        replace(c, chain, true);
                    } catch (const InputError&) {
                    }
                }
            } else {
                walk(c, chain,
                     unrendered || (svg && kUnrendered.count(svg_xml::local_name(c->Name()))));
            }
            c = next;
        }
    }

private:
    void replace(XMLElement* use, std::vector<std::string>& chain, bool unrendered) {
        const char* h = href(use);
        if (!h || !*h) throw InputError(label(use), "refers to nothing (no href)");
        if (h[0] != '#') {
            throw InputError(label(use), "refers to '" + text::printable(h, 60) +
                                             "', outside the file: only #id is read");
        }
        const std::string id = h + 1;
        const auto found = ids_.find(id);
        if (found == ids_.end()) {
            throw InputError(label(use), "refers to #" + text::printable(id, 40) +
                                             ", which the file does not hold");
        }
        if (std::find(chain.begin(), chain.end(), id) != chain.end()) {
            // The uses that led here, outermost first: the cycle as the
            // file writes it.
            std::vector<std::string> drawn;
            for (const tinyxml2::XMLNode* n = use->Parent(); n && n->ToElement(); n = n->Parent()) {
                if (const char* of = n->ToElement()->Attribute(kUseOf))
                    drawn.insert(drawn.begin(), of);
            }
            std::string path;
            // The shortest cycle: from the innermost use of this id on.
            const auto last = std::find(drawn.rbegin(), drawn.rend(), id);
            for (auto i = last == drawn.rend() ? drawn.end() : std::prev(last.base());
                 i != drawn.end(); ++i)
                path += text::printable(*i, 40) + " -> ";
            throw InputError(label(use), "refers to #" + text::printable(id, 40) +
                                             ", which draws itself (" + path +
                                             text::printable(id, 40) + ")");
        }
        if (chain.size() >= kMaxDepth) {
            throw InputError(label(use),
                             "uses nested more than " + std::to_string(kMaxDepth) + " deep");
        }
        const XMLElement* target = found->second;
        copied_ += element_count(target) + 1;
        if (copied_ > kMaxCopied) {
            throw InputError("(document)", "its use elements draw more than " +
                                               std::to_string(kMaxCopied) +
                                               " copied elements: too large for a drawing");
        }
        const double x = user_length(use, "x"), y = user_length(use, "y");

        // SVG 1.1, 5.6: a g with the use's attributes, its transform then a
        // translation by x and y, holding a copy of the referenced element;
        // a symbol becomes an svg of the use's width and height.
        XMLElement* g = doc_.NewElement("g");
        for (const tinyxml2::XMLAttribute* a = use->FirstAttribute(); a; a = a->Next()) {
            const std::string_view name = a->Name();
            if (name == "x" || name == "y" || name == "width" || name == "height" ||
                name == "href" || name == "xlink:href" || name == "transform")
                continue;
            g->SetAttribute(a->Name(), a->Value());
        }
        std::string transform = use->Attribute("transform") ? use->Attribute("transform") : "";
        if (x != 0.0 || y != 0.0) {
            char move[80];
            std::snprintf(move, sizeof move, " translate(%.17g,%.17g)", x, y);
            transform += move;
        }
        if (!transform.empty()) g->SetAttribute("transform", transform.c_str());
        g->SetAttribute(kLine, use->IntAttribute(kLine, use->GetLineNum()));
        g->SetAttribute(kUseOf, id.c_str());
        if (const char* u = use->Attribute(kUseLine)) g->SetAttribute(kUseLine, u);

        XMLElement* copy = target->DeepClone(&doc_)->ToElement();
        keep_lines(target, copy, use->IntAttribute(kLine, use->GetLineNum()));
        const std::string_view kind = svg_xml::local_name(target->Name());
        if (kind == "symbol" || kind == "svg") {
            if (kind == "symbol") copy->SetName("svg");
            for (const char* size : {"width", "height"}) {
                if (const char* v = use->Attribute(size)) {
                    copy->SetAttribute(size, v);
                } else if (kind == "symbol") {
                    copy->SetAttribute(size, "100%");
                }
            }
        }
        g->InsertEndChild(copy);
        use->Parent()->InsertAfterChild(use, g);
        // The group now draws what the use did, under its id: a use that
        // refers to this one (SVG allows a use of a use) copies the group,
        // never the use element deleted below.
        if (const char* own = use->Attribute("id")) {
            const auto mine = ids_.find(own);
            if (mine != ids_.end() && mine->second == use) mine->second = g;
        }
        use->Parent()->DeleteChild(use);

        chain.push_back(id);
        walk(g, chain, unrendered);
        chain.pop_back();
    }

    tinyxml2::XMLDocument& doc_;
    std::map<std::string, XMLElement*, std::less<>> ids_;
    std::size_t copied_ = 0;
};

}  // namespace

void expand(tinyxml2::XMLDocument& doc) {
    if (!doc.RootElement()) return;
    Expander expander(doc);
    std::vector<std::string> chain;
    expander.walk(doc.RootElement(), chain);
}

tinyxml2::XMLElement* copy_of(const tinyxml2::XMLElement* e, tinyxml2::XMLDocument& doc) {
    XMLElement* copy = e->DeepClone(&doc)->ToElement();
    keep_lines(e, copy);
    return copy;
}

std::string line_of(const tinyxml2::XMLElement* e) {
    std::string out = std::to_string(e->IntAttribute(kLine, e->GetLineNum()));
    if (const char* use = e->Attribute(kUseLine))
        out += ", drawn by use at line " + text::printable(use, 12);
    return out;
}

}  // namespace modsynth::drawing::svg_use
