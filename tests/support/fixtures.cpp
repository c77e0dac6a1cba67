#include "fixtures.h"

#include <fstream>
#include <stdexcept>

namespace modsynth::testing {

nlohmann::json read_json(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot read " + path);
    return nlohmann::json::parse(in);
}

}  // namespace modsynth::testing
