#pragma once
#include <stdexcept>
#include <string>

namespace modsynth::task {

/// Bad input. what() is "PART: problem", where PART is the JSON path of the
/// offending part of the task (e.g. "trajectory[1].center"), so a user can
/// find it; part() returns PART alone. Said of a file (in_file), what() is
/// "FILE: PART: problem", naming each once: "FILE: problem" when the part
/// is the file itself or the whole document.
class InputError : public std::runtime_error {
public:
    InputError(std::string part, const std::string& problem)
        : InputError(std::string(), std::move(part), problem) {}
    const std::string& part() const { return part_; }
    /// The file the input came from, once said (in_file), else empty.
    const std::string& file() const { return file_; }
    /// The problem alone, without the part or the file.
    const std::string& problem() const { return problem_; }
    /// The same error, said of `file`; an error already said of a file
    /// stays as it is.
    InputError in_file(const std::string& file) const {
        return file_.empty() ? InputError(file, part_, problem_) : *this;
    }

private:
    InputError(std::string file, std::string part, std::string problem)
        : std::runtime_error(message(file, part, problem)),
          part_(std::move(part)),
          file_(std::move(file)),
          problem_(std::move(problem)) {}
    static std::string message(const std::string& file, const std::string& part,
                               const std::string& problem) {
        std::string out;
        if (!file.empty()) out = file + ": ";
        if (!part.empty() && part != file && !(part == "(document)" && !file.empty()))
            out += part + ": ";
        return out + problem;
    }
    std::string part_;
    std::string file_;
    std::string problem_;
};

}  // namespace modsynth::task
