#include <modsynth/prove/conflict_text.h>

#include <algorithm>

#include <modsynth/text/format.h>

namespace modsynth::prove {
namespace {

using task::RobotKey;
using task::TaskPart;

std::vector<std::string> names_of(const std::vector<TaskPart>& core, TaskPart::Kind kind) {
    std::vector<std::string> out;
    for (const TaskPart& p : core)
        if (p.kind() == kind) out.push_back(task::to_string(p));
    return out;
}

bool names(const std::vector<TaskPart>& core, const TaskPart& part) {
    return std::find(core.begin(), core.end(), part) != core.end();
}

std::string robot_words(const task::Task& task, RobotKey key) {
    const auto& r = task.robot;
    switch (key) {
        case RobotKey::MaxLinkLength:
            return text::format("links of at most %.3f m", r.max_link_length);
        case RobotKey::MinLinkLength:
            return text::format("links of at least %.3f m", r.min_link_length);
        case RobotKey::LinkDiameter:
            return text::format("tubes %.4f m thick", r.link_diameter);
        case RobotKey::Dof:
            return joint_counts(task) + " joints";
        case RobotKey::ModuleLength:
        case RobotKey::ModuleWidth:
        case RobotKey::ModuleHeight:
        case RobotKey::AdapterLength:
        case RobotKey::EeRodDiameter:
        case RobotKey::Modules:
        case RobotKey::Payload:
        case RobotKey::Gravity:
        case RobotKey::JointLimits:
        case RobotKey::Twists:
        case RobotKey::ToolLength:
            return "";
    }
    return "";
}

}  // namespace

std::string listing(const std::vector<std::string>& items, const char* last) {
    std::string s;
    for (std::size_t i = 0; i < items.size(); ++i)
        s += (i == 0 ? "" : (i + 1 == items.size() ? last : ", ")) + items[i];
    return s;
}

std::string joint_counts(const task::Task& task) {
    std::vector<std::string> d;
    for (int k : task.robot.dof) d.push_back(std::to_string(k));
    return listing(d, " or ");
}

std::string describe_conflict(const task::Task& task, const std::vector<TaskPart>& core) {
    const auto traj = names_of(core, TaskPart::Kind::Primitive);
    const auto obst = names_of(core, TaskPart::Kind::Obstacle);
    const bool base = names(core, TaskPart::base_regions());
    const bool longest = names(core, TaskPart::robot(RobotKey::MaxLinkLength));
    const bool shortest = names(core, TaskPart::robot(RobotKey::MinLinkLength));
    const bool tube = names(core, TaskPart::robot(RobotKey::LinkDiameter));
    const std::string arms = "an arm of " + joint_counts(task) + " links";
    if (!traj.empty() && longest && obst.empty() && !shortest) {
        return listing(traj) + (traj.size() > 1 ? " cannot all be reached" : " is out of reach") +
               (base ? " from every allowed base position" : " from any base position") + " by " +
               arms + text::format(" of at most %.2f m.", task.robot.max_link_length);
    }
    if (traj.empty() && !obst.empty() && base && tube) {
        return listing(obst) + (obst.size() > 1 ? " cover" : " covers") +
               " every allowed base position: the first joint would stand inside an obstacle.";
    }
    if (!traj.empty() && !obst.empty() && tube && !base && !longest) {
        return listing(obst) + " lies closer to " + listing(traj) +
               text::format(
                   " than half the tube diameter (%.4f m): the last link, which ends on the path, "
                   "would "
                   "touch it.",
                   task.robot.link_diameter / 2);
    }
    if (!traj.empty() && shortest) {
        return listing(traj) + " passes too close to " +
               (base ? std::string("every allowed base position") : std::string("the base")) +
               text::format(" for links of at least %.2f m: the arm cannot fold that tightly.",
                            task.robot.min_link_length);
    }
    std::vector<std::string> all;
    for (const TaskPart& p : core) all.push_back(task::to_string(p));
    return "These parts of the task cannot all be satisfied by " + arms + ": " + listing(all) + ".";
}

std::string describe_part(const task::Task& task, const TaskPart& part) {
    const std::string name = task::to_string(part);
    switch (part.kind()) {
        case TaskPart::Kind::Primitive: {
            const auto j = task::primitive_index(task, part);
            if (!j) return name;
            const auto& p = task.trajectory.at(*j);
            switch (p.kind) {
                case geometry::PrimitiveKind::Line:
                    return name +
                           text::format(": a line from (%.3f, %.3f)", p.start.x(), p.start.y()) +
                           text::format(" to (%.3f, %.3f)", p.end.x(), p.end.y());
                case geometry::PrimitiveKind::Arc:
                    return name +
                           text::format(": an arc from (%.3f, %.3f)", p.start.x(), p.start.y()) +
                           text::format(" to (%.3f, %.3f)", p.end.x(), p.end.y()) +
                           text::format(" around (%.3f, %.3f)", p.center.x(), p.center.y());
                case geometry::PrimitiveKind::Circle:
                    return name + text::format(": a circle of radius %.3f m around (%.3f, %.3f)",
                                               p.radius, p.center.x(), p.center.y());
            }
            geometry::invalid_kind(p.kind);
        }
        case TaskPart::Kind::Obstacle: {
            if (part.index() >= static_cast<int>(task.obstacles.size())) return name;
            const auto& o = task.obstacles[part.index()];
            return name + text::format(": a disc of radius %.3f m at (%.3f, %.3f)", o.radius,
                                       o.center.x(), o.center.y());
        }
        case TaskPart::Kind::BaseRegions: {
            std::string s = name + ": the base must stand in";
            for (std::size_t k = 0; k < task.base_regions.size(); ++k) {
                const auto& r = task.base_regions[k];
                s += (k ? " or" : "") + text::format(" [%.3f, %.3f] x", r.min.x(), r.max.x()) +
                     text::format(" [%.3f, %.3f]", r.min.y(), r.max.y());
            }
            return s;
        }
        case TaskPart::Kind::BaseRegion:
        case TaskPart::Kind::ToolAxis:
            return name;
        case TaskPart::Kind::Robot: {
            const std::string words = part.field().empty() ? robot_words(task, part.key()) : "";
            return words.empty() ? name : name + ": " + words;
        }
    }
    return name;
}

}  // namespace modsynth::prove
