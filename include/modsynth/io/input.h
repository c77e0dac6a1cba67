#pragma once
// The two steps every document reader shares: the bytes of a file the user
// named, and those bytes as JSON. Failures are task::InputErrors a user can
// act on (the path, or the line and column where the syntax breaks).
#include <cstddef>
#include <functional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include <modsynth/task/input_error.h>
#include <modsynth/task/input_file.h>

namespace modsynth::io {

// Opening and reading a file the user named (task/input_file.h: below
// every stage that reads one, the module catalog's too).
using task::InputFile;
using task::read_input_file;

/// JSON text as a document. A syntax error or a number beyond the range of
/// a double is an InputError for "(document)" saying where it is.
nlohmann::json parse_json_text(std::string_view text);

/// nlohmann's parser callback: called at each event, false drops the value.
using JsonCallback =
    std::function<bool(int depth, nlohmann::json::parse_event_t event, nlohmann::json& parsed)>;

/// The file's JSON, parsed as it is read: its text is never held whole, and
/// `callback` may take values out of the document as they complete (the
/// samples of a long motion). Errors as parse_json_text's, the line and
/// column read back from the file; a file that grows past its cap while it
/// is read is refused as too large.
nlohmann::json parse_json_file(const InputFile& file, const JsonCallback& callback);

/// read(path), whose InputErrors are said of the file ("rose.json:
/// trajectory[1]: ..."): a message about a document names the file it is in.
template <class Read>
auto read_document_file(const std::string& path, Read&& read) {
    try {
        return read(path);
    } catch (const task::InputError& e) {
        throw e.in_file(path);
    }
}

}  // namespace modsynth::io
