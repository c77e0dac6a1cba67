#pragma once
// The editor page (web/ in the source tree), compiled into the binary so
// that `modsynth serve` needs no files beside it and works offline.
#include <cstddef>
#include <string_view>

namespace modsynth::app {

struct WebAsset {
    std::string_view path;  ///< URL path, e.g. "/index.html"
    const char* mime;
    const unsigned char* data;
    std::size_t size;

    std::string_view text() const { return {reinterpret_cast<const char*>(data), size}; }
};

/// The file served at `path`, or null.
const WebAsset* find_web_asset(std::string_view path);

}  // namespace modsynth::app
