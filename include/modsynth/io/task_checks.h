#pragma once
// What a task document may hold that modsynth reads past but its author
// most likely did not mean: keys formats.md does not define (a misspelt
// `base_region` is ignored, and the task is solved as if it had no base
// regions) and lengths that look like millimetres (every length is in
// metres). Warnings, not errors: formats.md lets other tools add keys.
// Each is an InputError naming the part, so that a caller may print it or
// refuse the task with it (`--strict`).
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include <modsynth/task/input_error.h>

namespace modsynth::io {

/// Keys the task format does not define, at any depth, each with the
/// nearest known key when one is close ("did you mean ...").
std::vector<task::InputError> unknown_keys(const nlohmann::json& doc);

/// Lengths that look like millimetres: a point of the path, an obstacle or
/// a base region more than 20 m from the origin, link bounds over 10 m.
/// One warning per kind, naming the first part and the unit.
std::vector<task::InputError> unit_warnings(const nlohmann::json& doc);

/// Both, in that order.
std::vector<task::InputError> task_warnings(const nlohmann::json& doc);

/// The known word nearest `word` (Damerau-Levenshtein), when it is close
/// enough to be a slip of the keyboard; else empty.
std::string nearest_word(std::string_view word, const std::vector<std::string>& known);

}  // namespace modsynth::io
