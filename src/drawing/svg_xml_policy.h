#pragma once
// SVG++ reads XML through a policy per parser; this is the one for
// tinyxml2, which SVG++ does not ship. tinyxml2 knows no namespaces, so an
// element or attribute is SVG when it has no prefix or the prefix "svg";
// "xlink:" and "xml:" name those namespaces; other prefixes (inkscape:,
// sodipodi:) are foreign and skipped.
#include <cstring>
#include <string_view>

#include <tinyxml2.h>
#include <boost/range/iterator_range.hpp>
#include <svgpp/definitions.hpp>
#include <svgpp/detail/namespace.hpp>
#include <svgpp/policy/xml/fwd.hpp>

namespace modsynth::drawing::svg_xml {

/// The prefix of a qualified name ("" when none).
inline std::string_view prefix(const char* name) {
    const char* colon = std::strchr(name, ':');
    return colon ? std::string_view(name, colon - name) : std::string_view();
}

inline const char* local_name(const char* name) {
    const char* colon = std::strchr(name, ':');
    return colon ? colon + 1 : name;
}

inline bool is_svg_element(const tinyxml2::XMLElement* e) {
    const std::string_view p = prefix(e->Name());
    return p.empty() || p == "svg";
}

}  // namespace modsynth::drawing::svg_xml

namespace svgpp::policy::xml {

template <>
struct attribute_iterator<const tinyxml2::XMLAttribute*> {
    typedef const tinyxml2::XMLAttribute* iterator_type;
    typedef boost::iterator_range<const char*> string_type;
    typedef string_type attribute_name_type;
    typedef string_type attribute_value_type;
    typedef string_type saved_value_type;

    static string_type get_string_range(const string_type& str) { return str; }
    static void advance(iterator_type& a) { a = a->Next(); }
    static bool is_end(iterator_type a) { return a == nullptr; }
    static BOOST_SCOPED_ENUM(detail::namespace_id) get_namespace(iterator_type a) {
        const std::string_view p = modsynth::drawing::svg_xml::prefix(a->Name());
        if (p.empty()) return detail::namespace_id::svg;
        if (p == "xlink") return detail::namespace_id::xlink;
        if (p == "xml") return detail::namespace_id::xml;
        return detail::namespace_id::other;
    }
    static attribute_name_type get_local_name(iterator_type a) {
        const char* n = modsynth::drawing::svg_xml::local_name(a->Name());
        return {n, n + std::strlen(n)};
    }
    static attribute_value_type get_value(iterator_type a) {
        return {a->Value(), a->Value() + std::strlen(a->Value())};
    }
    static saved_value_type save_value(iterator_type a) { return get_value(a); }
    static iterator_type get_attribute(iterator_type a) { return a; }
};

template <>
struct element_iterator<const tinyxml2::XMLElement*> {
    typedef const tinyxml2::XMLElement* iterator_type;
    typedef boost::iterator_range<const char*> string_type;
    typedef string_type element_name_type;
    typedef string_type element_text_type;
    typedef const tinyxml2::XMLAttribute* attribute_enumerator_type;

    static string_type get_string_range(const string_type& str) { return str; }
    static void advance_element(iterator_type& e) {
        e = e->NextSiblingElement();
        skip_foreign(e);
    }
    // Text content is never used: only the elements are walked.
    static void advance_element_or_text(iterator_type& e) { advance_element(e); }
    static bool is_end(iterator_type e) { return e == nullptr; }
    static bool is_text(iterator_type) { return false; }
    static element_name_type get_local_name(iterator_type e) {
        const char* n = modsynth::drawing::svg_xml::local_name(e->Name());
        return {n, n + std::strlen(n)};
    }
    static element_text_type get_text(iterator_type) { return {nullptr, nullptr}; }
    static attribute_enumerator_type get_attributes(iterator_type e) { return e->FirstAttribute(); }
    static iterator_type get_child_elements(iterator_type e) {
        iterator_type child = e->FirstChildElement();
        skip_foreign(child);
        return child;
    }
    static iterator_type get_child_elements_and_texts(iterator_type e) {
        return get_child_elements(e);
    }

private:
    static void skip_foreign(iterator_type& e) {
        while (e && !modsynth::drawing::svg_xml::is_svg_element(e)) e = e->NextSiblingElement();
    }
};

}  // namespace svgpp::policy::xml
