#pragma once
// Reading a task file on the command line: the task, and on stderr what
// looks like a mistake in it (unknown keys with the nearest known one,
// lengths in millimetres); `--strict` refuses an unknown key instead.
#include <string>

#include <CLI/CLI.hpp>

#include <modsynth/io/task_document.h>

namespace modsynth::app {

/// --strict, for the commands that read a task file.
void add_strict_option(CLI::App& sub, bool& strict);

/// The task file at `path`; its warnings printed as "warning: FILE: PART:
/// ...". Under `strict` the first unknown key is an InputError (exit 2).
/// A spatial task's checks stop at `deadline` (io::CheckTimeout).
io::TaskDocument read_task_file(const std::string& path, bool strict,
                                const run::Deadline& deadline = {});

}  // namespace modsynth::app
