#include <modsynth/io/input.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <istream>
#include <streambuf>
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

namespace {

/// The file's bytes as a stream, a buffer at a time, never past the cap.
class FileBuffer : public std::streambuf {
public:
    explicit FileBuffer(const InputFile& file) : file_(file) {}

protected:
    int_type underflow() override {
        if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
        ssize_t n;
        do {
            n = ::read(file_.fd(), buffer_.data(), buffer_.size());
        } while (n < 0 && errno == EINTR);
        if (n < 0)
            throw InputError(file_.path(),
                             "cannot read the " + file_.what() + " file: " + std::strerror(errno));
        if (n == 0) return traits_type::eof();
        read_ += static_cast<std::size_t>(n);
        if (read_ > file_.max_bytes()) file_.too_large(read_);
        setg(buffer_.data(), buffer_.data(), buffer_.data() + n);
        return traits_type::to_int_type(*gptr());
    }

private:
    const InputFile& file_;
    std::array<char, 1 << 16> buffer_{};
    std::size_t read_ = 0;
};

/// Line and column of the byte at 1-based position `byte` of the file,
/// read back from its start.
std::pair<std::size_t, std::size_t> file_line_column(const InputFile& file, std::size_t byte) {
    std::array<char, 1 << 16> buffer{};
    std::size_t line = 1, column = 1, at = 0;
    const std::size_t end = byte == 0 ? 0 : byte - 1;
    while (at < end) {
        const ssize_t n = ::pread(file.fd(), buffer.data(), std::min(buffer.size(), end - at),
                                  static_cast<off_t>(at));
        if (n <= 0) break;
        for (ssize_t i = 0; i < n; ++i) {
            if (buffer[static_cast<std::size_t>(i)] == '\n') {
                ++line;
                column = 1;
            } else {
                ++column;
            }
        }
        at += static_cast<std::size_t>(n);
    }
    return {line, column};
}

}  // namespace

nlohmann::json parse_json_file(const InputFile& file, const JsonCallback& callback) {
    using nlohmann::json;
    FileBuffer buffer(file);
    std::istream in(&buffer);
    try {
        return json::parse(in, callback);
    } catch (const json::parse_error& e) {
        const auto [line, column] = file_line_column(file, e.byte);
        throw InputError(kDocument, "not valid JSON at line " + std::to_string(line) + ", column " +
                                        std::to_string(column) + ": " + parse_detail(e));
    } catch (const json::out_of_range& e) {
        throw InputError(kDocument, "a number is too large (" + json_error_detail(e) +
                                        "); numbers must be finite");
    } catch (const json::exception& e) {
        throw InputError(kDocument, "not valid JSON: " + json_error_detail(e));
    }
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
