#pragma once
// A task whose checks did not end before the deadline its reader was given:
// it is neither valid nor invalid yet. Checking that a long path keeps off
// many obstacles costs primitives x turns x obstacles; a reader given a
// deadline stops there, and the command answers "unknown" (exit 4) rather
// than hold a process or a server's worker past its time limit.
#include <stdexcept>
#include <string>

namespace modsynth::io {

class CheckTimeout : public std::runtime_error {
public:
    /// `doing`: what the check was at ("checking trajectory[0] against
    /// obstacles[12]"); `task_name`: the task's name as read, "" if none.
    CheckTimeout(std::string task_name, const std::string& doing)
        : std::runtime_error("the time limit was reached while " + doing),
          task_name_(std::move(task_name)),
          doing_(doing) {}
    const std::string& task_name() const { return task_name_; }
    const std::string& doing() const { return doing_; }

private:
    std::string task_name_, doing_;
};

}  // namespace modsynth::io
