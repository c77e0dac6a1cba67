#include <modsynth/task/input_file.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>

#include <modsynth/task/input_error.h>

namespace modsynth::task {

InputFile::InputFile(const std::string& path, const std::string& what, std::size_t max_bytes)
    : path_(path), what_(what), max_bytes_(max_bytes) {
    // Opened without waiting (a FIFO with no writer would block here), then
    // judged by what was opened, so that nothing can be swapped in between.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        const int err = errno;
        std::error_code ec;
        if (std::filesystem::is_directory(path, ec))
            throw InputError(path, "is a folder, not a " + what + " file");
        throw InputError(path, "cannot open the " + what + " file: " + std::strerror(err));
    }
    fd_ = fd;
    struct stat st {};
    if (::fstat(fd, &st) != 0) {
        const int err = errno;
        ::close(fd_);
        throw InputError(path, "cannot read the " + what + " file: " + std::strerror(err));
    }
    const auto refuse = [&](const std::string& why) {
        ::close(fd_);
        throw InputError(path, why);
    };
    if (S_ISDIR(st.st_mode)) refuse("is a folder, not a " + what + " file");
    if (!S_ISREG(st.st_mode))
        refuse("is not a regular file (a device, FIFO or socket), not a " + what + " file");
    if (static_cast<std::uintmax_t>(st.st_size) > max_bytes) {
        ::close(fd_);
        too_large(static_cast<std::size_t>(st.st_size));
    }
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
}

InputFile::~InputFile() { ::close(fd_); }

void InputFile::too_large(std::size_t bytes) const {
    throw InputError(path_, std::to_string(bytes) + " bytes, more than the " +
                                std::to_string(max_bytes_) + " allowed for a " + what_ + " file");
}

std::string read_input_file(const std::string& path, const std::string& what,
                            std::size_t max_bytes) {
    const InputFile file(path, what, max_bytes);
    struct stat st {};
    ::fstat(file.fd(), &st);
    // Read to the end, never past the cap: the file may grow meanwhile.
    std::string content;
    content.resize(std::min<std::size_t>(static_cast<std::size_t>(st.st_size), max_bytes) + 1);
    std::size_t got = 0;
    for (;;) {
        if (got == content.size()) {
            if (got > max_bytes) file.too_large(got);
            content.resize(std::min(max_bytes + 1, std::max<std::size_t>(2 * got, 4096)));
        }
        const ssize_t n = ::read(file.fd(), content.data() + got, content.size() - got);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0)
            throw InputError(path, "cannot read the " + what + " file: " + std::strerror(errno));
        if (n == 0) break;
        got += static_cast<std::size_t>(n);
    }
    if (got > max_bytes) file.too_large(got);
    content.resize(got);
    return content;
}

}  // namespace modsynth::task
