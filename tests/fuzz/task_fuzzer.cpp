// Task parsing and validation on arbitrary bytes: every input is either a
// task or an InputError naming the offending part; nothing else escapes,
// messages are short printable UTF-8, a task stays within the documented
// caps, and a task that parses writes back to JSON that parses to the same
// task. What the CLI prints of a valid task (the description of each part)
// must not throw either. Spatial tasks (`"space": "3d"`) go through their
// own reader with the same rules.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <variant>

#include <nlohmann/json.hpp>

#include <modsynth/io/spatial_task_io.h>
#include <modsynth/io/task_document.h>
#include <modsynth/io/task_io.h>
#include <modsynth/prove/conflict_text.h>
#include <modsynth/task/input_error.h>
#include <modsynth/task/limits.h>
#include <modsynth/text/printable.h>

namespace {

using namespace modsynth::task;
using modsynth::io::parse_task;
using modsynth::io::to_json;

bool printable(const std::string& s) {
    return s.size() < 1000 && modsynth::text::printable(s, s.size()) == s;
}

bool within_caps(const Task& t) {
    const auto inside = [](const modsynth::geometry::Vec2& p) {
        return std::fabs(p.x()) <= kMaxCoordinate && std::fabs(p.y()) <= kMaxCoordinate;
    };
    if (t.trajectory.size() > kMaxPrimitives || t.obstacles.size() > kMaxObstacles ||
        t.base_regions.size() > kMaxBaseRegions)
        return false;
    for (const auto& p : t.trajectory)
        if (!inside(p.start) || !inside(p.end)) return false;
    for (const auto& o : t.obstacles)
        if (!inside(o.center) || o.radius > kMaxLength) return false;
    return t.robot.max_link_length <= kMaxLength;
}

bool within_caps(const SpatialTask& t) {
    const auto inside = [](const modsynth::geometry::Vec3& p) {
        return p.cwiseAbs().maxCoeff() <= kMaxCoordinate;
    };
    if (t.trajectory.size() > kMaxPrimitives || t.obstacles.size() > kMaxObstacles ||
        t.base_regions.size() > kMaxBaseRegions)
        return false;
    for (const auto& p : t.trajectory)
        if (!inside(modsynth::geometry::start_point(p)) ||
            !inside(modsynth::geometry::end_point(p)))
            return false;
    for (const auto& b : t.base_regions)
        if (!inside(b.min) || !inside(b.max)) return false;
    return t.robot.max_link_length <= kMaxLength;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    modsynth::io::TaskDocument doc;
    try {
        doc = modsynth::io::parse_task_document_text(text);
    } catch (const InputError& e) {
        if (!printable(e.what())) std::abort();
        return 0;
    }
    if (const auto* spatial = std::get_if<SpatialTask>(&doc)) {
        if (!within_caps(*spatial)) std::abort();
        const auto written = to_json(*spatial);
        if (to_json(modsynth::io::parse_spatial_task(written)) != written) std::abort();
        return 0;
    }
    const Task task = std::get<Task>(std::move(doc));
    if (!within_caps(task)) std::abort();
    // What parsed must survive its own round trip.
    const auto again = to_json(parse_task(to_json(task)));
    if (again != to_json(task)) std::abort();
    // The descriptions explain and the report print for every part.
    using modsynth::task::RobotKey;
    using modsynth::task::TaskPart;
    for (std::size_t j = 0; j < task.trajectory.size() && j < 8; ++j)
        (void)modsynth::prove::describe_part(task, TaskPart::primitive(task, static_cast<int>(j)));
    for (std::size_t i = 0; i < task.obstacles.size() && i < 8; ++i)
        (void)modsynth::prove::describe_part(task, TaskPart::obstacle(static_cast<int>(i)));
    for (const TaskPart& part :
         {TaskPart::base_regions(), TaskPart::robot(RobotKey::MaxLinkLength),
          TaskPart::robot(RobotKey::MinLinkLength), TaskPart::robot(RobotKey::LinkDiameter),
          TaskPart::robot(RobotKey::Dof)})
        (void)modsynth::prove::describe_part(task, part);
    return 0;
}
