#include <modsynth/io/spatial_task_io.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include <modsynth/geometry/curve_distance.h>
#include <modsynth/geometry/distance3.h>
#include <modsynth/io/check_timeout.h>
#include <modsynth/io/input.h>
#include <modsynth/io/task_io.h>
#include <modsynth/task/limits.h>
#include <modsynth/task/spatial_strokes.h>
#include <modsynth/text/printable.h>

#include "json_parts.h"
#include "json_values.h"

namespace modsynth::io {

using geometry::Box3;
using geometry::Obstacle3;
using geometry::Primitive3;
using geometry::Vec3;
using task::InputError;
using task::SpatialRobotSpec;
using task::SpatialTask;
using task::ToolAxis;
using namespace values;

namespace {

using nlohmann::json;

constexpr const char* kFormat = "modsynth-task/1";
/// Below this a length is zero: a degenerate primitive.
constexpr double kDegenerate = 1e-9;
/// formats.md: |pitch| >= 0.005 m, so that neighbouring turns stay apart.
constexpr double kMinPitch = 0.005;
/// A helix of more turns describes no job a workshop arm does, and the work
/// of following it grows with them.
constexpr double kMaxTurns = 1000.0;
/// Twists a robot may list: a handful describe every bracket there is.
constexpr std::size_t kMaxTwists = 100;

// -------------------------------------------------------------- primitives

/// A primitive as read, with the end point the next one must start from
/// (formats.md: an arc's `end` as written, a helix's computed end).
struct ReadPrimitive {
    Primitive3 primitive;
    Vec3 end;
};

bool direction_ccw(const json& prim, const std::string& part, const char* why) {
    const std::string p = member(part, "direction");
    const std::string d = text(required(prim, part, "direction", why), p, "\"ccw\" or \"cw\"");
    if (d == "ccw") return true;
    if (d == "cw") return false;
    throw InputError(p, "expected \"ccw\" (right-handed about the normal) or \"cw\", got \"" +
                            text::printable(d) + "\"");
}

Vec3 required_point(const json& prim, const std::string& part, const char* key, const char* why) {
    return point3(required(prim, part, key, why), member(part, key));
}

Vec3 required_direction(const json& prim, const std::string& part, const char* key,
                        const char* why) {
    return direction3(required(prim, part, key, why), member(part, key));
}

/// The start off the axis through center: a turn needs a radius.
void require_off_axis(const Vec3& start, const Vec3& center, const Vec3& axis,
                      const std::string& part, const char* kind, const char* axis_key) {
    const Vec3 r0 = start - center;
    const double radius = (r0 - r0.dot(axis) * axis).norm();
    if (!(radius >= kDegenerate))
        throw InputError(part, std::string(kind) + " start " + point_text(start) +
                                   " lies on the line through center along " + axis_key +
                                   ", so its radius is 0");
}

/// |(x - center) . n| <= 1e-6 m (formats.md).
void require_in_plane(const Vec3& x, const Vec3& center, const Vec3& normal,
                      const std::string& part, const char* which) {
    const double off = std::abs((x - center).dot(normal));
    if (off > kJoinTolerance)
        throw InputError(member(part, "normal"), std::string("not perpendicular to ") + which +
                                                     " - center (" + metres(off) + " m)");
}

void check_radius_key(const json& prim, const std::string& part, double actual) {
    const json* r = optional(prim, "radius");
    if (!r) return;
    const std::string rp = member(part, "radius");
    const double radius = finite_number(*r, rp, "a radius in metres");
    if (std::abs(radius - actual) > kJoinTolerance)
        throw InputError(rp, "radius " + metres(radius) + " m disagrees with the distance " +
                                 metres(actual) + " m from start to center");
}

ReadPrimitive read_line(const json& prim, const std::string& part) {
    const char* why = "a line needs \"start\" and \"end\"";
    const Vec3 start = required_point(prim, part, "start", why);
    const Vec3 end = required_point(prim, part, "end", why);
    if (!((end - start).norm() >= kDegenerate))
        throw InputError(
            part, "line has zero length: start and end are the same point " + point_text(start));
    return {geometry::Line3{start, end}, end};
}

ReadPrimitive read_arc(const json& prim, const std::string& part) {
    const char* why = "an arc needs \"start\", \"end\", \"center\", \"normal\" and \"direction\"";
    const Vec3 start = required_point(prim, part, "start", why);
    const Vec3 end = required_point(prim, part, "end", why);
    const Vec3 center = required_point(prim, part, "center", why);
    const Vec3 given = required_direction(prim, part, "normal", why);
    const Vec3 normal = geometry::unit_vector(given);
    const bool ccw = direction_ccw(prim, part, why);
    require_in_plane(start, center, normal, part, "start");
    require_in_plane(end, center, normal, part, "end");
    require_off_axis(start, center, normal, part, "arc", "normal");
    const double gap = (end - center).norm() - (start - center).norm();
    if (std::abs(gap) > kJoinTolerance)
        throw InputError(part, "arc end is " + metres(std::abs(gap)) + " m " +
                                   (gap > 0 ? "farther from" : "closer to") +
                                   " center than start; both must lie on the same circle");
    check_radius_key(prim, part, (start - center).norm());
    geometry::Arc3 arc = geometry::make_arc3(start, end, center, given, ccw);
    if (!(arc.sweep * arc.turn.radius >= kDegenerate))
        throw InputError(part, "arc has zero length: its end " + point_text(end) +
                                   " lies at the start's angle about the normal");
    return {arc, end};
}

ReadPrimitive read_circle(const json& prim, const std::string& part) {
    const char* why = "a circle needs \"start\", \"center\", \"normal\" and \"direction\"";
    const Vec3 start = required_point(prim, part, "start", why);
    const Vec3 center = required_point(prim, part, "center", why);
    const Vec3 given = required_direction(prim, part, "normal", why);
    const Vec3 normal = geometry::unit_vector(given);
    const bool ccw = direction_ccw(prim, part, why);
    require_in_plane(start, center, normal, part, "start");
    require_off_axis(start, center, normal, part, "circle", "normal");
    check_radius_key(prim, part, (start - center).norm());
    return {geometry::Circle3{geometry::make_turn(start, center, given, ccw)}, start};
}

ReadPrimitive read_helix(const json& prim, const std::string& part) {
    const char* why =
        "a helix needs \"start\", \"center\", \"axis\", \"direction\", \"pitch\" and \"turns\"";
    const Vec3 start = required_point(prim, part, "start", why);
    const Vec3 center = required_point(prim, part, "center", why);
    const Vec3 given = required_direction(prim, part, "axis", why);
    const Vec3 axis = geometry::unit_vector(given);
    const bool ccw = direction_ccw(prim, part, why);
    const std::string pp = member(part, "pitch");
    const double pitch = finite_number(required(prim, part, "pitch", why), pp,
                                       "an advance along the axis per turn in metres");
    if (!(std::abs(pitch) >= kMinPitch))
        throw InputError(pp, "|pitch| must be at least " + metres(kMinPitch) +
                                 " m so that neighbouring turns stay apart, got " +
                                 text::compact(pitch) + " m");
    if (std::abs(pitch) > task::kMaxLength)
        throw InputError(pp, metres(pitch) + " m is more than the " +
                                 text::compact(task::kMaxLength) + " m allowed for a size");
    const std::string tp = member(part, "turns");
    const double turns = finite_number(required(prim, part, "turns", why), tp, "a number of turns");
    if (!(turns > 0.0)) throw InputError(tp, "must be greater than 0, got " + text::compact(turns));
    if (turns > kMaxTurns)
        throw InputError(tp, text::compact(turns) + " turns is more than the " +
                                 text::compact(kMaxTurns) + " allowed");
    const double level = (start - center).dot(axis);
    if (std::abs(level) > kJoinTolerance)
        throw InputError(member(part, "center"),
                         "not level with start along axis (" + metres(std::abs(level)) + " m)");
    require_off_axis(start, center, axis, part, "helix", "axis");
    check_radius_key(prim, part, (start - center).norm());
    const geometry::Helix3 helix = geometry::make_helix3(start, center, given, ccw, pitch, turns);
    // As a line's: a helix of a vanishing part of a turn (1e-12 of one, or
    // the least double) is no path to follow.
    if (!(geometry::length(geometry::Primitive3(helix)) >= kDegenerate))
        throw InputError(
            part, "helix has zero length: " + text::compact(turns) + " turns of it are " +
                      text::compact(geometry::length(geometry::Primitive3(helix))) + " m long");
    const Vec3 end = geometry::end_point(helix);
    for (int k = 0; k < 3; ++k)
        if (std::abs(end[k]) > task::kMaxCoordinate)
            throw InputError(part, "the helix ends at " + point_text(end) + ", beyond the " +
                                       text::compact(task::kMaxCoordinate) +
                                       " m from the origin allowed");
    if (const json* e = optional(prim, "end")) {
        const Vec3 given = point3(*e, member(part, "end"));
        const double gap = (given - end).norm();
        if (gap > kJoinTolerance)
            throw InputError(member(part, "end"),
                             "lies " + metres(gap) + " m from the helix's end " + point_text(end));
    }
    return {helix, end};
}

// ------------------------------------------------------------ tool axes

/// formats.md "Tool orientation": {"direction": [x, y, z]} or {"toward":
/// "axis" | "away"}, with an optional "tolerance" in (0, pi/2].
ToolAxis read_tool_axis(const json& j, const std::string& part) {
    require_object(j, part, "{\"direction\": [0, 0, -1], \"tolerance\": 0.05}");
    for (const auto& [key, value] : j.items())
        if (key != "direction" && key != "toward" && key != "tolerance")
            throw InputError(member(part, text::printable(key, 40).c_str()),
                             "unknown key; a tool axis takes \"direction\" or \"toward\", and "
                             "\"tolerance\"");
    const json* direction = optional(j, "direction");
    const json* toward = optional(j, "toward");
    if (direction && toward)
        throw InputError(part, "has both \"direction\" and \"toward\"; give one of them");
    if (!direction && !toward)
        throw InputError(part,
                         "needs \"direction\": [x, y, z] or \"toward\": \"axis\" or "
                         "\"away\"");
    ToolAxis a;
    if (direction) {
        a.direction = direction3(*direction, member(part, "direction"));
    } else {
        const std::string tp = member(part, "toward");
        const std::string t = text(*toward, tp, "\"axis\" or \"away\"");
        if (t == "axis")
            a.kind = ToolAxis::Kind::TowardAxis;
        else if (t == "away")
            a.kind = ToolAxis::Kind::AwayFromAxis;
        else
            throw InputError(tp,
                             "expected \"axis\" or \"away\", got \"" + text::printable(t) + "\"");
    }
    if (const json* tol = optional(j, "tolerance")) {
        const std::string tp = member(part, "tolerance");
        a.tolerance = finite_number(*tol, tp, "an angle in radians");
        if (!(a.tolerance > 0.0 && a.tolerance <= geometry::kPi / 2 + 1e-12))
            throw InputError(tp, "is " + text::compact(a.tolerance) +
                                     " rad; a tolerance lies in (0, pi/2], 1.5707963267948966");
        a.tolerance_given = true;
    }
    return a;
}

/// A tool pointing at the axis of primitive `prim` needs a turn with a
/// radius (`part` names the axis's document).
void check_toward(const ToolAxis& a, const Primitive3& prim, const std::string& part,
                  const std::string& primitive) {
    if (a.kind == ToolAxis::Kind::Direction) return;
    const auto axis = task::turn_axis(prim);
    if (!axis)
        throw InputError(member(part, "toward"),
                         primitive +
                             " is a line, which has no axis to point at; give "
                             "\"direction\"");
    const Vec3 r = geometry::start_point(prim) - axis->first;
    const double radius = (r - r.dot(axis->second) * axis->second).norm();
    if (radius < task::kLeastTowardRadius)
        throw InputError(member(part, "toward"), primitive + "'s radius " + metres(radius) +
                                                     " m is under the " +
                                                     metres(task::kLeastTowardRadius) +
                                                     " m a tool may point at its axis from");
}

ReadPrimitive read_primitive(const json& prim, const std::string& part) {
    require_object(prim, part, "{\"type\": \"line\", \"start\": [x, y, z], \"end\": [x, y, z]}");
    const char* kinds = "\"line\", \"arc\", \"circle\" or \"helix\"";
    const std::string why = std::string("expected ") + kinds;
    const std::string tp = member(part, "type");
    const std::string type = text(required(prim, part, "type", why.c_str()), tp, kinds);
    if (type == "line") return read_line(prim, part);
    if (type == "arc") return read_arc(prim, part);
    if (type == "circle") return read_circle(prim, part);
    if (type == "helix") return read_helix(prim, part);
    throw InputError(tp, "unknown primitive type \"" + text::printable(type) + "\"; " + why);
}

/// One list of connected primitives named `part`, appended to the task's,
/// with their tool axes.
void read_primitives(const json& list, const std::string& part, SpatialTask& task) {
    std::vector<Primitive3>& out = task.trajectory;
    Vec3 previous_end = Vec3::Zero();
    for (std::size_t j = 0; j < list.size(); ++j) {
        const std::string pj = element(part, j);
        ReadPrimitive r = read_primitive(list[j], pj);
        std::optional<ToolAxis> axis;
        if (const json* a = optional(list[j], "tool_axis")) {
            const std::string ap = member(pj, "tool_axis");
            axis = read_tool_axis(*a, ap);
            check_toward(*axis, r.primitive, ap, pj);
        }
        // Kept per primitive from the first one that has a tool axis on.
        if (axis || !task.tool_axes.empty()) {
            task.tool_axes.resize(out.size());
            task.tool_axes.push_back(std::move(axis));
        }
        if (j > 0) {
            const double gap = (geometry::start_point(r.primitive) - previous_end).norm();
            if (gap > kJoinTolerance)
                throw InputError(pj, "starts " + metres(gap) + " m from the end of " +
                                         element(part, j - 1) + " (it ends at " +
                                         point_text(previous_end) +
                                         "); consecutive primitives must connect");
        }
        previous_end = r.end;
        out.push_back(std::move(r.primitive));
    }
}

/// Exactly one of `trajectory` and `strokes` (formats.md "Several strokes").
void read_path(const json& doc, SpatialTask& task) {
    const json* trajectory = optional(doc, "trajectory");
    const json* strokes = optional(doc, "strokes");
    if (trajectory && strokes)
        throw InputError(
            "strokes", "a task holds either \"trajectory\" (one stroke) or \"strokes\", not both");
    if (!strokes) {
        const json& list = required(
            doc, "", "trajectory",
            "a task needs a list of primitives to follow (or \"strokes\", a list of such lists)");
        require_array(list, "trajectory", "primitives");
        if (list.empty())
            throw InputError("trajectory", "is empty; a task needs at least one primitive");
        require_count_cap(list, "trajectory", "primitives", task::kMaxPrimitives);
        read_primitives(list, "trajectory", task);
        return;
    }
    const std::string part = "strokes";
    require_array(*strokes, part, "strokes (each a list of primitives)");
    if (strokes->empty()) throw InputError(part, "is empty; a task needs at least one stroke");
    std::size_t total = 0;
    for (std::size_t s = 0; s < strokes->size(); ++s) {
        const std::string sp = element(part, s);
        require_array((*strokes)[s], sp, "primitives");
        if ((*strokes)[s].empty())
            throw InputError(sp, "is empty; every stroke needs at least one primitive");
        total += (*strokes)[s].size();
    }
    if (total > task::kMaxPrimitives)
        throw InputError(part, std::to_string(total) + " primitives, more than the " +
                                   std::to_string(task::kMaxPrimitives) + " allowed");
    for (std::size_t s = 0; s < strokes->size(); ++s) {
        task.stroke_starts.push_back(static_cast<int>(task.trajectory.size()));
        read_primitives((*strokes)[s], element(part, s), task);
    }
}

// --------------------------------------------------------------- obstacles

/// max above min on every axis (`strict`: boxes) or not below it (base
/// regions, which may be flat).
Box3 read_box(const json& j, const std::string& part, bool strict, const char* why) {
    Box3 b;
    b.min = point3(required(j, part, "min", why), member(part, "min"));
    b.max = point3(required(j, part, "max", why), member(part, "max"));
    const char* axes[3] = {"x", "y", "z"};
    for (int k = 0; k < 3; ++k) {
        if (b.max[k] < b.min[k])
            throw InputError(member(part, "max"), std::string("below min on ") + axes[k] + " (" +
                                                      metres(b.max[k]) + " m < " +
                                                      metres(b.min[k]) + " m)");
        if (strict && b.max[k] == b.min[k])
            throw InputError(member(part, "max"),
                             std::string("equal to min on ") + axes[k] +
                                 "; a box obstacle needs min < max on every axis");
    }
    return b;
}

Obstacle3 read_obstacle(const json& j, const std::string& part) {
    require_object(j, part, "{\"type\": \"sphere\", \"center\": [x, y, z], \"radius\": r}");
    std::string type;
    if (const json* t = optional(j, "type")) {
        type = text(*t, member(part, "type"), "\"sphere\", \"capsule\" or \"box\"");
    } else if (optional(j, "center") && optional(j, "radius")) {
        type = "sphere";
    } else {
        throw InputError(member(part, "type"),
                         "missing; an obstacle is a \"sphere\", a \"capsule\" or a \"box\"");
    }
    if (type == "sphere") {
        const char* why = "a sphere needs \"center\" and \"radius\"";
        return geometry::Sphere{
            point3(required(j, part, "center", why), member(part, "center")),
            positive_length(required(j, part, "radius", why), member(part, "radius"))};
    }
    if (type == "capsule") {
        const char* why = "a capsule needs \"a\", \"b\" and \"radius\"";
        return geometry::Capsule{
            point3(required(j, part, "a", why), member(part, "a")),
            point3(required(j, part, "b", why), member(part, "b")),
            positive_length(required(j, part, "radius", why), member(part, "radius"))};
    }
    if (type == "box") return read_box(j, part, true, "a box needs \"min\" and \"max\" corners");
    throw InputError(member(part, "type"), "unknown obstacle type \"" + text::printable(type) +
                                               "\"; expected \"sphere\", \"capsule\" or \"box\"");
}

template <class T, class Read>
std::vector<T> read_list(const json& doc, const char* key, const char* what, std::size_t cap,
                         Read read) {
    std::vector<T> out;
    const json* list = optional(doc, key);
    if (!list) return out;
    require_array(*list, key, what);
    require_count_cap(*list, key, what, cap);
    for (std::size_t i = 0; i < list->size(); ++i) out.push_back(read((*list)[i], element(key, i)));
    return out;
}

// ------------------------------------------------------------------- robot

std::vector<int> read_dof(const json& j, const std::string& part) {
    require_array(j, part, "joint counts, e.g. [3, 4]");
    if (j.empty()) throw InputError(part, "is empty; list at least one joint count, e.g. [3, 4]");
    require_count_cap(j, part, "joint counts", 10);
    std::vector<int> dof;
    for (std::size_t i = 0; i < j.size(); ++i) {
        const int n = whole_number(j[i], element(part, i), task::kMinSpatialDof,
                                   task::kMaxSpatialDof, "joints (a spatial chain has 3 to 6)");
        if (std::find(dof.begin(), dof.end(), n) != dof.end())
            throw InputError(element(part, i), std::to_string(n) + " is listed twice");
        dof.push_back(n);
    }
    std::sort(dof.begin(), dof.end());
    return dof;
}

std::vector<double> read_twists(const json& j, const std::string& part) {
    require_array(j, part, "DH twists in radians, e.g. [0, 1.5707963267948966]");
    if (j.empty()) throw InputError(part, "is empty; list at least one twist, e.g. [0]");
    require_count_cap(j, part, "twists", kMaxTwists);
    std::vector<double> out;
    for (std::size_t i = 0; i < j.size(); ++i)
        out.push_back(finite_number(j[i], element(part, i), "a twist in radians"));
    return out;
}

/// As in the plane (jerk included): one reader of the key for both.
void read_joint_limits(const json& robot, const std::string& robot_part, SpatialRobotSpec& r) {
    if (const json* limits = optional(robot, "joint_limits"))
        r.joint_limits = values::joint_limits(*limits, member(robot_part, "joint_limits"), r.dof);
}

void read_loads(const json& robot, const std::string& part, SpatialRobotSpec& r) {
    if (const json* v = optional(robot, "modules")) {
        const std::string p = member(part, "modules");
        require_array(*v, p, "module names, e.g. [\"X8-9\", \"X5-4\"]");
        if (v->empty())
            throw InputError(p, "is empty; list at least one module, or leave the key out");
        require_count_cap(*v, p, "modules", 100);
        for (std::size_t i = 0; i < v->size(); ++i) {
            const std::string name = text((*v)[i], element(p, i), "a module name (text)");
            if (name.empty()) throw InputError(element(p, i), "is empty; expected a module name");
            if (std::find(r.modules.begin(), r.modules.end(), name) != r.modules.end())
                throw InputError(element(p, i),
                                 "\"" + text::printable(name) + "\" is listed twice");
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
        if (!v->is_array() || v->size() != 3)
            throw InputError(
                p, "expected a vector [gx, gy, gz] in m/s^2 (z up), got " +
                       (v->is_array() ? "a list of " + std::to_string(v->size()) : describe(*v)));
        Vec3 g;
        for (std::size_t k = 0; k < 3; ++k)
            g[static_cast<int>(k)] =
                finite_number((*v)[k], element(p, k), "an acceleration in m/s^2");
        if (g.norm() > 100.0)
            throw InputError(p, "|g| = " + text::compact(g.norm()) +
                                    " m/s^2 is more than the 100 m/s^2 allowed");
        r.gravity = g;
    }
}

SpatialRobotSpec read_robot(const json& doc) {
    SpatialRobotSpec r;
    const json* robot = optional(doc, "robot");
    if (!robot) return r;
    const std::string part = "robot";
    require_object(*robot, part, "{\"dof\": [3, 4], \"max_link_length\": 1.0}");
    if (const json* v = optional(*robot, "dof")) r.dof = read_dof(*v, member(part, "dof"));
    if (const json* v = optional(*robot, "link_diameter"))
        r.link_diameter = positive_length(*v, member(part, "link_diameter"));
    if (const json* v = optional(*robot, "min_link_length"))
        r.min_link_length = non_negative_length(*v, member(part, "min_link_length"));
    if (const json* v = optional(*robot, "max_link_length"))
        r.max_link_length = positive_length(*v, member(part, "max_link_length"));
    if (const json* v = optional(*robot, "twists"))
        r.twists = read_twists(*v, member(part, "twists"));
    if (const json* v = optional(*robot, "tool_length"))
        r.tool_length = non_negative_length(*v, member(part, "tool_length"));
    if (optional(*robot, "joint_diameter"))
        throw InputError(member(part, "joint_diameter"), "joint bodies are not supported yet");
    const std::pair<const char*, double*> sizes[] = {{"module_length", &r.module_length},
                                                     {"module_width", &r.module_width},
                                                     {"module_height", &r.module_height},
                                                     {"adapter_length", &r.adapter_length},
                                                     {"ee_rod_diameter", &r.ee_rod_diameter}};
    for (const auto& [key, value] : sizes)
        if (const json* v = optional(*robot, key)) *value = positive_length(*v, member(part, key));
    read_loads(*robot, part, r);
    read_joint_limits(*robot, part, r);
    if (r.min_link_length > r.max_link_length)
        throw InputError(member(part, "min_link_length"),
                         "minimum link length " + metres(r.min_link_length) +
                             " m is larger than the maximum link length " +
                             metres(r.max_link_length) + " m");
    return r;
}

// ---------------------------------------------------------------- the rest

void check_format_and_space(const json& doc) {
    const json& f = required(doc, "", "format",
                             "a task document must start with \"format\": \"modsynth-task/1\"");
    if (!f.is_string() || f.get<std::string>() != kFormat)
        throw InputError("format", std::string("expected \"") + kFormat + "\", got " + describe(f) +
                                       "; this is not a task file modsynth can read");
    const json* space = optional(doc, "space");
    const std::string value = space ? text(*space, "space", "\"3d\"") : std::string("plane");
    if (value != "3d")
        throw InputError("space",
                         "expected \"3d\" for a spatial task, got " +
                             (space ? describe(*space) : std::string("none (a planar task)")));
}

/// A ball holding the whole primitive, for quick rejections.
geometry::Sphere bounding_ball(const Primitive3& p) {
    // Every point is within len / 2 (along the path) of the point halfway.
    const double len = geometry::length(p);
    return {geometry::point_at(p, 0.5 * len), 0.5 * len};
}

/// Nothing can trace a path that runs through an obstacle, whatever the
/// robot: the path must stay outside every obstacle (as in the plane). A
/// curve's pair with an obstacle may take tens of milliseconds (a helix of
/// a thousand turns round a post), so the deadline is asked before each.
void check_clearance(const SpatialTask& task, const run::Deadline& deadline) {
    std::vector<geometry::Sphere> balls;
    balls.reserve(task.trajectory.size());
    for (const Primitive3& p : task.trajectory) balls.push_back(bounding_ball(p));
    for (std::size_t i = 0; i < task.obstacles.size(); ++i) {
        const Obstacle3& o = task.obstacles[i];
        const geometry::Sphere around = geometry::bounding_sphere(o);
        const geometry::ObstacleCore core = geometry::core_of(o);
        const bool box = std::holds_alternative<Box3>(o);
        const geometry::ConvexDistance to_core = [&](const Vec3& x) {
            return std::visit(
                [&](const auto& shape) -> double {
                    using T = std::decay_t<decltype(shape)>;
                    if constexpr (std::is_same_v<T, geometry::Sphere>) {
                        return (x - shape.center).norm();
                    } else if constexpr (std::is_same_v<T, geometry::Capsule>) {
                        return geometry::point_segment(x, shape.a, shape.b);
                    } else {
                        // A new kind of obstacle fails the build here.
                        static_assert(std::is_same_v<T, Box3>);
                        return geometry::point_box(x, shape);
                    }
                },
                o);
        };
        for (std::size_t j = 0; j < task.trajectory.size(); ++j) {
            const Primitive3& p = task.trajectory[j];
            if ((balls[j].center - around.center).norm() > balls[j].radius + around.radius + 1e-9)
                continue;
            if (deadline.expired())
                throw CheckTimeout(task.name, "checking " +
                                                  task::part_name(task, static_cast<int>(j)) +
                                                  " against " + element("obstacles", i));
            // A line's distance to a core is exact; a curve's is decided by
            // the branch and bound of curve_distance.h.
            const auto* line = std::get_if<geometry::Line3>(&p);
            const double line_gap =
                line ? std::visit(
                           [&](const auto& shape) -> double {
                               using T = std::decay_t<decltype(shape)>;
                               if constexpr (std::is_same_v<T, geometry::Sphere>) {
                                   return geometry::point_segment(shape.center, line->start,
                                                                  line->end);
                               } else if constexpr (std::is_same_v<T, geometry::Capsule>) {
                                   return geometry::segment_segment(line->start, line->end, shape.a,
                                                                    shape.b);
                               } else {
                                   static_assert(std::is_same_v<T, Box3>);
                                   return geometry::segment_box(line->start, line->end, shape);
                               }
                           },
                           o)
                     : 0.0;
            if (line ? line_gap > core.radius : !geometry::comes_within(p, to_core, core.radius))
                continue;
            const double depth =
                core.radius -
                (line ? line_gap : geometry::least_distance(p, to_core, 1e-12).distance);
            throw InputError(
                element("obstacles", i),
                "touches " + task::part_name(task, static_cast<int>(j)) +
                    (box ? std::string(" (the path meets the box)")
                         : " (the path runs " + metres(std::max(depth, 0.0)) + " m inside it)") +
                    "; the path must stay outside every obstacle");
        }
    }
}

// ------------------------------------------------------------------ output

json point_json(const Vec3& p) { return json::array({p.x(), p.y(), p.z()}); }

json primitive_json(const Primitive3& prim) {
    return std::visit(
        [&](const auto& p) -> json {
            using T = std::decay_t<decltype(p)>;
            if constexpr (std::is_same_v<T, geometry::Line3>) {
                return {
                    {"type", "line"}, {"start", point_json(p.start)}, {"end", point_json(p.end)}};
            } else {
                const geometry::Turn& t = p.turn;
                const char* dir = t.ccw ? "ccw" : "cw";
                const Vec3 start = geometry::start_point(prim);
                if constexpr (std::is_same_v<T, geometry::Arc3>) {
                    return {{"type", "arc"},
                            {"start", point_json(start)},
                            {"end", point_json(p.end)},
                            {"center", point_json(t.center)},
                            {"normal", point_json(t.given_axis)},
                            {"direction", dir}};
                } else if constexpr (std::is_same_v<T, geometry::Circle3>) {
                    return {{"type", "circle"},
                            {"start", point_json(start)},
                            {"center", point_json(t.center)},
                            {"normal", point_json(t.given_axis)},
                            {"direction", dir},
                            {"radius", (start - t.center).norm()}};
                } else {
                    return {{"type", "helix"},
                            {"start", point_json(start)},
                            {"center", point_json(t.center)},
                            {"axis", point_json(t.given_axis)},
                            {"direction", dir},
                            {"pitch", p.pitch},
                            {"turns", p.turns},
                            {"end", point_json(geometry::end_point(prim))}};
                }
            }
        },
        prim);
}

json tool_axis_json(const ToolAxis& a) {
    json j;
    switch (a.kind) {
        case ToolAxis::Kind::Direction:
            j["direction"] = point_json(a.direction);
            break;
        case ToolAxis::Kind::TowardAxis:
            j["toward"] = "axis";
            break;
        case ToolAxis::Kind::AwayFromAxis:
            j["toward"] = "away";
            break;
    }
    if (a.tolerance_given) j["tolerance"] = a.tolerance;
    return j;
}

json obstacle_json(const Obstacle3& o) {
    return std::visit(
        [](const auto& x) -> json {
            using T = std::decay_t<decltype(x)>;
            if constexpr (std::is_same_v<T, geometry::Sphere>) {
                return {{"type", "sphere"}, {"center", point_json(x.center)}, {"radius", x.radius}};
            } else if constexpr (std::is_same_v<T, geometry::Capsule>) {
                return {{"type", "capsule"},
                        {"a", point_json(x.a)},
                        {"b", point_json(x.b)},
                        {"radius", x.radius}};
            } else {
                return {{"type", "box"}, {"min", point_json(x.min)}, {"max", point_json(x.max)}};
            }
        },
        o);
}

}  // namespace

SpatialTask parse_spatial_task(const json& doc, const run::Deadline& deadline) {
    if (!doc.is_object())
        throw InputError(kDocument,
                         "expected a JSON object {\"format\": \"modsynth-task/1\", \"space\": "
                         "\"3d\", ...}, got " +
                             describe(doc));
    check_format_and_space(doc);
    SpatialTask task;
    if (const json* name = optional(doc, "name")) task.name = text(*name, "name", "a name (text)");
    read_path(doc, task);
    if (!task.tool_axes.empty()) task.tool_axes.resize(task.trajectory.size());
    if (const json* a = optional(doc, "tool_axis")) {
        task.tool_axis = read_tool_axis(*a, "tool_axis");
        // It applies to every primitive without one of its own.
        for (int j = 0; j < static_cast<int>(task.trajectory.size()); ++j)
            if (task.tool_axes.empty() || !task.tool_axes[static_cast<std::size_t>(j)])
                check_toward(*task.tool_axis, task.trajectory[static_cast<std::size_t>(j)],
                             "tool_axis", task::part_name(task, j));
    }
    task.obstacles =
        read_list<Obstacle3>(doc, "obstacles", "obstacles", task::kMaxObstacles, read_obstacle);
    task.base_regions = read_list<Box3>(
        doc, "base_regions", "base regions", task::kMaxBaseRegions,
        [](const json& j, const std::string& part) {
            require_object(j, part, "{\"min\": [x, y, z], \"max\": [x, y, z]}");
            return read_box(j, part, false, "a base region needs \"min\" and \"max\" corners");
        });
    task.robot = read_robot(doc);
    check_clearance(task, deadline);
    return task;
}

SpatialTask parse_spatial_task_text(std::string_view text, const run::Deadline& deadline) {
    if (text.size() > task::kMaxTaskBytes)
        throw InputError(kDocument, std::to_string(text.size()) + " bytes, more than the " +
                                        std::to_string(task::kMaxTaskBytes) +
                                        " allowed for a task");
    return parse_spatial_task(parse_json_text(text), deadline);
}

SpatialTask load_spatial_task(const std::string& path, const run::Deadline& deadline) {
    SpatialTask task;
    try {
        task = read_document_file(path, [&](const std::string& p) {
            return parse_spatial_task_text(read_input_file(p, "task", task::kMaxTaskBytes),
                                           deadline);
        });
    } catch (const CheckTimeout& e) {
        if (!e.task_name().empty()) throw;
        throw CheckTimeout(std::filesystem::path(path).stem().string(), e.doing());
    }
    if (task.name.empty()) task.name = std::filesystem::path(path).stem().string();
    return task;
}

json to_json(const SpatialTask& task) {
    json trajectory = json::array(), strokes = json::array();
    for (int j = 0; j < static_cast<int>(task.trajectory.size()); ++j) {
        json prim = primitive_json(task.trajectory[static_cast<std::size_t>(j)]);
        if (!task.tool_axes.empty())
            if (const auto& a = task.tool_axes[static_cast<std::size_t>(j)])
                prim["tool_axis"] = tool_axis_json(*a);
        if (!task::has_strokes(task)) {
            trajectory.push_back(std::move(prim));
            continue;
        }
        if (j == task::stroke_first(task, task::stroke_of(task, j)))
            strokes.push_back(json::array());
        strokes.back().push_back(std::move(prim));
    }
    json obstacles = json::array();
    for (const Obstacle3& o : task.obstacles) obstacles.push_back(obstacle_json(o));
    json regions = json::array();
    for (const Box3& b : task.base_regions)
        regions.push_back({{"min", point_json(b.min)}, {"max", point_json(b.max)}});
    const SpatialRobotSpec& r = task.robot;
    json robot = {{"dof", r.dof},
                  {"link_diameter", r.link_diameter},
                  {"min_link_length", r.min_link_length},
                  {"max_link_length", r.max_link_length},
                  {"twists", r.twists},
                  {"tool_length", r.tool_length},
                  {"module_length", r.module_length},
                  {"module_width", r.module_width},
                  {"module_height", r.module_height},
                  {"adapter_length", r.adapter_length},
                  {"ee_rod_diameter", r.ee_rod_diameter}};
    if (const auto& l = r.joint_limits) robot["joint_limits"] = values::joint_limits_json(*l);
    if (!r.modules.empty()) robot["modules"] = r.modules;
    if (r.payload > 0.0) robot["payload"] = r.payload;
    if (r.gravity != SpatialRobotSpec{}.gravity) robot["gravity"] = point_json(r.gravity);
    json doc = {{"format", kFormat},      {"name", task.name},       {"space", "3d"},
                {"obstacles", obstacles}, {"base_regions", regions}, {"robot", robot}};
    if (task.tool_axis) doc["tool_axis"] = tool_axis_json(*task.tool_axis);
    if (task::has_strokes(task))
        doc["strokes"] = std::move(strokes);
    else
        doc["trajectory"] = std::move(trajectory);
    return doc;
}

}  // namespace modsynth::io
