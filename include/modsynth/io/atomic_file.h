#pragma once
// Every output file is written whole or not at all. The text goes to a
// temporary file in the same folder, which then replaces the target with
// rename(2): a reader, a crash or a SIGTERM in the middle of a write sees
// the previous file or the new one, never a truncated one.
#include <string>

namespace modsynth::io {

/// Writes text to path atomically. SIGINT, SIGTERM and SIGHUP wait until
/// the rename is done, so that an interrupted write leaves no temporary file
/// (only SIGKILL can: it is named ".NAME.tmp-PID-N"). Throws
/// std::runtime_error naming the path on failure; the previous file is then
/// untouched and the temporary file removed. A symbolic link's file is
/// replaced, the link kept; a device or pipe (/dev/stdout) is written to.
void write_file_atomically(const std::string& path, const std::string& text);

}  // namespace modsynth::io
