#include <modsynth/synth/status.h>

#include <modsynth/task/input_error.h>
#include <modsynth/text/printable.h>

namespace modsynth::synth {

const char* to_string(Status::Kind kind) {
    switch (kind) {
        case Status::Solved:
            return "solved";
        case Status::Infeasible:
            return "infeasible";
        case Status::Unknown:
            return "unknown";
    }
    return "unknown";
}

Status::Kind status_from_string(std::string_view text, const std::string& part) {
    for (const Status::Kind kind : {Status::Solved, Status::Infeasible, Status::Unknown}) {
        if (text == to_string(kind)) return kind;
    }
    throw task::InputError(part, "expected \"solved\", \"infeasible\" or \"unknown\", got \"" +
                                     text::printable(text) + "\"");
}

}  // namespace modsynth::synth
