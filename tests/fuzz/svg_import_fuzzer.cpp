// SVG import on arbitrary bytes: read, placed, fitted and ordered as
// `modsynth import` does it, under a time limit (import_fuzz.h).
#include <cstddef>
#include <cstdint>

#include "import_fuzz.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return modsynth::fuzz::import_one(data, size, modsynth::drawing::DrawingFormat::Svg);
}
