#include <modsynth/task/part.h>

#include <array>
#include <cassert>
#include <utility>

#include <modsynth/task/strokes.h>

namespace modsynth::task {
namespace {

constexpr std::array<std::pair<RobotKey, const char*>, 15> kRobotKeys{{
    {RobotKey::Dof, "dof"},
    {RobotKey::LinkDiameter, "link_diameter"},
    {RobotKey::MinLinkLength, "min_link_length"},
    {RobotKey::MaxLinkLength, "max_link_length"},
    {RobotKey::ModuleLength, "module_length"},
    {RobotKey::ModuleWidth, "module_width"},
    {RobotKey::ModuleHeight, "module_height"},
    {RobotKey::AdapterLength, "adapter_length"},
    {RobotKey::EeRodDiameter, "ee_rod_diameter"},
    {RobotKey::Modules, "modules"},
    {RobotKey::Payload, "payload"},
    {RobotKey::Gravity, "gravity"},
    {RobotKey::JointLimits, "joint_limits"},
    {RobotKey::Twists, "twists"},
    {RobotKey::ToolLength, "tool_length"},
}};

std::string indexed(int i) { return "[" + std::to_string(i) + "]"; }

// Reads "[i]" at `at`, a whole number written as to_string writes it (no
// sign, no leading zero), and moves past it.
std::optional<int> read_index(std::string_view text, std::size_t& at) {
    if (at >= text.size() || text[at] != '[') return std::nullopt;
    std::size_t end = at + 1;
    long value = 0;
    while (end < text.size() && text[end] >= '0' && text[end] <= '9') {
        if (end > at + 1 && value == 0) return std::nullopt;  // a leading zero
        value = value * 10 + (text[end++] - '0');
        if (value > 1'000'000'000) return std::nullopt;
    }
    if (end == at + 1 || end >= text.size() || text[end] != ']') return std::nullopt;
    at = end + 1;
    return static_cast<int>(value);
}

bool starts(std::string_view text, std::string_view head) {
    return text.substr(0, head.size()) == head;
}

}  // namespace

const char* to_string(RobotKey key) {
    for (const auto& [k, name] : kRobotKeys)
        if (k == key) return name;
    return "";
}

TaskPart TaskPart::primitive(const Task& task, int j) {
    assert(j >= 0 && j < static_cast<int>(task.trajectory.size()));
    return primitive_part(task, j);
}

TaskPart TaskPart::with_field(std::string field) const {
    TaskPart p = *this;
    p.field_ = std::move(field);
    return p;
}

TaskPart TaskPart::whole() const { return with_field({}); }

bool TaskPart::holds(const TaskPart& other) const {
    if (*this == other) return true;
    if (!field_.empty()) return false;
    if (kind_ == Kind::BaseRegions) return other.kind_ == Kind::BaseRegion;
    return other.whole() == *this;
}

std::string to_string(const TaskPart& part) {
    std::string s;
    switch (part.kind()) {
        case TaskPart::Kind::Primitive:
            s = part.stroke() < 0 ? "trajectory" + indexed(part.index())
                                  : "strokes" + indexed(part.stroke()) + indexed(part.index());
            break;
        case TaskPart::Kind::Obstacle:
            s = "obstacles" + indexed(part.index());
            break;
        case TaskPart::Kind::BaseRegions:
            s = "base_regions";
            break;
        case TaskPart::Kind::BaseRegion:
            s = "base_regions" + indexed(part.index());
            break;
        case TaskPart::Kind::Robot:
            s = std::string("robot.") + to_string(part.key()) +
                (part.index() >= 0 ? indexed(part.index()) : std::string());
            break;
    }
    return part.field().empty() ? s : s + "." + part.field();
}

std::string to_string(const std::vector<TaskPart>& parts, const char* separator) {
    std::string s;
    for (std::size_t i = 0; i < parts.size(); ++i) s += (i ? separator : "") + to_string(parts[i]);
    return s;
}

std::vector<std::string> to_strings(const std::vector<TaskPart>& parts) {
    std::vector<std::string> out;
    out.reserve(parts.size());
    for (const TaskPart& p : parts) out.push_back(to_string(p));
    return out;
}

std::optional<TaskPart> parse_task_part(std::string_view name) {
    std::size_t at = 0;
    std::optional<TaskPart> part;
    if (starts(name, "trajectory[")) {
        at = 10;
        if (const auto j = read_index(name, at)) part = TaskPart::trajectory(*j);
    } else if (starts(name, "strokes[")) {
        at = 7;
        const auto s = read_index(name, at);
        const auto k = s ? read_index(name, at) : std::nullopt;
        if (k) part = TaskPart::stroke_primitive(*s, *k);
    } else if (starts(name, "obstacles[")) {
        at = 9;
        if (const auto i = read_index(name, at)) part = TaskPart::obstacle(*i);
    } else if (starts(name, "base_regions[")) {
        at = 12;
        if (const auto i = read_index(name, at)) part = TaskPart::base_region(*i);
    } else if (starts(name, "base_regions")) {
        at = 12;
        part = TaskPart::base_regions();
    } else if (starts(name, "robot.")) {
        for (const auto& [key, key_name] : kRobotKeys) {
            const std::string_view k(key_name);
            const std::size_t after = 6 + k.size();
            if (name.substr(6, k.size()) != k ||
                (after < name.size() && name[after] != '.' && name[after] != '['))
                continue;
            at = after;
            int i = -1;
            if (at < name.size() && name[at] == '[') {
                const auto read = read_index(name, at);
                if (!read) return std::nullopt;
                i = *read;
            }
            part = TaskPart::robot(key, i);
            break;
        }
    }
    if (!part) return std::nullopt;
    if (at == name.size()) return part;
    // What follows is a key inside the part.
    if (name[at] != '.' || at + 1 == name.size()) return std::nullopt;
    return part->with_field(std::string(name.substr(at + 1)));
}

std::optional<int> primitive_index(const Task& task, const TaskPart& part) {
    if (part.kind() != TaskPart::Kind::Primitive || part.index() < 0) return std::nullopt;
    if (part.stroke() < 0) {
        if (has_strokes(task) || part.index() >= static_cast<int>(task.trajectory.size()))
            return std::nullopt;
        return part.index();
    }
    if (!has_strokes(task) || part.stroke() >= stroke_count(task) ||
        part.index() > stroke_last(task, part.stroke()) - stroke_first(task, part.stroke()))
        return std::nullopt;
    return primitive_index(task, part.stroke(), part.index());
}

}  // namespace modsynth::task
