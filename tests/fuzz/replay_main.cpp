// A main for the fuzz targets in an ordinary build: feeds every file of the
// folders (or files) named on the command line to LLVMFuzzerTestOneInput,
// once each. The test suite runs it over the seed corpus and the inputs that
// once crashed (regressions/), so every finding stays a regression test.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);
// A target whose fixture runs threads defines this to stop them: exit's
// destructors of statics must not run under a thread still serving.
extern "C" void modsynth_fuzz_teardown() __attribute__((weak));

namespace {

int replay(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    const std::vector<char> bytes{std::istreambuf_iterator<char>(in), {}};
    std::fprintf(stderr, "replay %s\n", file.c_str());
    return LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()),
                                  bytes.size());
}

}  // namespace

int main(int argc, char** argv) {
    int files = 0;
    for (int i = 1; i < argc; ++i) {
        const std::filesystem::path arg = argv[i];
        if (std::filesystem::is_directory(arg)) {
            std::vector<std::filesystem::path> inputs;
            for (const auto& entry : std::filesystem::recursive_directory_iterator(arg))
                if (entry.is_regular_file()) inputs.push_back(entry.path());
            std::sort(inputs.begin(), inputs.end());
            for (const auto& file : inputs) files += (replay(file), 1);
        } else if (std::filesystem::is_regular_file(arg)) {
            files += (replay(arg), 1);
        } else {
            std::fprintf(stderr, "no such input: %s\n", argv[i]);
            return 2;
        }
    }
    if (files == 0) {
        std::fprintf(stderr, "no inputs to replay\n");
        return 2;
    }
    if (modsynth_fuzz_teardown) modsynth_fuzz_teardown();
    std::printf("%d passed, 0 failed: replayed %d inputs\n", files, files);
    return 0;
}
