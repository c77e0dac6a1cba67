#pragma once
// The two steps every document reader shares: the bytes of a file the user
// named, and those bytes as JSON. Failures are task::InputErrors a user can
// act on (the path, or the line and column where the syntax breaks).
#include <cstddef>
#include <string>
#include <string_view>

#include <nlohmann/json_fwd.hpp>

#include <modsynth/task/input_error.h>

namespace modsynth::io {

/// The whole content of a file; `what` says what the file should be ("task",
/// "solution"). A path that is not a regular file (a folder, a FIFO, a
/// device such as /dev/zero) or a file of more than `max_bytes` is refused
/// before anything is read; a FIFO is never waited on. Failures are
/// InputErrors whose part is the path.
std::string read_input_file(const std::string& path, const std::string& what,
                            std::size_t max_bytes);

/// JSON text as a document. A syntax error or a number beyond the range of
/// a double is an InputError for "(document)" saying where it is.
nlohmann::json parse_json_text(std::string_view text);

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
