// The spatial task reader on arbitrary bytes: every input is a spatial
// task, an InputError naming the offending part (short printable UTF-8), or
// a CheckTimeout when checking the path against the obstacles takes longer
// than the reader was given; nothing else escapes. A task that parses keeps
// the documented caps, has no primitive of zero length (of any kind) and no
// helix of a pitch past the rules, and writes back to JSON that parses to
// the same task.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <variant>

#include <nlohmann/json.hpp>

#include <modsynth/geometry/primitive3.h>
#include <modsynth/io/check_timeout.h>
#include <modsynth/io/spatial_task_io.h>
#include <modsynth/run/deadline.h>
#include <modsynth/task/input_error.h>
#include <modsynth/task/limits.h>
#include <modsynth/text/printable.h>

namespace {

using namespace modsynth;

bool printable(const std::string& s) {
    return s.size() < 1000 && text::printable(s, s.size()) == s;
}

bool sound(const task::SpatialTask& t) {
    const auto inside = [](const geometry::Vec3& p) {
        return p.cwiseAbs().maxCoeff() <= task::kMaxCoordinate;
    };
    if (t.trajectory.empty() || t.trajectory.size() > task::kMaxPrimitives ||
        t.obstacles.size() > task::kMaxObstacles || t.base_regions.size() > task::kMaxBaseRegions)
        return false;
    for (const auto& p : t.trajectory) {
        if (!inside(geometry::start_point(p)) || !inside(geometry::end_point(p))) return false;
        if (!(geometry::length(p) >= 1e-9)) return false;
        if (const auto* h = std::get_if<geometry::Helix3>(&p))
            if (!(std::abs(h->pitch) >= 0.005 && std::abs(h->pitch) <= task::kMaxLength))
                return false;
    }
    for (const auto& b : t.base_regions)
        if (!inside(b.min) || !inside(b.max)) return false;
    if (t.robot.joint_limits)
        for (const auto* list : {&t.robot.joint_limits->velocity,
                                 &t.robot.joint_limits->acceleration, &t.robot.joint_limits->jerk})
            for (double v : *list)
                if (!(v >= task::kMinJointLimit && v <= task::kMaxJointLimit)) return false;
    return t.robot.max_link_length <= task::kMaxLength;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    task::SpatialTask task;
    try {
        // The checks of a long path among many obstacles stop here.
        task = io::parse_spatial_task_text(text, run::Deadline::in(1.0));
    } catch (const task::InputError& e) {
        if (!printable(e.what())) std::abort();
        return 0;
    } catch (const io::CheckTimeout& e) {
        if (!printable(e.what())) std::abort();
        return 0;
    }
    if (!sound(task)) std::abort();
    // What parsed must survive its own round trip.
    const nlohmann::json written = io::to_json(task);
    if (io::to_json(io::parse_spatial_task(written)) != written) std::abort();
    return 0;
}
