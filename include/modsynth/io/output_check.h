#pragma once
// Where a command will write, checked before it does any work: a run of
// minutes must not end in an output it cannot write, a FIFO it blocks on,
// or the loss of the very file it read.
#include <string>
#include <vector>

namespace modsynth::io {

/// One file a command writes: the option that names it ("-o", "--report")
/// and its path.
struct OutputFile {
    std::string option;
    std::string path;
};

/// Throws task::InputError, its part "OPTION PATH", unless every output is
/// a regular file or a new name in an existing folder that may be written
/// (never a folder, FIFO, socket or device), none is one of `inputs` (the
/// same file by any path or link, or the same new name), and no two
/// outputs are the same file. Outputs with an empty path are not asked for
/// and pass.
void check_outputs(const std::vector<OutputFile>& outputs, const std::vector<std::string>& inputs);

}  // namespace modsynth::io
