#include <modsynth/io/output_check.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <optional>

#include <modsynth/task/input_error.h>
#include <modsynth/text/printable.h>

namespace modsynth::io {
namespace {

namespace fs = std::filesystem;
using task::InputError;

/// A file as the system knows it (device and inode, through any links), or
/// for a name that does not exist yet, its absolute path with `.`, `..` and
/// the links of its folders resolved.
struct Identity {
    bool exists = false;
    dev_t device = 0;
    ino_t inode = 0;
    std::string path;

    bool same(const Identity& o) const {
        if (exists != o.exists) return false;
        return exists ? device == o.device && inode == o.inode : path == o.path;
    }
};

std::optional<Identity> identity(const std::string& path) {
    struct stat st {};
    Identity id;
    if (::stat(path.c_str(), &st) == 0) {
        id.exists = true;
        id.device = st.st_dev;
        id.inode = st.st_ino;
        return id;
    }
    std::error_code ec;
    const fs::path absolute = fs::absolute(path, ec);
    if (ec) return std::nullopt;
    id.path = fs::weakly_canonical(absolute, ec).string();
    if (ec) id.path = absolute.lexically_normal().string();
    return id;
}

std::string label(const OutputFile& o) { return o.option + " " + text::printable(o.path, 200); }

void check_one(const OutputFile& o) {
    const std::string part = label(o);
    struct stat st {};
    if (::stat(o.path.c_str(), &st) == 0) {
        if (S_ISDIR(st.st_mode))
            throw InputError(part, "is a folder; give a file name for the output");
        if (!S_ISREG(st.st_mode))
            throw InputError(part,
                             "is not a regular file (a device, FIFO or socket); outputs are "
                             "written to regular files or new names");
        if (::access(o.path.c_str(), W_OK) != 0)
            throw InputError(part, std::string("cannot be written: ") + std::strerror(errno));
        return;
    }
    if (errno != ENOENT)
        throw InputError(part, std::string("cannot be written: ") + std::strerror(errno));
    // A new file: its folder must be there to hold it.
    fs::path folder = fs::path(o.path).parent_path();
    if (folder.empty()) folder = ".";
    struct stat fst {};
    if (::stat(folder.c_str(), &fst) != 0)
        throw InputError(part,
                         "its folder " + text::printable(folder.string(), 200) + " does not exist");
    if (!S_ISDIR(fst.st_mode))
        throw InputError(part, text::printable(folder.string(), 200) + " is not a folder");
    if (::access(folder.c_str(), W_OK | X_OK) != 0)
        throw InputError(part, "its folder " + text::printable(folder.string(), 200) +
                                   " cannot be written: " + std::strerror(errno));
}

}  // namespace

void check_outputs(const std::vector<OutputFile>& outputs, const std::vector<std::string>& inputs) {
    // What is already spoken for, and the end of the message that says by
    // what.
    std::vector<std::pair<Identity, std::string>> taken;
    for (const std::string& in : inputs) {
        if (in.empty()) continue;
        if (const auto id = identity(in))
            taken.emplace_back(*id, "the input " + text::printable(in, 200) +
                                        ": writing there would destroy what the command reads");
    }
    for (const OutputFile& o : outputs) {
        if (o.path.empty()) continue;
        check_one(o);
        const auto id = identity(o.path);
        if (!id) continue;
        for (const auto& [other, what] : taken)
            if (id->same(other)) throw InputError(label(o), "is " + what);
        taken.emplace_back(*id,
                           "also the output of " + o.option + ": one would overwrite the other");
    }
}

}  // namespace modsynth::io
