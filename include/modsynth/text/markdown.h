#pragma once
// User text (a task's name, a message quoting it) embedded in Markdown must
// read as the very characters it holds: neither markup nor raw HTML, nor a
// line break that ends a heading or a table row.
#include <string>
#include <string_view>

namespace modsynth::text {

/// The text as literal Markdown inline content: ASCII punctuation escaped
/// with a backslash, '<', '>', '&', '"' and '\'' as HTML entities (a
/// renderer that passes HTML through then shows them too), and control
/// characters, line breaks included, as U+FFFD. Bytes >= 0x80 are kept.
std::string markdown_literal(std::string_view text);

/// modsynth's own sentences (a proof, a reason) as Markdown that reads as
/// plain text too: only what CommonMark would take for markup is escaped
/// (emphasis, code, links, HTML, table bars, a block marker at the start),
/// and ":", "-", "(" and the like are left as they are. Control
/// characters become U+FFFD as above.
std::string markdown_text(std::string_view text);

}  // namespace modsynth::text
