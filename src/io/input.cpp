#include <modsynth/io/input.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <utility>

#include <nlohmann/json.hpp>

#include <modsynth/task/input_error.h>
#include <modsynth/text/printable.h>

#include "json_parts.h"

namespace modsynth::io {
namespace {

using task::InputError;

/// 1-based line and column of the byte at 1-based position `byte`.
std::pair<std::size_t, std::size_t> line_column(std::string_view text, std::size_t byte) {
    const std::size_t pos = std::min(byte == 0 ? 0 : byte - 1, text.size());
    const std::size_t line = 1 + std::count(text.begin(), text.begin() + pos, '\n');
    const std::size_t last_nl = text.rfind('\n', pos == 0 ? std::string_view::npos : pos - 1);
    const std::size_t column =
        (pos == 0 || last_nl == std::string_view::npos) ? pos + 1 : pos - last_nl;
    return {line, column};
}

/// nlohmann's explanation without its exception-id prefix and its position;
/// it quotes the input, so it is made printable.
std::string parse_detail(const nlohmann::json::parse_error& e) {
    const std::string what = e.what();
    const std::size_t at = what.find("syntax error");
    if (at != std::string::npos) return text::printable(what.substr(at), 200);
    const std::size_t colon = what.find(": ");
    return text::printable(colon == std::string::npos ? what : what.substr(colon + 2), 200);
}

/// The number the parser could not hold (1e999) and where it stands:
/// nlohmann reports no position for it, only the number's text.
std::string overflow_detail(std::string_view text, const std::string& what) {
    const std::size_t open = what.find('\'');
    const std::size_t close = what.rfind('\'');
    if (open == std::string::npos || close <= open + 1) return "a number";
    const std::string number = what.substr(open + 1, close - open - 1);
    std::string out = "the number " + text::printable(number);
    const std::size_t at = text.find(number);
    if (at == std::string_view::npos) return out;
    const auto [line, column] = line_column(text, at + 1);
    return out + " at line " + std::to_string(line) + ", column " + std::to_string(column);
}

/// A JSON library error other than a syntax error in a few words, without
/// the library's error id.
std::string json_error_detail(const std::exception& e) {
    std::string what = e.what();
    const std::size_t close = what.find("] ");
    if (close != std::string::npos) what = what.substr(close + 2);
    // The offending token may be a whole file of digits.
    constexpr std::size_t kMax = 120;
    return what.size() <= kMax ? what : what.substr(0, kMax) + "...";
}

}  // namespace

std::string read_input_file(const std::string& path, const std::string& what,
                            std::size_t max_bytes) {
    // Opened without waiting (a FIFO with no writer would block here), then
    // judged by what was opened, so that nothing can be swapped in between.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        const int err = errno;
        std::error_code ec;
        if (std::filesystem::is_directory(path, ec))
            throw InputError(path, "is a folder, not a " + what + " file");
        throw InputError(path, "cannot open the " + what + " file: " + std::strerror(err));
    }
    struct Closer {
        int fd;
        ~Closer() { ::close(fd); }
    } closer{fd};
    struct stat st {};
    if (::fstat(fd, &st) != 0)
        throw InputError(path, "cannot read the " + what + " file: " + std::strerror(errno));
    if (S_ISDIR(st.st_mode)) throw InputError(path, "is a folder, not a " + what + " file");
    if (!S_ISREG(st.st_mode)) {
        throw InputError(
            path, "is not a regular file (a device, FIFO or socket), not a " + what + " file");
    }
    const auto too_large = [&](std::size_t bytes) {
        return InputError(path, std::to_string(bytes) + " bytes, more than the " +
                                    std::to_string(max_bytes) + " allowed for a " + what + " file");
    };
    if (static_cast<std::uintmax_t>(st.st_size) > max_bytes)
        throw too_large(static_cast<std::size_t>(st.st_size));
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
    // Read to the end, never past the cap: the file may grow meanwhile.
    std::string content;
    content.resize(std::min<std::size_t>(static_cast<std::size_t>(st.st_size), max_bytes) + 1);
    std::size_t got = 0;
    for (;;) {
        if (got == content.size()) {
            if (got > max_bytes) throw too_large(got);
            content.resize(std::min(max_bytes + 1, std::max<std::size_t>(2 * got, 4096)));
        }
        const ssize_t n = ::read(fd, content.data() + got, content.size() - got);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0)
            throw InputError(path, "cannot read the " + what + " file: " + std::strerror(errno));
        if (n == 0) break;
        got += static_cast<std::size_t>(n);
    }
    if (got > max_bytes) throw too_large(got);
    content.resize(got);
    return content;
}

nlohmann::json parse_json_text(std::string_view text) {
    using nlohmann::json;
    try {
        return json::parse(text.begin(), text.end());
    } catch (const json::parse_error& e) {
        const auto [line, column] = line_column(text, e.byte);
        throw InputError(kDocument, "not valid JSON at line " + std::to_string(line) + ", column " +
                                        std::to_string(column) + ": " + parse_detail(e));
    } catch (const json::out_of_range& e) {
        // The only one the parser throws: a number beyond double (1e999).
        throw InputError(kDocument,
                         overflow_detail(text, e.what()) + " is too large; numbers must be finite");
    } catch (const json::exception& e) {
        throw InputError(kDocument, "not valid JSON: " + json_error_detail(e));
    }
}

}  // namespace modsynth::io
