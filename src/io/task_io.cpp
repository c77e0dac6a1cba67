#include <modsynth/io/task_io.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include <modsynth/geometry/distance.h>
#include <modsynth/io/input.h>
#include <modsynth/task/limits.h>
#include <modsynth/task/strokes.h>
#include <modsynth/text/format.h>
#include <modsynth/text/printable.h>

#include "json_parts.h"
#include "json_values.h"

namespace modsynth::io {

using task::BaseRegion;
using task::InputError;
using task::kMaxBaseRegions;
using task::kMaxCoordinate;
using task::kMaxDof;
using task::kMaxLength;
using task::kMaxObstacles;
using task::kMaxPrimitives;
using task::kMaxTaskBytes;
using task::kMinDof;
using task::Obstacle;
using task::Primitive;
using task::RobotSpec;
using task::Task;
using task::Vec2;

namespace {

using nlohmann::json;

constexpr const char* kFormat = "modsynth-task/1";
/// Below this a length is treated as zero: a degenerate primitive.
constexpr double kDegenerate = 1e-9;

// The values of the document: the same rules, caps and wording as the
// spatial reader's (json_values.h); points here are planar.
using values::describe;
using values::finite_number;
using values::metres;
using values::non_negative_length;
using values::positive_length;
using values::require_array;
using values::require_count_cap;
using values::require_object;
using values::required;
using values::text;

std::string point_text(const Vec2& p) { return "[" + metres(p.x()) + ", " + metres(p.y()) + "]"; }

Vec2 point(const json& j, const std::string& part) {
    if (!j.is_array()) throw InputError(part, "expected a point [x, y], got " + describe(j));
    if (j.size() != 2) {
        throw InputError(part, "expected a point [x, y] with 2 numbers, got a list of " +
                                   std::to_string(j.size()));
    }
    const char* names[2] = {"x", "y"};
    Vec2 p;
    for (int k = 0; k < 2; ++k) {
        const json& c = j[static_cast<std::size_t>(k)];
        if (!c.is_number() || !std::isfinite(c.get<double>())) {
            throw InputError(part, std::string("the ") + names[k] +
                                       " coordinate must be a finite number, got " + describe(c));
        }
        p[k] = c.get<double>();
        if (std::fabs(p[k]) > kMaxCoordinate) {
            throw InputError(part, std::string("the ") + names[k] + " coordinate " + metres(p[k]) +
                                       " m is beyond the " + text::compact(kMaxCoordinate) +
                                       " m from the origin allowed");
        }
    }
    return p;
}

bool direction_ccw(const json& prim, const std::string& part, const char* why) {
    const std::string p = member(part, "direction");
    const std::string d = text(required(prim, part, "direction", why), p, "\"ccw\" or \"cw\"");
    if (d == "ccw") return true;
    if (d == "cw") return false;
    throw InputError(p, "expected \"ccw\" (counter-clockwise) or \"cw\" (clockwise), got \"" +
                            text::printable(d) + "\"");
}

Vec2 required_point(const json& prim, const std::string& part, const char* key, const char* why) {
    return point(required(prim, part, key, why), member(part, key));
}

Primitive parse_line(const json& prim, const std::string& part) {
    const char* why = "a line needs \"start\" and \"end\"";
    const Vec2 start = required_point(prim, part, "start", why);
    const Vec2 end = required_point(prim, part, "end", why);
    if ((end - start).norm() < kDegenerate) {
        throw InputError(
            part, "line has zero length: start and end are the same point " + point_text(start));
    }
    return geometry::make_line(start, end);
}

void require_radius(const Vec2& start, const Vec2& center, const std::string& part,
                    const char* kind) {
    if ((start - center).norm() < kDegenerate) {
        throw InputError(part, std::string(kind) + " start " + point_text(start) +
                                   " is its center, so its radius is 0");
    }
}

Primitive parse_arc(const json& prim, const std::string& part) {
    const char* why = "an arc needs \"start\", \"end\", \"center\" and \"direction\"";
    const Vec2 start = required_point(prim, part, "start", why);
    Vec2 end = required_point(prim, part, "end", why);
    const Vec2 center = required_point(prim, part, "center", why);
    const bool ccw = direction_ccw(prim, part, why);
    require_radius(start, center, part, "arc");
    const double gap = (end - center).norm() - (start - center).norm();
    if (std::fabs(gap) > kJoinTolerance) {
        throw InputError(part, "arc end is " + metres(std::fabs(gap)) + " m " +
                                   (gap > 0 ? "farther from" : "closer to") +
                                   " center than start; both must lie on the same circle");
    }
    // A start equal to the end within rounding means a full circle; passing
    // the exact start lets make_arc recognise it.
    if ((end - start).norm() < kDegenerate) end = start;
    return geometry::make_arc(start, end, center, ccw);
}

Primitive parse_circle(const json& prim, const std::string& part) {
    const char* why = "a circle needs \"start\", \"center\" and \"direction\"";
    const Vec2 start = required_point(prim, part, "start", why);
    const Vec2 center = required_point(prim, part, "center", why);
    const bool ccw = direction_ccw(prim, part, why);
    require_radius(start, center, part, "circle");
    if (const json* r = optional(prim, "radius")) {
        const std::string rp = member(part, "radius");
        const double radius = finite_number(*r, rp, "a radius in metres");
        const double actual = (start - center).norm();
        if (std::fabs(radius - actual) > kJoinTolerance) {
            throw InputError(rp, "radius " + metres(radius) + " m disagrees with the distance " +
                                     metres(actual) + " m from start to center");
        }
    }
    return geometry::make_circle(start, center, ccw);
}

Primitive parse_primitive(const json& prim, const std::string& part) {
    require_object(prim, part, "{\"type\": \"line\", \"start\": [x, y], \"end\": [x, y]}");
    const char* kinds = "\"line\", \"arc\" or \"circle\"";
    const std::string why = std::string("expected ") + kinds;
    const std::string tp = member(part, "type");
    const std::string type = text(required(prim, part, "type", why.c_str()), tp, kinds);
    if (type == "line") return parse_line(prim, part);
    if (type == "arc") return parse_arc(prim, part);
    if (type == "circle") return parse_circle(prim, part);
    throw InputError(tp, "unknown primitive type \"" + text::printable(type) + "\"; " + why);
}

void require_connected(const Primitive& prev, const Primitive& next, const std::string& prev_part,
                       const std::string& part) {
    const double gap = (next.start - prev.end).norm();
    if (gap > kJoinTolerance) {
        throw InputError(part, "starts " + metres(gap) + " m from the end of " + prev_part +
                                   " (it ends at " + point_text(prev.end) +
                                   "); consecutive primitives must connect");
    }
}

/// One list of connected primitives, `part` naming the list; appended to
/// `out` (whose primitives before `first` belong to earlier strokes).
void parse_primitives(const json& list, const std::string& part, std::vector<Primitive>& out) {
    const std::size_t first = out.size();
    for (std::size_t j = 0; j < list.size(); ++j) {
        out.push_back(parse_primitive(list[j], element(part, j)));
        if (j > 0)
            require_connected(out[first + j - 1], out[first + j], element(part, j - 1),
                              element(part, j));
    }
}

std::vector<Primitive> parse_trajectory(const json& list) {
    const std::string part = "trajectory";
    require_array(list, part, "primitives");
    if (list.empty()) throw InputError(part, "is empty; a task needs at least one primitive");
    require_count_cap(list, part, "primitives", kMaxPrimitives);
    std::vector<Primitive> out;
    out.reserve(list.size());
    parse_primitives(list, part, out);
    return out;
}

/// formats.md "Several strokes": each stroke connected in itself, the
/// strokes one after another in task.trajectory.
void parse_strokes(const json& list, Task& task) {
    const std::string part = "strokes";
    require_array(list, part, "strokes (each a list of primitives)");
    if (list.empty()) throw InputError(part, "is empty; a task needs at least one stroke");
    std::size_t total = 0;
    for (std::size_t s = 0; s < list.size(); ++s) {
        const std::string sp = element(part, s);
        require_array(list[s], sp, "primitives");
        if (list[s].empty())
            throw InputError(sp, "is empty; every stroke needs at least one primitive");
        total += list[s].size();
    }
    if (total > kMaxPrimitives) {
        throw InputError(part, std::to_string(total) + " primitives, more than the " +
                                   std::to_string(kMaxPrimitives) + " allowed");
    }
    task.trajectory.reserve(total);
    for (std::size_t s = 0; s < list.size(); ++s) {
        task.stroke_starts.push_back(static_cast<int>(task.trajectory.size()));
        parse_primitives(list[s], element(part, s), task.trajectory);
    }
}

/// Exactly one of `trajectory` and `strokes`.
void parse_path(const json& doc, Task& task) {
    const json* trajectory = optional(doc, "trajectory");
    const json* strokes = optional(doc, "strokes");
    if (trajectory && strokes) {
        throw InputError(
            "strokes", "a task holds either \"trajectory\" (one stroke) or \"strokes\", not both");
    }
    if (strokes) {
        parse_strokes(*strokes, task);
        return;
    }
    task.trajectory = parse_trajectory(required(
        doc, "", "trajectory",
        "a task needs a list of primitives to follow (or \"strokes\", a list of such lists)"));
}

// -------------------------------------------------------------- the others

Obstacle parse_obstacle(const json& j, const std::string& part) {
    require_object(j, part, "{\"center\": [x, y], \"radius\": r}");
    const char* why = "an obstacle needs \"center\" and \"radius\"";
    Obstacle o;
    o.center = point(required(j, part, "center", why), member(part, "center"));
    o.radius = positive_length(required(j, part, "radius", why), member(part, "radius"));
    return o;
}

BaseRegion parse_base_region(const json& j, const std::string& part) {
    require_object(j, part, "{\"min\": [x, y], \"max\": [x, y]}");
    const char* why = "a base region needs \"min\" and \"max\" corners";
    BaseRegion b;
    b.min = point(required(j, part, "min", why), member(part, "min"));
    b.max = point(required(j, part, "max", why), member(part, "max"));
    for (int k = 0; k < 2; ++k) {
        if (b.min[k] > b.max[k]) {
            const char* axis = k == 0 ? "x" : "y";
            throw InputError(part, std::string("min ") + axis + " " + metres(b.min[k]) +
                                       " m is larger than max " + axis + " " + metres(b.max[k]) +
                                       " m");
        }
    }
    return b;
}

template <class T, class Parse>
std::vector<T> parse_list(const json& doc, const char* key, const char* what, std::size_t cap,
                          Parse parse) {
    std::vector<T> out;
    const json* list = optional(doc, key);
    if (!list) return out;
    require_array(*list, key, what);
    require_count_cap(*list, key, what, cap);
    for (std::size_t i = 0; i < list->size(); ++i) {
        out.push_back(parse((*list)[i], element(key, i)));
    }
    return out;
}

int joint_count(const json& j, const std::string& part) {
    const bool integral =
        j.is_number_integer() || (j.is_number_float() && std::isfinite(j.get<double>()) &&
                                  j.get<double>() == std::floor(j.get<double>()));
    if (!integral) throw InputError(part, "expected a whole number of joints, got " + describe(j));
    const double v = j.get<double>();
    if (v < kMinDof || v > kMaxDof) {
        throw InputError(
            part, describe(j) + " joints is not supported; modsynth builds robots with " +
                      std::to_string(kMinDof) + " to " + std::to_string(kMaxDof) + " joints");
    }
    return static_cast<int>(v);
}

std::vector<int> parse_dof(const json& j, const std::string& part) {
    require_array(j, part, "joint counts, e.g. [2, 3]");
    if (j.empty()) throw InputError(part, "is empty; list at least one joint count, e.g. [2, 3]");
    std::vector<int> dof;
    for (std::size_t i = 0; i < j.size(); ++i) {
        const int n = joint_count(j[i], element(part, i));
        if (std::find(dof.begin(), dof.end(), n) != dof.end()) {
            throw InputError(element(part, i), std::to_string(n) + " is listed twice");
        }
        dof.push_back(n);
    }
    std::sort(dof.begin(), dof.end());
    return dof;
}

/// Optional module and tube sizes; only the build sheet and URDF use them.
void parse_hardware(const json& robot, const std::string& part, RobotSpec& r) {
    const std::pair<const char*, double*> keys[] = {{"module_length", &r.module_length},
                                                    {"module_width", &r.module_width},
                                                    {"module_height", &r.module_height},
                                                    {"adapter_length", &r.adapter_length},
                                                    {"ee_rod_diameter", &r.ee_rod_diameter}};
    for (const auto& [key, value] : keys) {
        if (const json* v = optional(robot, key)) *value = positive_length(*v, member(part, key));
    }
}

/// Optional keys for choosing modules (formats.md "Modules and loads").
void parse_loads(const json& robot, const std::string& part, RobotSpec& r) {
    if (const json* v = optional(robot, "modules")) {
        const std::string p = member(part, "modules");
        require_array(*v, p, "module names, e.g. [\"X8-9\", \"X5-4\"]");
        if (v->empty())
            throw InputError(p, "is empty; list at least one module, or leave the key out");
        require_count_cap(*v, p, "modules", 100);
        for (std::size_t i = 0; i < v->size(); ++i) {
            const std::string name = text((*v)[i], element(p, i), "a module name (text)");
            if (name.empty()) throw InputError(element(p, i), "is empty; expected a module name");
            if (std::find(r.modules.begin(), r.modules.end(), name) != r.modules.end()) {
                throw InputError(element(p, i),
                                 "\"" + text::printable(name) + "\" is listed twice");
            }
            r.modules.push_back(name);
        }
    }
    if (const json* v = optional(robot, "payload")) {
        const std::string p = member(part, "payload");
        r.payload = finite_number(*v, p, "a mass in kg");
        if (r.payload < 0.0)
            throw InputError(p, "must not be negative, got " + describe(*v) + " kg");
        if (r.payload > 1000.0)
            throw InputError(p, describe(*v) + " kg is more than the 1000 kg allowed");
    }
    if (const json* v = optional(robot, "gravity")) {
        const std::string p = member(part, "gravity");
        if (v->is_string() && v->get<std::string>() == "joint_axes") {
            r.gravity.reset();
        } else if (v->is_array()) {
            if (v->size() != 2) {
                throw InputError(p, "expected [gx, gy] in m/s^2 with 2 numbers, got a list of " +
                                        std::to_string(v->size()));
            }
            Vec2 g;
            for (std::size_t k = 0; k < 2; ++k)
                g[k] = finite_number((*v)[k], element(p, k), "an acceleration in m/s^2");
            if (g.norm() > 100.0)
                throw InputError(p, "|g| = " + text::compact(g.norm()) +
                                        " m/s^2 is more than the 100 m/s^2 allowed");
            r.gravity = g;
        } else {
            throw InputError(
                p,
                "expected \"joint_axes\" (the default: gravity along the joint axes) or "
                "a vector [gx, gy] in m/s^2 in the task plane, got " +
                    describe(*v));
        }
    }
}

/// `robot.joint_limits`. A list with one value per joint fixes the joint
/// count: the search then considers only that count.
void parse_joint_limits(const json& robot, const std::string& robot_part, RobotSpec& r) {
    if (const json* limits = optional(robot, "joint_limits"))
        r.joint_limits = values::joint_limits(*limits, member(robot_part, "joint_limits"), r.dof);
}

RobotSpec parse_robot(const json& doc) {
    RobotSpec r;
    const json* robot = optional(doc, "robot");
    if (!robot) return r;
    const std::string part = "robot";
    require_object(*robot, part, "{\"dof\": [2, 3], \"max_link_length\": 1.0}");
    if (const json* v = optional(*robot, "dof")) r.dof = parse_dof(*v, member(part, "dof"));
    if (const json* v = optional(*robot, "link_diameter")) {
        r.link_diameter = positive_length(*v, member(part, "link_diameter"));
    }
    if (const json* v = optional(*robot, "min_link_length")) {
        r.min_link_length = non_negative_length(*v, member(part, "min_link_length"));
    }
    if (const json* v = optional(*robot, "max_link_length")) {
        r.max_link_length = positive_length(*v, member(part, "max_link_length"));
    }
    if (optional(*robot, "joint_diameter"))
        throw InputError(member(part, "joint_diameter"), "joint bodies are not supported yet");
    parse_hardware(*robot, part, r);
    parse_loads(*robot, part, r);
    parse_joint_limits(*robot, part, r);
    if (r.min_link_length > r.max_link_length) {
        throw InputError(member(part, "min_link_length"),
                         "minimum link length " + metres(r.min_link_length) +
                             " m is larger than the maximum link length " +
                             metres(r.max_link_length) + " m");
    }
    return r;
}

std::string parse_name(const json& doc) {
    const json* name = optional(doc, "name");
    return name ? text(*name, "name", "a name (text)") : std::string();
}

void check_format(const json& doc) {
    const json& f = required(doc, "", "format",
                             "a task document must start with \"format\": \"modsynth-task/1\"");
    if (!f.is_string() || f.get<std::string>() != kFormat) {
        throw InputError("format", std::string("expected \"") + kFormat + "\", got " + describe(f) +
                                       "; this is not a task file modsynth can read");
    }
}

/// `"space": "plane"` (or no `space`) is the planar task; a spatial task
/// (`"3d"`, io/spatial_task_io.h) is refused by name rather than misread as
/// planar, by callers that take planar tasks only.
void check_space(const json& doc) {
    const json* space = optional(doc, "space");
    if (!space) return;
    const std::string value = text(*space, "space", "\"plane\" or \"3d\"");
    if (value == "plane") return;
    if (value == "3d") {
        throw InputError("space", "spatial tasks (\"space\": \"3d\") are not supported here yet");
    }
    throw InputError("space", "expected \"plane\" or \"3d\", got " + describe(*space));
}

/// Nothing can trace a path that runs through an obstacle, whatever the robot.
void check_clearance(const Task& task) {
    for (std::size_t i = 0; i < task.obstacles.size(); ++i) {
        const Obstacle& o = task.obstacles[i];
        for (std::size_t j = 0; j < task.trajectory.size(); ++j) {
            const double d = geometry::point_primitive(o.center, task.trajectory[j]);
            if (d <= o.radius) {
                throw InputError(element("obstacles", i),
                                 "touches " + task::part_name(task, static_cast<int>(j)) +
                                     " (the path runs " + metres(o.radius - d) +
                                     " m inside it); the path must stay outside every obstacle");
            }
        }
    }
}

// ------------------------------------------------------------------ output

json point_json(const Vec2& p) { return json::array({p.x(), p.y()}); }

json primitive_json(const Primitive& p) {
    const char* dir = p.sweep >= 0 ? "ccw" : "cw";
    switch (p.kind) {
        case geometry::PrimitiveKind::Line:
            return {{"type", "line"}, {"start", point_json(p.start)}, {"end", point_json(p.end)}};
        case geometry::PrimitiveKind::Arc:
            return {{"type", "arc"},
                    {"start", point_json(p.start)},
                    {"end", point_json(p.end)},
                    {"center", point_json(p.center)},
                    {"direction", dir}};
        case geometry::PrimitiveKind::Circle:
            return {{"type", "circle"},
                    {"start", point_json(p.start)},
                    {"center", point_json(p.center)},
                    {"direction", dir},
                    {"radius", p.radius}};
    }
    return {};
}

}  // namespace

Task parse_task(const json& doc) {
    if (!doc.is_object()) {
        throw InputError(
            kDocument,
            "expected a JSON object {\"format\": \"modsynth-task/1\", ...}, got " + describe(doc));
    }
    check_format(doc);
    check_space(doc);
    Task task;
    task.name = parse_name(doc);
    parse_path(doc, task);
    task.obstacles =
        parse_list<Obstacle>(doc, "obstacles", "obstacles", kMaxObstacles, parse_obstacle);
    task.base_regions = parse_list<BaseRegion>(doc, "base_regions", "base regions", kMaxBaseRegions,
                                               parse_base_region);
    task.robot = parse_robot(doc);
    check_clearance(task);
    return task;
}

Task parse_task_text(std::string_view text) {
    if (text.size() > kMaxTaskBytes) {
        throw InputError(kDocument, std::to_string(text.size()) + " bytes, more than the " +
                                        std::to_string(kMaxTaskBytes) + " allowed for a task");
    }
    return parse_task(parse_json_text(text));
}

Task load_task(const std::string& path) {
    Task task = read_document_file(path, [](const std::string& p) {
        return parse_task_text(read_input_file(p, "task", kMaxTaskBytes));
    });
    if (task.name.empty()) task.name = std::filesystem::path(path).stem().string();
    return task;
}

namespace {

/// The optional keys of module selection, only when set, so that a task
/// without them is written as before.
void add_loads_json(const RobotSpec& r, json& robot) {
    if (!r.modules.empty()) robot["modules"] = r.modules;
    if (r.payload > 0.0) robot["payload"] = r.payload;
    if (r.gravity) robot["gravity"] = point_json(*r.gravity);
}

}  // namespace

json to_json(const Task& task) {
    json trajectory = json::array();
    json strokes = json::array();
    for (int j = 0; j < static_cast<int>(task.trajectory.size()); ++j) {
        if (!task::has_strokes(task)) {
            trajectory.push_back(primitive_json(task.trajectory[j]));
            continue;
        }
        if (task::index_in_stroke(task, j) == 0) strokes.push_back(json::array());
        strokes.back().push_back(primitive_json(task.trajectory[j]));
    }
    json obstacles = json::array();
    for (const Obstacle& o : task.obstacles) {
        obstacles.push_back({{"center", point_json(o.center)}, {"radius", o.radius}});
    }
    json regions = json::array();
    for (const BaseRegion& b : task.base_regions) {
        regions.push_back({{"min", point_json(b.min)}, {"max", point_json(b.max)}});
    }
    json robot = {{"dof", task.robot.dof},
                  {"link_diameter", task.robot.link_diameter},
                  {"min_link_length", task.robot.min_link_length},
                  {"max_link_length", task.robot.max_link_length},
                  {"module_length", task.robot.module_length},
                  {"module_width", task.robot.module_width},
                  {"module_height", task.robot.module_height},
                  {"adapter_length", task.robot.adapter_length},
                  {"ee_rod_diameter", task.robot.ee_rod_diameter}};
    if (const auto& l = task.robot.joint_limits)
        robot["joint_limits"] = values::joint_limits_json(*l);
    add_loads_json(task.robot, robot);
    json doc = {{"format", kFormat},
                {"name", task.name},
                {"obstacles", obstacles},
                {"base_regions", regions},
                {"robot", robot}};
    if (task::has_strokes(task)) {
        doc["strokes"] = std::move(strokes);
    } else {
        doc["trajectory"] = std::move(trajectory);
    }
    return doc;
}

}  // namespace modsynth::io
