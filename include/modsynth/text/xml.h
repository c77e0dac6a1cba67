#pragma once
// User text (a task's name, a catalog's module names, messages quoting
// them) written into XML and HTML (the URDF, the reports, SVG) must read as
// the very characters it holds: never markup, never the end of a comment,
// never a character an XML parser refuses.
#include <string>
#include <string_view>

namespace modsynth::text {

/// The text as XML or HTML character data or attribute value: '&', '<',
/// '>', '"' and '\'' as references; control characters other than tab and
/// line breaks (which XML 1.0 does not allow at all) and bytes that are not
/// UTF-8 as U+FFFD.
std::string xml_text(std::string_view text);

/// The text inside an XML comment (<!-- ... -->), where references mean
/// nothing: "--" (which would end or break the comment) written "- -", a
/// final '-' followed by a space, control characters and bytes that are
/// not UTF-8 as U+FFFD.
std::string xml_comment(std::string_view text);

}  // namespace modsynth::text
