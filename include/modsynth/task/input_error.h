#pragma once
#include <stdexcept>
#include <string>

namespace modsynth::task {

/// Bad input. what() is "PART: problem", where PART is the JSON path of the
/// offending part of the task (e.g. "trajectory[1].center"), so a user can
/// find it; part() returns PART alone.
class InputError : public std::runtime_error {
public:
    InputError(std::string part, const std::string& problem)
        : std::runtime_error(part.empty() ? problem : part + ": " + problem), part_(std::move(part)) {}
    const std::string& part() const { return part_; }

private:
    std::string part_;
};

/// The whole content of a file the user named, for parsing. Failures are
/// InputErrors whose part is the path; `what` says what the file should be
/// ("task", "solution").
std::string read_input_file(const std::string& path, const std::string& what);

/// A JSON library error other than a syntax error (a number beyond the range
/// of a double) in a few words, without the library's error id.
std::string json_error_detail(const std::exception& e);

}  // namespace modsynth::task
