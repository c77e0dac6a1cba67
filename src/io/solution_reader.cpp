#include <modsynth/io/solution_io.h>

#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include <modsynth/io/input.h>
#include <modsynth/kinematics/kinematics.h>
#include <modsynth/task/limits.h>
#include <modsynth/task/part.h>
#include <modsynth/task/spatial_strokes.h>
#include <modsynth/task/strokes.h>
#include <modsynth/text/printable.h>

#include "json_parts.h"

namespace modsynth::io {
namespace {

using nlohmann::json;
using task::InputError;

constexpr const char* kFormat = "modsynth-solution/1";

/// What the document holds instead of what was expected, in plain words.
std::string describe(const json& j) {
    if (j.is_array()) return "a list";
    if (j.is_object()) return "an object";
    if (j.is_null()) return "null";
    return text::printable(j.dump());
}

const json& required(const json& obj, const std::string& part, const char* key) {
    const auto it = obj.find(key);
    if (it == obj.end()) throw InputError(member(part, key), "missing");
    return *it;
}

void require_object(const json& j, const std::string& part) {
    if (!j.is_object()) throw InputError(part, "expected an object, got " + describe(j));
}

void require_array(const json& j, const std::string& part, const char* what) {
    if (!j.is_array()) {
        throw InputError(part, std::string("expected a list of ") + what + ", got " + describe(j));
    }
}

double finite_number(const json& j, const std::string& part) {
    if (!j.is_number() || !std::isfinite(j.get<double>())) {
        throw InputError(part, "expected a finite number, got " + describe(j));
    }
    return j.get<double>();
}

/// A number of at most `most` in magnitude: a robot's sizes and place lie
/// within the task's limits (task/limits.h), so that no message or output
/// prints hundreds of digits for one.
double within(const json& j, const std::string& part, double most, const char* unit) {
    const double v = finite_number(j, part);
    if (std::abs(v) > most)
        throw InputError(part, text::compact(v) + " " + unit + " is beyond the " +
                                   text::compact(most) + " " + unit + " allowed");
    return v;
}

double positive_number(const json& j, const std::string& part) {
    const double v = finite_number(j, part);
    if (v <= 0.0) throw InputError(part, "must be greater than 0, got " + describe(j));
    return v;
}

/// Certificate margins are null when nothing was there to check.
double number_or_infinity(const json& j, const std::string& part) {
    return j.is_null() ? std::numeric_limits<double>::infinity() : finite_number(j, part);
}

int integer(const json& j, const std::string& part, int min, int max) {
    if (!j.is_number_integer() || j.get<long long>() < min || j.get<long long>() > max) {
        throw InputError(part, "expected a whole number from " + std::to_string(min) + " to " +
                                   std::to_string(max) + ", got " + describe(j));
    }
    return j.get<int>();
}

std::string text(const json& j, const std::string& part) {
    if (!j.is_string()) throw InputError(part, "expected text, got " + describe(j));
    return j.get<std::string>();
}

/// A list of numbers, one per joint: `count` of them, or any number of
/// them when count is negative (a sample read before the robot: its count
/// is checked once the robot is known, check_joint_count).
std::vector<double> numbers(const json& j, const std::string& part, int count) {
    require_array(j, part, "numbers");
    if (count >= 0 && static_cast<int>(j.size()) != count) {
        throw InputError(part, "expected " + std::to_string(count) +
                                   " numbers (one per joint), got " + std::to_string(j.size()));
    }
    std::vector<double> out;
    out.reserve(j.size());
    for (std::size_t i = 0; i < j.size(); ++i) out.push_back(finite_number(j[i], element(part, i)));
    return out;
}

// ------------------------------------------------------------------- parts

synth::Status parse_status(const json& doc) {
    return synth::status_from_string(text(required(doc, "", "status"), "status"), "status");
}

geometry::Vec2 parse_point(const json& j, const std::string& part) {
    require_array(j, part, "2 numbers");
    if (j.size() != 2)
        throw InputError(part, "expected [x, y], got " + std::to_string(j.size()) + " numbers");
    return {finite_number(j[0], element(part, 0)), finite_number(j[1], element(part, 1))};
}

int index(const json& j, const std::string& part) {
    return integer(j, part, 0, std::numeric_limits<int>::max());
}

/// Reads each element of the array under `key` of `obj` with
/// read(element, its part name); `what` says what the array holds.
template <class Read>
void each_element(const json& obj, const std::string& part, const char* key, const char* what,
                  Read read) {
    const std::string p = member(part, key);
    const json& a = required(obj, part, key);
    require_array(a, p, what);
    for (std::size_t i = 0; i < a.size(); ++i) read(a[i], element(p, i));
}

/// The obstacle (or other) indices listed under `key` of `obj`.
std::vector<int> indices(const json& obj, const std::string& part, const char* key) {
    std::vector<int> out;
    each_element(obj, part, key, "obstacle indices",
                 [&](const json& x, const std::string& p) { out.push_back(index(x, p)); });
    return out;
}

prove::SeparationWitness parse_separation(const json& j, const std::string& part) {
    require_object(j, part);
    prove::SeparationWitness w;
    each_element(j, part, "walls", "walls", [&](const json& x, const std::string& p) {
        require_object(x, p);
        prove::Wall wall;
        wall.base_region = index(required(x, p, "base_region"), member(p, "base_region"));
        wall.primitive = index(required(x, p, "primitive"), member(p, "primitive"));
        wall.point = parse_point(required(x, p, "point"), member(p, "point"));
        wall.cycle = indices(x, p, "cycle");
        each_element(x, p, "overlaps", "numbers", [&](const json& o, const std::string& op) {
            wall.overlaps.push_back(finite_number(o, op));
        });
        if (wall.overlaps.size() != wall.cycle.size())
            throw InputError(member(p, "overlaps"),
                             "expected one overlap per obstacle of the cycle");
        w.walls.push_back(std::move(wall));
    });
    return w;
}

geometry::Vec3 parse_point3(const json& j, const std::string& part) {
    require_array(j, part, "3 numbers");
    if (j.size() != 3)
        throw InputError(part, "expected [x, y, z], got " + std::to_string(j.size()) + " numbers");
    return {finite_number(j[0], element(part, 0)), finite_number(j[1], element(part, 1)),
            finite_number(j[2], element(part, 2))};
}

prove::EnclosureWitness parse_enclosure(const json& j, const std::string& part) {
    require_object(j, part);
    prove::EnclosureWitness w;
    each_element(j, part, "walls", "walls", [&](const json& x, const std::string& p) {
        require_object(x, p);
        prove::Enclosure e;
        e.base_region = index(required(x, p, "base_region"), member(p, "base_region"));
        e.primitive = index(required(x, p, "primitive"), member(p, "primitive"));
        e.point = parse_point3(required(x, p, "point"), member(p, "point"));
        e.obstacles = indices(x, p, "obstacles");
        const std::string gp = member(p, "grid");
        const json& grid = required(x, p, "grid");
        require_object(grid, gp);
        e.grid.origin = parse_point3(required(grid, gp, "origin"), member(gp, "origin"));
        e.grid.cell = finite_number(required(grid, gp, "cell"), member(gp, "cell"));
        if (!(e.grid.cell > 0.0)) throw InputError(member(gp, "cell"), "expected a positive size");
        const std::string sp = member(gp, "size");
        const json& size = required(grid, gp, "size");
        require_array(size, sp, "3 whole numbers");
        if (size.size() != 3) throw InputError(sp, "expected 3 whole numbers");
        for (int a = 0; a < 3; ++a)
            e.grid.size[static_cast<std::size_t>(a)] =
                integer(size[static_cast<std::size_t>(a)], element(sp, a), 1, 1 << 20);
        const std::string inside = text(required(x, p, "inside"), member(p, "inside"));
        if (inside != "base_region" && inside != "point")
            throw InputError(member(p, "inside"), "expected \"base_region\" or \"point\"");
        e.base_inside = inside == "base_region";
        const std::string cp = member(p, "cells");
        const json& cells = required(x, p, "cells");
        require_array(cells, cp, "runs of cells");
        for (std::size_t i = 0; i < cells.size(); ++i) {
            const std::string rp = element(cp, i);
            require_array(cells[i], rp, "[j, k, i0, i1]");
            if (cells[i].size() != 4) throw InputError(rp, "expected [j, k, i0, i1]");
            e.cells.push_back(
                {index(cells[i][0], element(rp, 0)), index(cells[i][1], element(rp, 1)),
                 index(cells[i][2], element(rp, 2)), index(cells[i][3], element(rp, 3))});
        }
        w.walls.push_back(std::move(e));
    });
    return w;
}

prove::GeodesicWitness parse_geodesic(const json& j, const std::string& part) {
    require_object(j, part);
    prove::GeodesicWitness w;
    w.reach = finite_number(required(j, part, "reach"), member(part, "reach"));
    const std::string op = member(part, "obstacles");
    const json& obstacles = required(j, part, "obstacles");
    require_array(obstacles, op, "obstacle indices");
    for (std::size_t i = 0; i < obstacles.size(); ++i)
        w.obstacles.push_back(index(obstacles[i], element(op, i)));
    const std::string dp = member(part, "detours");
    const json& detours = required(j, part, "detours");
    require_array(detours, dp, "detours");
    for (std::size_t k = 0; k < detours.size(); ++k) {
        const std::string p = element(dp, k);
        const json& x = detours[k];
        require_object(x, p);
        prove::Detour d;
        d.base_region = index(required(x, p, "base_region"), member(p, "base_region"));
        d.primitive = index(required(x, p, "primitive"), member(p, "primitive"));
        d.point = parse_point(required(x, p, "point"), member(p, "point"));
        d.lower_bound = finite_number(required(x, p, "lower_bound"), member(p, "lower_bound"));
        const std::string rp = member(p, "route");
        const json& route = required(x, p, "route");
        require_array(route, rp, "steps");
        for (std::size_t i = 0; i < route.size(); ++i) {
            const std::string sp = element(rp, i);
            require_object(route[i], sp);
            prove::RouteStep s;
            s.point = parse_point(required(route[i], sp, "point"), member(sp, "point"));
            if (const json* a = optional(route[i], "around"))
                s.around = index(*a, member(sp, "around"));
            d.route.push_back(s);
        }
        w.detours.push_back(std::move(d));
    }
    return w;
}

synth::Explanation parse_explanation(const json& doc) {
    const std::string part = "explanation";
    const json& e = required(doc, "", "explanation");
    require_object(e, part);
    synth::Explanation out;
    out.message = text(required(e, part, "message"), member(part, "message"));
    if (const json* core = optional(e, "core")) {
        const std::string cp = member(part, "core");
        require_array(*core, cp, "task parts");
        for (std::size_t i = 0; i < core->size(); ++i) {
            const std::string at = element(cp, i);
            const std::string name = text((*core)[i], at);
            const auto part = task::parse_task_part(name);
            if (!part)
                throw task::InputError(at,
                                       "\"" + text::printable(name) + "\" names no part of a task");
            out.core.push_back(*part);
        }
    }
    if (const json* s = optional(e, "separation"))
        out.separation = parse_separation(*s, member(part, "separation"));
    if (const json* g = optional(e, "geodesic"))
        out.geodesic = parse_geodesic(*g, member(part, "geodesic"));
    if (const json* w = optional(e, "enclosure"))
        out.enclosure = parse_enclosure(*w, member(part, "enclosure"));
    return out;
}

int parse_elbow(const json& j, const std::string& part) {
    const int e = integer(j, part, -1, 1);
    if (e == 0) throw InputError(part, "expected +1 or -1, got 0");
    return e;
}

kinematics::Robot parse_robot(const json& doc) {
    const std::string part = "robot";
    const json& r = required(doc, "", "robot");
    require_object(r, part);
    kinematics::Robot robot;
    const int dof =
        integer(required(r, part, "dof"), member(part, "dof"), task::kMinDof, task::kMaxDof);
    const json& base = required(r, part, "base");
    const std::vector<double> b = numbers(base, member(part, "base"), 2);
    for (int k = 0; k < 2; ++k)
        within(base[static_cast<std::size_t>(k)], element(member(part, "base"), k),
               task::kMaxCoordinate, "m");
    robot.base = {b[0], b[1]};
    const std::string lp = member(part, "link_lengths");
    robot.link_lengths = numbers(required(r, part, "link_lengths"), lp, dof);
    for (int k = 0; k < dof; ++k) {
        positive_number(r["link_lengths"][k], element(lp, k));
        within(r["link_lengths"][k], element(lp, k), task::kMaxLength, "m");
    }
    robot.link_diameter =
        positive_number(required(r, part, "link_diameter"), member(part, "link_diameter"));
    within(r["link_diameter"], member(part, "link_diameter"), task::kMaxLength, "m");
    robot.elbow = 0;
    if (const json* e = optional(r, "elbow")) robot.elbow = parse_elbow(*e, member(part, "elbow"));
    return robot;
}

/// rad: a twist is an angle; a few turns either way hold every one.
constexpr double kLargestTwist = 100.0;

/// A spatial solution's robot (formats.md "Spatial tasks"): base [x, y, z]
/// and one DH row per joint.
kinematics::DhChain parse_dh_robot(const json& r) {
    const std::string part = "robot";
    kinematics::DhChain chain;
    const int dof = integer(required(r, part, "dof"), member(part, "dof"), task::kMinSpatialDof,
                            task::kMaxSpatialDof);
    const std::vector<double> b = numbers(required(r, part, "base"), member(part, "base"), 3);
    for (std::size_t k = 0; k < 3; ++k)
        within(r["base"][k], element(member(part, "base"), k), task::kMaxCoordinate, "m");
    chain.base = {b[0], b[1], b[2]};
    const std::string dp = member(part, "dh");
    const json& dh = required(r, part, "dh");
    require_array(dh, dp, "DH rows {\"a\", \"alpha\", \"d\"}");
    if (static_cast<int>(dh.size()) != dof)
        throw InputError(dp, "expected " + std::to_string(dof) + " rows (one per joint), got " +
                                 std::to_string(dh.size()));
    for (std::size_t k = 0; k < dh.size(); ++k) {
        const std::string rp = element(dp, k);
        require_object(dh[k], rp);
        kinematics::DhRow row;
        row.a = within(required(dh[k], rp, "a"), member(rp, "a"), task::kMaxLength, "m");
        row.alpha = within(required(dh[k], rp, "alpha"), member(rp, "alpha"), kLargestTwist, "rad");
        row.d = within(required(dh[k], rp, "d"), member(rp, "d"), task::kMaxLength, "m");
        chain.rows.push_back(row);
    }
    chain.link_diameter =
        positive_number(required(r, part, "link_diameter"), member(part, "link_diameter"));
    within(r["link_diameter"], member(part, "link_diameter"), task::kMaxLength, "m");
    return chain;
}

control::Phase parse_phase(const json& j, const std::string& part) {
    const std::string p = text(j, part);
    if (p == "trace") return control::Phase::Trace;
    if (p == "transition") return control::Phase::Transition;
    if (p == "travel") return control::Phase::Travel;
    throw InputError(part, "expected \"trace\", \"transition\" or \"travel\", got \"" +
                               text::printable(p) + "\"");
}

/// A sample with any number of joints (check_joint_count says whether
/// they are the robot's).
control::Sample parse_sample(const json& j, const std::string& part) {
    require_object(j, part);
    control::Sample s;
    s.t = finite_number(required(j, part, "t"), member(part, "t"));
    if (!(s.t >= 0.0 && s.t <= task::kLongestMotion)) {
        throw InputError(member(part, "t"), text::compact(s.t) +
                                                " s: a motion's times lie within 0 to " +
                                                text::compact(task::kLongestMotion) + " s");
    }
    s.phase = parse_phase(required(j, part, "phase"), member(part, "phase"));
    s.primitive = integer(required(j, part, "primitive"), member(part, "primitive"), 0,
                          std::numeric_limits<int>::max());
    s.q = numbers(required(j, part, "q"), member(part, "q"), -1);
    if (const json* k = optional(j, "stroke"))
        s.stroke = integer(*k, member(part, "stroke"), 0, std::numeric_limits<int>::max());
    if (const json* v = optional(j, "qd")) s.qd = numbers(*v, member(part, "qd"), -1);
    if (const json* v = optional(j, "qdd")) s.qdd = numbers(*v, member(part, "qdd"), -1);
    return s;
}

void require_like_first(const std::vector<double>& values, const std::vector<double>& first,
                        const std::string& part, const char* key) {
    if (values.empty() == first.empty()) return;
    throw InputError(member(part, key), values.empty()
                                            ? std::string("missing, but samples[0] has it; ") +
                                                  "give it on every sample or on none"
                                            : std::string("given, but samples[0] has none; ") +
                                                  "give it on every sample or on none");
}

/// The samples of a document, one at a time as the parser completes them:
/// a long motion's file is never held as a tree (about 1 KB per sample)
/// but as its samples. What is wrong with one is kept, not thrown, until
/// the document is known to be a solved one whose robot is valid: the
/// errors then come in the order of the document's checks.
class SampleReader {
public:
    /// The parser's callback: takes the elements of the document's
    /// top-level "samples" list out of the tree as they complete.
    bool on_event(int depth, json::parse_event_t event, json& parsed) {
        using E = json::parse_event_t;
        if (depth == 1 && event == E::key) {
            samples_key_ = parsed.is_string() && parsed.get_ref<const std::string&>() == "samples";
            return true;
        }
        if (depth == 1 && event == E::array_start && samples_key_) {
            // A later "samples" key wins, as in a tree.
            *this = SampleReader{};
            in_list_ = seen_ = true;
            return true;
        }
        if (depth == 1 && event == E::array_end && in_list_) {
            in_list_ = false;
            return true;
        }
        if (!in_list_ || depth != 2) return true;
        if (event == E::object_end || event == E::value || event == E::array_end) {
            add(parsed);
            return false;
        }
        return true;
    }

