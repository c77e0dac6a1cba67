#pragma once
// Progress events (run/progress.h) as JSON lines, for a program that follows
// a run from another process (the server follows its solves so):
// {"stage": "front stage", "message": "2 joints: front stage", "elapsed": 0.012}
#include <optional>
#include <string>
#include <string_view>

#include <modsynth/run/progress.h>

namespace modsynth::io {

/// One line of JSON, without its newline.
std::string progress_json_line(const run::ProgressEvent& event);

/// The event a line written by progress_json_line holds; nothing for a
/// line that is not one (a partial line, another program's output).
std::optional<run::ProgressEvent> parse_progress_json_line(std::string_view line);

}  // namespace modsynth::io
