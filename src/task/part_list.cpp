#include <modsynth/task/part_list.h>

namespace modsynth::task {

std::string to_short_list(const std::vector<TaskPart>& parts) {
    std::string out;
    for (std::size_t i = 0; i < parts.size();) {
        std::size_t end = i + 1;
        if (parts[i].kind() == TaskPart::Kind::Primitive && parts[i].field().empty())
            while (end < parts.size() && parts[end].kind() == TaskPart::Kind::Primitive &&
                   parts[end].field().empty() && parts[end].stroke() == parts[i].stroke() &&
                   parts[end].index() == parts[end - 1].index() + 1)
                ++end;
        out += (out.empty() ? "" : " ") + to_string(parts[i]);
        if (end - i >= 3) {
            out += " to " + to_string(parts[end - 1]);
        } else {
            for (std::size_t k = i + 1; k < end; ++k) out += " " + to_string(parts[k]);
        }
        i = end;
    }
    return out;
}

}  // namespace modsynth::task
