#include <modsynth/task/part_list.h>

namespace modsynth::task {

namespace {

/// Whether `b` follows `a` in a run: the next primitive of the same stroke,
/// or the next obstacle (whole parts, no field).
bool follows(const TaskPart& a, const TaskPart& b) {
    if (!a.field().empty() || !b.field().empty() || a.kind() != b.kind()) return false;
    if (a.kind() == TaskPart::Kind::Primitive)
        return a.stroke() == b.stroke() && b.index() == a.index() + 1;
    return a.kind() == TaskPart::Kind::Obstacle && b.index() == a.index() + 1;
}

}  // namespace

std::vector<PartRun> part_runs(const std::vector<TaskPart>& parts) {
    std::vector<PartRun> out;
    for (std::size_t i = 0; i < parts.size();) {
        std::size_t end = i + 1;
        while (end < parts.size() && follows(parts[end - 1], parts[end])) ++end;
        out.push_back({i, end - 1});
        i = end;
    }
    return out;
}

std::string run_text(const std::vector<TaskPart>& parts, const PartRun& run) {
    if (run.size() >= 3) return to_string(parts[run.first]) + " to " + to_string(parts[run.last]);
    std::string out;
    for (std::size_t k = run.first; k <= run.last; ++k)
        out += (out.empty() ? "" : " ") + to_string(parts[k]);
    return out;
}

std::string to_short_list(const std::vector<TaskPart>& parts) {
    std::string out;
    for (const PartRun& run : part_runs(parts))
        out += (out.empty() ? "" : " ") + run_text(parts, run);
    return out;
}

}  // namespace modsynth::task
