#pragma once
// A private scratch folder, removed with everything in it when it goes out
// of scope (also when an exception passes).
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>

namespace modsynth::app {

class TempDir {
public:
    explicit TempDir(const std::string& prefix) {
        const auto base = std::filesystem::temp_directory_path() / (prefix + ".XXXXXX");
        std::string pattern = base.string();
        if (!mkdtemp(pattern.data()))
            throw std::runtime_error(base.parent_path().string() +
                                     ": cannot create a scratch folder");
        path_ = pattern;
    }
    ~TempDir() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    const std::string& path() const { return path_; }

private:
    std::string path_;
};

}  // namespace modsynth::app