    /// One sample of the list, in order.
    void add(const json& j) {
        const std::size_t i = count_++;
        if (error_) return;
        try {
            const std::string part = element("samples", i);
            control::Sample s = parse_sample(j, part);
            if (i > 0 && s.t < samples_.back().t)
                throw InputError(member(part, "t"), "time goes backwards");
            // Velocities and accelerations are on every sample or on none.
            if (i > 0) {
                require_like_first(s.qd, samples_.front().qd, part, "qd");
                require_like_first(s.qdd, samples_.front().qdd, part, "qdd");
            }
            samples_.push_back(std::move(s));
        } catch (const InputError& e) {
            error_ = e;
            samples_.clear();
            samples_.shrink_to_fit();
        }
    }

    /// Whether a list of samples was taken out of the document.
    bool seen() const { return seen_; }

    /// The samples, each with `dof` joints; throws the first error found.
    std::vector<control::Sample> take(int dof) {
        if (error_) throw *error_;
        if (samples_.empty())
            throw InputError("samples", "is empty; a solved solution needs its motion");
        for (std::size_t i = 0; i < samples_.size(); ++i) {
            const std::string part = element("samples", i);
            const control::Sample& s = samples_[i];
            for (const auto& [values, key] :
                 {std::pair{&s.q, "q"}, std::pair{&s.qd, "qd"}, std::pair{&s.qdd, "qdd"}}) {
                if (values->empty() && key != std::string("q")) continue;
                if (static_cast<int>(values->size()) != dof)
                    throw InputError(member(part, key), "expected " + std::to_string(dof) +
                                                            " numbers (one per joint), got " +
                                                            std::to_string(values->size()));
            }
        }
        return std::move(samples_);
    }

private:
    std::vector<control::Sample> samples_;
    std::optional<InputError> error_;
    std::size_t count_ = 0;
    bool samples_key_ = false, in_list_ = false, seen_ = false;
};

/// The samples under "samples" of a document held as a tree.
std::vector<control::Sample> parse_samples(const json& doc, int dof) {
    const std::string part = "samples";
    const json& list = required(doc, "", "samples");
    require_array(list, part, "samples");
    SampleReader reader;
    for (const json& x : list) reader.add(x);
    return reader.take(dof);
}

verify::Certificate parse_certificate(const json& c) {
    const std::string part = "certificate";
    require_object(c, part);
    verify::Certificate out;
    out.ok = true;
    out.min_clearance = number_or_infinity(required(c, part, "min_clearance_margin"),
                                           member(part, "min_clearance_margin"));
    out.min_self_clearance = number_or_infinity(required(c, part, "min_self_collision_margin"),
                                                member(part, "min_self_collision_margin"));
    out.max_deviation =
        finite_number(required(c, part, "max_ee_deviation"), member(part, "max_ee_deviation"));
    if (const json* v = optional(c, "max_joint_step")) {
        out.max_joint_step = finite_number(*v, member(part, "max_joint_step"));
    }
    if (const json* v = optional(c, "min_tool_angle_margin"))
        out.min_tool_angle_margin = finite_number(*v, member(part, "min_tool_angle_margin"));
    return out;
}

/// Without an explicit elbow, the branch the motion is on: the sign of the
/// last joint's angle where the arm is not straight.
int elbow_from_samples(const std::vector<control::Sample>& samples) {
    for (const auto& s : samples) {
        const int e = kinematics::elbow_sign(s.q.back());
        if (e != 0) return e;
    }
    return 1;
}

void check_format(const json& doc) {
    const json& f = required(doc, "", "format");
    if (!f.is_string() || f.get<std::string>() != kFormat) {
        throw InputError("format", std::string("expected \"") + kFormat + "\", got " + describe(f) +
                                       "; this is not a solution file modsynth can read");
    }
}

/// The solution; its samples from `taken` when the parser took them out of
/// the document, else from the document.
ParsedSolution parse_solution_document(const json& doc, SampleReader* taken) {
    if (!doc.is_object()) {
        throw InputError(kDocument,
                         "expected a JSON object {\"format\": \"modsynth-solution/1\", "
                         "...}, got " +
                             describe(doc));
    }
    check_format(doc);
    ParsedSolution out;
    synth::Solution& s = out.solution;
    if (const json* name = optional(doc, "task")) s.task_name = text(*name, "task");
    s.status = parse_status(doc);
    if (s.status != synth::Status::Solved) {
        s.explanation = parse_explanation(doc);
        return out;
    }
    // A robot with `dh` is a spatial one (formats.md "Spatial tasks").
    const json* robot = optional(doc, "robot");
    const auto samples = [&](int dof) {
        return taken && taken->seen() ? taken->take(dof) : parse_samples(doc, dof);
    };
    if (robot && robot->is_object() && robot->contains("dh")) {
        s.dh_robot = parse_dh_robot(*robot);
        s.samples = samples(s.dh_robot->dof());
    } else {
        s.robot = parse_robot(doc);
        s.samples = samples(s.robot.dof());
        if (s.robot.elbow == 0) s.robot.elbow = elbow_from_samples(s.samples);
    }
    if (const json* c = optional(doc, "certificate")) {
        s.certificate = parse_certificate(*c);
        out.has_certificate = true;
    }
    return out;
}

}  // namespace

ParsedSolution parse_solution(const json& doc) { return parse_solution_document(doc, nullptr); }

ParsedSolution parse_solution_text(std::string_view text) {
    SampleReader reader;
    json doc;
    try {
        doc = json::parse(text.begin(), text.end(),
                          [&](int depth, json::parse_event_t event, json& parsed) {
                              return reader.on_event(depth, event, parsed);
                          });
    } catch (const json::exception&) {
        // The messages with their line and column.
        parse_json_text(text);
        throw;
    }
    return parse_solution_document(doc, &reader);
}

ParsedSolution load_solution(const std::string& path) {
    return read_document_file(path, [](const std::string& p) {
        // Read as it is parsed, its samples taken out as they complete:
        // memory is the motion's, not the file's text and tree.
        const InputFile file(p, "solution", task::kMaxSolutionBytes);
        SampleReader reader;
        const json doc =
            parse_json_file(file, [&](int depth, json::parse_event_t event, json& parsed) {
                return reader.on_event(depth, event, parsed);
            });
        return parse_solution_document(doc, &reader);
    });
}

void check_solution_fits(const task::Task& task, const synth::Solution& solution) {
    if (!solution.task_name.empty() && !task.name.empty() && solution.task_name != task.name) {
        throw InputError("task", "the solution is for task \"" + solution.task_name + "\", not \"" +
                                     task.name + "\"");
    }
    if (solution.dh_robot) throw InputError("robot.dh", "a spatial robot, but the task is planar");
    const int strokes = task::stroke_count(task);
    for (std::size_t i = 0; i < solution.samples.size(); ++i) {
        const control::Sample& x = solution.samples[i];
        if (x.stroke >= strokes) {
            throw InputError(member(element("samples", i), "stroke"),
                             "the task has only " + std::to_string(strokes) +
                                 (strokes == 1 ? " stroke" : " strokes"));
        }
        const int primitives =
            task::stroke_last(task, x.stroke) - task::stroke_first(task, x.stroke) + 1;
        if (x.primitive >= primitives) {
            throw InputError(
                member(element("samples", i), "primitive"),
                (task::has_strokes(task) ? "strokes[" + std::to_string(x.stroke) + "] has only "
                                         : std::string("the task has only ")) +
                    std::to_string(primitives) + " primitives");
        }
    }
}

void check_solution_fits(const task::SpatialTask& task, const synth::Solution& solution) {
    if (!solution.task_name.empty() && !task.name.empty() && solution.task_name != task.name)
        throw InputError("task", "the solution is for task \"" + solution.task_name + "\", not \"" +
                                     task.name + "\"");
    if (solution.status == synth::Status::Solved && !solution.dh_robot)
        throw InputError("robot",
                         "a planar robot (link_lengths), but the task is spatial; its "
                         "robot is {\"dof\", \"base\": [x, y, z], \"dh\": [...], "
                         "\"link_diameter\"}");
    const int strokes = task::stroke_count(task);
    for (std::size_t i = 0; i < solution.samples.size(); ++i) {
        const control::Sample& x = solution.samples[i];
        if (x.stroke >= strokes)
            throw InputError(member(element("samples", i), "stroke"),
                             "the task has only " + std::to_string(strokes) +
                                 (strokes == 1 ? " stroke" : " strokes"));
        const int primitives =
            task::stroke_last(task, x.stroke) - task::stroke_first(task, x.stroke) + 1;
        if (x.primitive >= primitives)
            throw InputError(
                member(element("samples", i), "primitive"),
                (task::has_strokes(task) ? "strokes[" + std::to_string(x.stroke) + "] has only "
                                         : std::string("the task has only ")) +
                    std::to_string(primitives) + " primitives");
    }
}

}  // namespace modsynth::io
