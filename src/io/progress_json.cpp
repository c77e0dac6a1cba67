#include <modsynth/io/progress_json.h>

#include <nlohmann/json.hpp>

namespace modsynth::io {

std::string progress_json_line(const run::ProgressEvent& event) {
    const nlohmann::ordered_json j = {{"stage", run::to_string(event.stage)},
                                      {"message", event.message},
                                      {"elapsed", event.elapsed}};
    return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::optional<run::ProgressEvent> parse_progress_json_line(std::string_view line) {
    const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
    if (!j.is_object()) return std::nullopt;
    const auto stage = j.find("stage");
    const auto message = j.find("message");
    const auto elapsed = j.find("elapsed");
    if (stage == j.end() || !stage->is_string() || message == j.end() || !message->is_string() ||
        elapsed == j.end() || !elapsed->is_number())
        return std::nullopt;
    const auto s = run::stage_from_string(stage->get<std::string>());
    if (!s) return std::nullopt;
    return run::ProgressEvent{*s, message->get<std::string>(), elapsed->get<double>()};
}

}  // namespace modsynth::io
