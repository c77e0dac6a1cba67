#include <modsynth/run/progress.h>

#include <array>
#include <cstdio>
#include <utility>

namespace modsynth::run {
namespace {

constexpr std::array<std::pair<Stage, const char*>, 10> kNames{{
    {Stage::Proofs, "proofs"},
    {Stage::FrontStage, "front stage"},
    {Stage::Search, "search"},
    {Stage::Refinement, "refinement"},
    {Stage::Verification, "verification"},
    {Stage::Shortening, "shortening"},
    {Stage::Timing, "timing"},
    {Stage::Modules, "modules"},
    {Stage::Explanation, "explanation"},
    {Stage::Baseline, "baseline"},
}};

}  // namespace

const char* to_string(Stage stage) {
    for (const auto& [s, name] : kNames)
        if (s == stage) return name;
    return "";
}

std::optional<Stage> stage_from_string(std::string_view name) {
    for (const auto& [s, n] : kNames)
        if (name == n) return s;
    return std::nullopt;
}

std::string console_line(const ProgressEvent& event) {
    char clock[32];
    std::snprintf(clock, sizeof clock, "[%7.3fs] ", event.elapsed);
    return clock + event.message;
}

}  // namespace modsynth::run
