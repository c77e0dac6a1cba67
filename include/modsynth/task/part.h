#pragma once
// A part of a task as cores, messages and errors name it (formats.md):
// "trajectory[3]", "strokes[1][0]", "obstacles[2]", "base_regions",
// "base_regions[0]", "robot.max_link_length", "robot.modules[1]", with an
// optional key inside it ("trajectory[2].normal"). Code makes, compares and
// dispatches on it as a value; it is text only where a document or a person
// reads it (to_string), and only the document readers turn text back into
// one (parse_task_part).
#include <compare>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <modsynth/task/task.h>

namespace modsynth::task {

/// The keys of a task's `robot` object, planar and spatial.
enum class RobotKey {
    Dof,
    LinkDiameter,
    MinLinkLength,
    MaxLinkLength,
    ModuleLength,
    ModuleWidth,
    ModuleHeight,
    AdapterLength,
    EeRodDiameter,
    Modules,
    Payload,
    Gravity,
    JointLimits,
    Twists,
    ToolLength,
};

/// "max_link_length", ...: the key as the document spells it.
const char* to_string(RobotKey key);

class TaskPart {
public:
    enum class Kind {
        Primitive,    ///< trajectory[j], or strokes[s][k] in a task written with strokes
        Obstacle,     ///< obstacles[i]
        BaseRegions,  ///< base_regions: all of them, where the base may stand
        BaseRegion,   ///< base_regions[i]
        Robot,        ///< robot.KEY, or robot.KEY[i] for an entry of a list
    };

    static TaskPart trajectory(int j) { return TaskPart(Kind::Primitive, -1, j); }
    static TaskPart stroke_primitive(int s, int k) { return TaskPart(Kind::Primitive, s, k); }
    /// Primitive j of task.trajectory, named as the task's document names it.
    static TaskPart primitive(const Task& task, int j);
    static TaskPart obstacle(int i) { return TaskPart(Kind::Obstacle, -1, i); }
    static TaskPart base_regions() { return TaskPart(Kind::BaseRegions, -1, -1); }
    static TaskPart base_region(int i) { return TaskPart(Kind::BaseRegion, -1, i); }
    static TaskPart robot(RobotKey key, int i = -1) {
        TaskPart p(Kind::Robot, -1, i);
        p.key_ = key;
        return p;
    }
    /// The key `field` of this part: trajectory(2).with_field("normal") is
    /// "trajectory[2].normal".
    TaskPart with_field(std::string field) const;
    /// The part without its field.
    TaskPart whole() const;

    Kind kind() const { return kind_; }
    /// Primitive: the stroke, or -1 in a task written with `trajectory`.
    int stroke() const { return stroke_; }
    /// The index in its list (the primitive within its stroke); -1 for a
    /// part that is no entry of a list.
    int index() const { return index_; }
    /// Robot only.
    RobotKey key() const { return key_; }
    const std::string& field() const { return field_; }
    bool is_robot(RobotKey key) const { return kind_ == Kind::Robot && key_ == key; }

    /// Whether this part is `other` or holds it: base_regions holds
    /// base_regions[1], trajectory[2] holds trajectory[2].normal.
    bool holds(const TaskPart& other) const;

    friend auto operator<=>(const TaskPart&, const TaskPart&) = default;

private:
    TaskPart(Kind kind, int stroke, int index) : kind_(kind), stroke_(stroke), index_(index) {}

    Kind kind_;
    int stroke_ = -1;
    int index_ = -1;
    RobotKey key_ = RobotKey::Dof;
    std::string field_;
};

/// The part's name in formats.md's terms.
std::string to_string(const TaskPart& part);
/// Each part's name, in order (a core as a document lists it).
std::vector<std::string> to_strings(const std::vector<TaskPart>& parts);
/// The parts' names joined by `separator`: "obstacles[0], base_regions".
std::string to_string(const std::vector<TaskPart>& parts, const char* separator);

/// The part a name written by to_string stands for, or nothing (for the
/// document readers only: everywhere else parts are values).
std::optional<TaskPart> parse_task_part(std::string_view name);

/// The index in task.trajectory of the primitive `part` names (with or
/// without a field), or nothing when it names none of this task's.
std::optional<int> primitive_index(const Task& task, const TaskPart& part);

}  // namespace modsynth::task
