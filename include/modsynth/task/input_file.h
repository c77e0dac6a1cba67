#pragma once
// Files the user named (a task, a solution, a drawing, the module catalog's
// files), opened the one way: what is not a regular file (a folder, a FIFO,
// a device such as /dev/zero) and a file past its cap are refused before
// anything is read, and a FIFO is never waited on. Failures are InputErrors
// whose part is the path.
#include <cstddef>
#include <string>

namespace modsynth::task {

/// A file opened for reading as read_input_file opens it, closed when
/// destroyed; `what` says what the file should be ("task", "solution").
class InputFile {
public:
    InputFile(const std::string& path, const std::string& what, std::size_t max_bytes);
    ~InputFile();
    InputFile(const InputFile&) = delete;
    InputFile& operator=(const InputFile&) = delete;

    int fd() const { return fd_; }
    const std::string& path() const { return path_; }
    const std::string& what() const { return what_; }
    std::size_t max_bytes() const { return max_bytes_; }
    /// Throws the InputError of a file past the cap, `bytes` long or more.
    [[noreturn]] void too_large(std::size_t bytes) const;

private:
    int fd_ = -1;
    std::string path_, what_;
    std::size_t max_bytes_;
};

/// The whole content of a file, never more than `max_bytes` of it (the file
/// may grow while it is read).
std::string read_input_file(const std::string& path, const std::string& what,
                            std::size_t max_bytes);

}  // namespace modsynth::task
