#include <modsynth/io/atomic_file.h>

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <memory>
#include <stdexcept>

namespace modsynth::io {
namespace {

namespace fs = std::filesystem;

std::string failure(const std::string& path, const char* what, int err) {
    return path + ": " + what + " (" + std::strerror(err) + ")";
}

// Holds back the signals that end a process politely for the span of a
// write, so that the process ends after the rename instead of between the
// temporary file's creation and its rename or removal.
class DeferTermination {
public:
    DeferTermination() {
        sigset_t set;
        sigemptyset(&set);
        for (int sig : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&set, sig);
        pthread_sigmask(SIG_BLOCK, &set, &old_);
    }
    ~DeferTermination() { pthread_sigmask(SIG_SETMASK, &old_, nullptr); }
    DeferTermination(const DeferTermination&) = delete;
    DeferTermination& operator=(const DeferTermination&) = delete;

private:
    sigset_t old_;
};

std::string temporary_name(const fs::path& target) {
    // Unique within the process too: a server writes from several threads.
    static std::atomic<unsigned long> counter{0};
    const fs::path name = "." + target.filename().string() + ".tmp-" + std::to_string(getpid()) +
                          "-" + std::to_string(++counter);
    return (target.parent_path() / name).string();
}

bool write_all(int fd, const std::string& text) {
    const char* p = text.data();
    std::size_t left = text.size();
    while (left > 0) {
        const ssize_t n = ::write(fd, p, left);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        p += n;
        left -= static_cast<std::size_t>(n);
    }
    return true;
}

// A device or a pipe (-o /dev/stdout) cannot be replaced, only written to.
void write_in_place(const std::string& path, const std::string& text) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
    if (fd < 0) throw WriteError(failure(path, "cannot open for writing", errno));
    const bool written = write_all(fd, text);
    const int err = errno;
    ::close(fd);
    if (!written) throw WriteError(failure(path, "write failed", err));
}

}  // namespace

void write_file_atomically(const std::string& path, const std::string& text) {
    if (path.empty()) throw WriteError("cannot write a file with an empty name");
    std::error_code ec;
    const fs::file_status st = fs::status(path, ec);
    if (fs::exists(st) && !fs::is_regular_file(st) && !fs::is_directory(st))
        return write_in_place(path, text);
    AtomicFile file(path);
    file.write(text);
    file.commit();
}

struct AtomicFile::Open {
    DeferTermination defer;
    std::string path, temp, target;
    int fd = -1;
    int error = 0;  ///< the first write's errno that failed, 0 if none
};

AtomicFile::AtomicFile(const std::string& path) {
    if (path.empty()) throw WriteError("cannot write a file with an empty name");
    std::error_code ec;
    const fs::file_status st = fs::status(path, ec);
    // Renaming onto a symbolic link would replace the link, not its file.
    fs::path target = path;
    if (fs::is_symlink(fs::symlink_status(target, ec)) && fs::is_regular_file(st)) {
        const fs::path real = fs::canonical(target, ec);
        if (!ec) target = real;
    }
    auto open = std::make_unique<Open>();
    open->path = path;
    open->target = target.string();
    open->temp = temporary_name(target);
    open->fd = ::open(open->temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (open->fd < 0) throw WriteError(failure(path, "cannot open for writing", errno));
    open_ = std::move(open);
}

AtomicFile::~AtomicFile() {
    if (!open_) return;
    ::close(open_->fd);
    ::unlink(open_->temp.c_str());
}

void AtomicFile::write(std::string_view text) {
    if (!open_) throw WriteError("write to a file already closed");
    if (open_->error != 0) return;
    const char* p = text.data();
    std::size_t left = text.size();
    while (left > 0) {
        const ssize_t n = ::write(open_->fd, p, left);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            open_->error = n < 0 ? errno : ENOSPC;
            return;
        }
        p += n;
        left -= static_cast<std::size_t>(n);
    }
    bytes_ += text.size();
}

void AtomicFile::commit() {
    if (!open_) throw WriteError("commit of a file already closed");
    const std::unique_ptr<Open> open = std::move(open_);
    // fsync before rename: otherwise a power cut may leave the new name on
    // an empty file.
    int err = open->error;
    if (err == 0 && ::fsync(open->fd) != 0) err = errno;
    if (::close(open->fd) != 0 && err == 0) err = errno;
    if (err != 0) {
        ::unlink(open->temp.c_str());
        throw WriteError(failure(open->path, "write failed", err));
    }
    if (::rename(open->temp.c_str(), open->target.c_str()) != 0) {
        err = errno;
        ::unlink(open->temp.c_str());
        throw WriteError(failure(open->path, "cannot replace", err));
    }
}

}  // namespace modsynth::io
