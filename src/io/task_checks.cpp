#include <modsynth/io/task_checks.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

#include <nlohmann/json.hpp>

#include <modsynth/text/format.h>

namespace modsynth::io {

using nlohmann::json;
using task::InputError;

namespace {

// The keys of formats.md (and docs/formats.md's additions), by where they
// may stand. Primitives and obstacles of both kinds of task share a list:
// a key of the other kind is refused by the reader itself.
const std::vector<std::string> kTopKeys = {"format",     "name",     "description", "space",
                                           "trajectory", "strokes",  "obstacles",   "base_regions",
                                           "robot",      "tool_axis"};
const std::vector<std::string> kPrimitiveKeys = {"type",      "start",  "end",      "center",
                                                 "direction", "radius", "normal",   "axis",
                                                 "pitch",     "turns",  "tool_axis"};
const std::vector<std::string> kObstacleKeys = {"type", "center", "radius", "a", "b", "min", "max"};
const std::vector<std::string> kRegionKeys = {"min", "max"};
const std::vector<std::string> kRobotKeys = {
    "dof",           "link_diameter", "min_link_length", "max_link_length", "module_length",
    "module_width",  "module_height", "adapter_length",  "ee_rod_diameter", "joint_limits",
    "modules",       "payload",       "gravity",         "twists",          "tool_length",
    "joint_diameter"};
const std::vector<std::string> kJointLimitKeys = {"velocity", "acceleration", "jerk"};
const std::vector<std::string> kToolAxisKeys = {"direction", "toward", "tolerance"};

/// A point more than this far from the origin, or a link bound over the
/// other, is most likely in millimetres.
constexpr double kFarPoint = 20.0;
constexpr double kLongLink = 10.0;

std::size_t edit_distance(std::string_view a, std::string_view b) {
    // Optimal string alignment: insertions, deletions, substitutions and
    // swaps of neighbours, each 1.
    const std::size_t n = a.size(), m = b.size();
    std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1));
    for (std::size_t i = 0; i <= n; ++i) d[i][0] = i;
    for (std::size_t j = 0; j <= m; ++j) d[0][j] = j;
    for (std::size_t i = 1; i <= n; ++i) {
        for (std::size_t j = 1; j <= m; ++j) {
            const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    }
    return d[n][m];
}

std::string lower(std::string_view s) {
    std::string out(s);
    for (char& c : out)
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    return out;
}

/// A key as a person may see it in a message: printable, not too long.
std::string shown(const std::string& key) {
    std::string out;
    for (unsigned char c : key) {
        if (out.size() > 60) return out + "...";
        if (c < 0x20 || c == 0x7f)
            out += text::format("\\x%02X", c);
        else
            out += static_cast<char>(c);
    }
    return out;
}

void check_keys(const json& object, const std::string& part, const std::vector<std::string>& known,
                const char* what, std::vector<InputError>& out) {
    if (!object.is_object()) return;
    for (const auto& [key, value] : object.items()) {
        if (std::find(known.begin(), known.end(), key) != known.end()) continue;
        const std::string where = part.empty() ? shown(key) : part + "." + shown(key);
        const std::string near = nearest_word(key, known);
        out.emplace_back(where, std::string("not a key of ") + what +
                                    (near.empty() ? " (docs/formats.md lists the keys)"
                                                  : "; did you mean \"" + near + "\"?"));
    }
}

void check_list(const json& doc, const std::string& key, const std::vector<std::string>& known,
                const char* what, std::vector<InputError>& out) {
    const auto it = doc.find(key);
    if (it == doc.end() || !it->is_array()) return;
    for (std::size_t i = 0; i < it->size(); ++i)
        check_keys((*it)[i], key + "[" + std::to_string(i) + "]", known, what, out);
}

void check_primitive(const json& p, const std::string& part, std::vector<InputError>& out) {
    check_keys(p, part, kPrimitiveKeys, "a primitive", out);
    if (p.is_object())
        if (const auto axis = p.find("tool_axis"); axis != p.end())
            check_keys(*axis, part + ".tool_axis", kToolAxisKeys, "tool_axis", out);
}

/// A point's distance from the origin, when `v` is a point.
double distance_of(const json& v) {
    if (!v.is_array() || v.size() < 2 || v.size() > 3) return 0.0;
    double sum = 0.0;
    for (const json& x : v) {
        if (!x.is_number()) return 0.0;
        const double c = x.get<double>();
        sum += c * c;
    }
    return std::sqrt(sum);
}

/// The farthest point among `keys` of every item of a list, and how many
/// points lie beyond kFarPoint.
struct Far {
    std::string part;
    double distance = 0.0;
    int count = 0;
    void see(const std::string& where, double d) {
        if (!(d > kFarPoint)) return;
        ++count;
        if (d > distance) {
            distance = d;
            part = where;
        }
    }
};

void far_points(const json& items, const std::string& name, const std::vector<std::string>& keys,
                Far& far) {
    if (!items.is_array()) return;
    for (std::size_t i = 0; i < items.size(); ++i) {
        const json& item = items[i];
        if (!item.is_object()) continue;
        const std::string part = name + "[" + std::to_string(i) + "]";
        for (const std::string& k : keys)
            if (const auto v = item.find(k); v != item.end())
                far.see(part + "." + k, distance_of(*v));
    }
}

std::string far_message(const Far& far, const char* what) {
    return text::format("%.3f m from the origin", far.distance) +
           (far.count > 1 ? text::format(" (%d points of the %s lie beyond %.0f m)", far.count,
                                         what, kFarPoint)
                          : std::string()) +
           ": lengths are in metres; is the task in millimetres? (then every length is 1000 "
           "times too large)";
}

}  // namespace

