#pragma once
// Every output file is written whole or not at all. The text goes to a
// temporary file in the same folder, which then replaces the target with
// rename(2): a reader, a crash or a SIGTERM in the middle of a write sees
// the previous file or the new one, never a truncated one.
#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>

namespace modsynth::io {

/// An output that could not be written (disk full, permissions): what()
/// names the file and says why. Not the input's fault, nor a defect.
class WriteError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// Writes text to path atomically. SIGINT, SIGTERM and SIGHUP wait until
/// the rename is done, so that an interrupted write leaves no temporary file
/// (only SIGKILL can: it is named ".NAME.tmp-PID-N"). Throws
/// WriteError naming the path on failure; the previous file is then
/// untouched and the temporary file removed. A symbolic link's file is
/// replaced, the link kept; a device or pipe (/dev/stdout) is written to.
void write_file_atomically(const std::string& path, const std::string& text);

/// The same, written piece by piece: a file of hundreds of megabytes (a
/// long motion's samples) never has to be held whole. Nothing appears at
/// `path` until commit(); a file destroyed before it leaves nothing (the
/// temporary file is removed), and a failed write is reported by commit().
/// The terminating signals wait from construction to commit or destruction.
/// Only regular files and new paths: a device is written with
/// write_file_atomically.
class AtomicFile {
public:
    /// Throws WriteError naming `path` when the temporary file cannot be made.
    explicit AtomicFile(const std::string& path);
    ~AtomicFile();
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    void write(std::string_view text);
    /// Bytes written so far.
    std::size_t bytes() const { return bytes_; }
    /// Makes the file the one at `path`; throws WriteError naming it when
    /// any write failed or it cannot be replaced (the previous file then
    /// stays).
    void commit();

private:
    struct Open;
    std::unique_ptr<Open> open_;
    std::size_t bytes_ = 0;
};

}  // namespace modsynth::io
