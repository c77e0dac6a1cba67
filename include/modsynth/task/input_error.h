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
        : std::runtime_error(part.empty() ? problem : part + ": " + problem),
          part_(std::move(part)) {}
    const std::string& part() const { return part_; }

private:
    std::string part_;
};

}  // namespace modsynth::task
