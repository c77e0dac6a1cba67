#pragma once
// Reads a log file while another process is still writing it: each call
// returns only the lines completed since the last one, so progress can be
// shown as it happens without pipes between the processes.
#include <cstdint>
#include <string>
#include <vector>

namespace modsynth::app {

class LogFollower {
public:
    explicit LogFollower(std::string path) : path_(std::move(path)) {}

    /// Lines finished since the previous call (without their newline). A
    /// partial last line waits for its end, unless `final` says the writer
    /// is gone.
    std::vector<std::string> new_lines(bool final = false);

private:
    std::string path_;
    std::uintmax_t offset_ = 0;
    std::string partial_;
};

}  // namespace modsynth::app
