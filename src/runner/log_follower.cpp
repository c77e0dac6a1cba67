#include "log_follower.h"

#include <fstream>

namespace modsynth::app {

std::vector<std::string> LogFollower::new_lines(bool final) {
    std::vector<std::string> lines;
    std::ifstream in(path_, std::ios::binary);
    if (in) {
        in.seekg(static_cast<std::streamoff>(offset_));
        std::string chunk((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        offset_ += chunk.size();
        partial_ += chunk;
    }
    std::size_t begin = 0;
    for (std::size_t end; (end = partial_.find('\n', begin)) != std::string::npos; begin = end + 1)
        lines.push_back(partial_.substr(begin, end - begin));
    partial_.erase(0, begin);
    if (final && !partial_.empty()) {
        lines.push_back(partial_);
        partial_.clear();
    }
    return lines;
}

}  // namespace modsynth::app