std::string nearest_word(std::string_view word, const std::vector<std::string>& known) {
    const std::string w = lower(word);
    std::string best;
    std::size_t best_distance = 0;
    for (const std::string& k : known) {
        const std::size_t d = edit_distance(w, k);
        if (best.empty() || d < best_distance) {
            best = k;
            best_distance = d;
        }
    }
    // A slip: a letter or two for a short key, a third of a long one.
    const std::size_t allowed = std::max<std::size_t>(2, best.size() / 3);
    return !best.empty() && best_distance <= allowed ? best : std::string();
}

std::vector<InputError> unknown_keys(const json& doc) {
    std::vector<InputError> out;
    if (!doc.is_object()) return out;
    check_keys(doc, "", kTopKeys, "a task", out);
    if (const auto t = doc.find("trajectory"); t != doc.end() && t->is_array())
        for (std::size_t j = 0; j < t->size(); ++j)
            check_primitive((*t)[j], "trajectory[" + std::to_string(j) + "]", out);
    if (const auto s = doc.find("strokes"); s != doc.end() && s->is_array())
        for (std::size_t i = 0; i < s->size(); ++i)
            if ((*s)[i].is_array())
                for (std::size_t j = 0; j < (*s)[i].size(); ++j)
                    check_primitive((*s)[i][j],
                                    "strokes[" + std::to_string(i) + "][" + std::to_string(j) + "]",
                                    out);
    check_list(doc, "obstacles", kObstacleKeys, "an obstacle", out);
    check_list(doc, "base_regions", kRegionKeys, "a base region", out);
    if (const auto axis = doc.find("tool_axis"); axis != doc.end())
        check_keys(*axis, "tool_axis", kToolAxisKeys, "tool_axis", out);
    if (const auto robot = doc.find("robot"); robot != doc.end() && robot->is_object()) {
        check_keys(*robot, "robot", kRobotKeys, "robot", out);
        if (const auto l = robot->find("joint_limits"); l != robot->end())
            check_keys(*l, "robot.joint_limits", kJointLimitKeys, "robot.joint_limits", out);
    }
    return out;
}

std::vector<InputError> unit_warnings(const json& doc) {
    std::vector<InputError> out;
    if (!doc.is_object()) return out;
    const std::vector<std::string> path_keys = {"start", "end", "center"};
    Far path;
    if (const auto t = doc.find("trajectory"); t != doc.end())
        far_points(*t, "trajectory", path_keys, path);
    if (const auto s = doc.find("strokes"); s != doc.end() && s->is_array())
        for (std::size_t i = 0; i < s->size(); ++i)
            far_points((*s)[i], "strokes[" + std::to_string(i) + "]", path_keys, path);
    if (path.count) out.emplace_back(path.part, far_message(path, "path"));
    Far obstacles;
    if (const auto o = doc.find("obstacles"); o != doc.end())
        far_points(*o, "obstacles", {"center", "a", "b", "min", "max"}, obstacles);
    if (obstacles.count) out.emplace_back(obstacles.part, far_message(obstacles, "obstacles"));
    Far regions;
    if (const auto b = doc.find("base_regions"); b != doc.end())
        far_points(*b, "base_regions", {"min", "max"}, regions);
    if (regions.count) out.emplace_back(regions.part, far_message(regions, "base regions"));
    if (const auto robot = doc.find("robot"); robot != doc.end() && robot->is_object()) {
        for (const char* key : {"max_link_length", "min_link_length"}) {
            const auto v = robot->find(key);
            if (v == robot->end() || !v->is_number() || !(v->get<double>() > kLongLink)) continue;
            out.emplace_back(
                std::string("robot.") + key,
                text::format("%g m, longer than any link of a buildable arm", v->get<double>()) +
                    ": lengths are in metres; is the task in millimetres? (then every "
                    "length is 1000 times too large)");
            break;
        }
    }
    return out;
}

std::vector<InputError> task_warnings(const json& doc) {
    std::vector<InputError> out = unknown_keys(doc);
    for (InputError& w : unit_warnings(doc)) out.push_back(std::move(w));
    return out;
}

}  // namespace modsynth::io
