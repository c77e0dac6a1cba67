#include "json_values.h"

#include <algorithm>
#include <cmath>

#include <modsynth/task/limits.h>
#include <modsynth/task/task.h>
#include <modsynth/text/format.h>
#include <modsynth/text/printable.h>

#include "json_parts.h"

namespace modsynth::io::values {

using nlohmann::json;
using task::InputError;

std::string metres(double value) {
    if (!std::isfinite(value) || std::fabs(value) >= 1e6) return text::compact(value);
    int decimals = 3;
    while (decimals < 12 && value != 0.0 && std::fabs(value) < 0.5 * std::pow(10.0, -decimals))
        ++decimals;
    return text::format("%.*f", decimals, value);
}

std::string point_text(const geometry::Vec3& p) {
    return "[" + metres(p.x()) + ", " + metres(p.y()) + ", " + metres(p.z()) + "]";
}

std::string describe(const json& j) {
    switch (j.type()) {
        case json::value_t::null:
            return "null";
        case json::value_t::boolean:
            return j.get<bool>() ? "true" : "false";
        case json::value_t::string:
            return "the text \"" + text::printable(j.get<std::string>()) + "\"";
        case json::value_t::array:
            return "a list";
        case json::value_t::object:
            return "an object";
        case json::value_t::number_float: {
            const double v = j.get<double>();
            if (std::isnan(v)) return "NaN";
            return text::compact(v);
        }
        default:
            return j.dump();
    }
}

void require_object(const json& j, const std::string& part, const char* example) {
    if (!j.is_object())
        throw InputError(
            part, std::string("expected an object like ") + example + ", got " + describe(j));
}

void require_array(const json& j, const std::string& part, const char* what) {
    if (!j.is_array())
        throw InputError(part, std::string("expected a list of ") + what + ", got " + describe(j));
}

void require_count_cap(const json& list, const std::string& part, const char* what,
                       std::size_t cap) {
    if (list.size() > cap)
        throw InputError(part, std::to_string(list.size()) + " " + what + ", more than the " +
                                   std::to_string(cap) + " allowed");
}

const json& required(const json& obj, const std::string& part, const char* key, const char* why) {
    const auto it = obj.find(key);
    if (it == obj.end())
        throw InputError(part.empty() ? std::string(key) : part + "." + key,
                         std::string("missing; ") + why);
    return *it;
}

double finite_number(const json& j, const std::string& part, const char* what) {
    if (!j.is_number())
        throw InputError(part, std::string("expected ") + what + " (a number), got " + describe(j));
    const double v = j.get<double>();
    if (!std::isfinite(v))
        throw InputError(
            part, std::string("expected ") + what + " (a finite number), got " + describe(j));
    return v;
}

namespace {

void require_size_cap(double v, const std::string& part) {
    if (v > task::kMaxLength)
        throw InputError(part, metres(v) + " m is more than the " +
                                   text::compact(task::kMaxLength) + " m allowed for a size");
}

}  // namespace

double positive_length(const json& j, const std::string& part) {
    const double v = finite_number(j, part, "a length in metres");
    if (v <= 0.0) throw InputError(part, "must be greater than 0 m, got " + metres(v) + " m");
    require_size_cap(v, part);
    return v;
}

double non_negative_length(const json& j, const std::string& part) {
    const double v = finite_number(j, part, "a length in metres");
    if (v < 0.0) throw InputError(part, "must not be negative, got " + metres(v) + " m");
    require_size_cap(v, part);
    return v;
}

std::string text(const json& j, const std::string& part, const char* what) {
    if (!j.is_string())
        throw InputError(part, std::string("expected ") + what + ", got " + describe(j));
    return j.get<std::string>();
}

task::JointLimitsSpec joint_limits(const json& limits, const std::string& part,
                                   std::vector<int>& dof) {
    require_object(limits, part, "{\"velocity\": 3.35, \"acceleration\": 10}");
    const char* why = "joint limits need \"velocity\" (rad/s) and \"acceleration\" (rad/s^2)";
    task::JointLimitsSpec spec;
    spec.velocity = joint_limit_values(required(limits, part, "velocity", why),
                                       member(part, "velocity"), "rad/s", dof);
    spec.acceleration = joint_limit_values(required(limits, part, "acceleration", why),
                                           member(part, "acceleration"), "rad/s^2", dof);
    const std::size_t nv = spec.velocity.size(), na = spec.acceleration.size();
    if (nv > 1 && na > 1 && nv != na) {
        throw InputError(member(part, "acceleration"),
                         "has " + std::to_string(na) + " values but velocity has " +
                             std::to_string(nv) + "; both lists need one value per joint");
    }
    if (const json* jerk = optional(limits, "jerk")) {
        spec.jerk = joint_limit_values(*jerk, member(part, "jerk"), "rad/s^3", dof);
        const std::size_t nj = spec.jerk.size(), other = std::max(nv, na);
        if (nj > 1 && other > 1 && nj != other) {
            throw InputError(member(part, "jerk"), "has " + std::to_string(nj) + " values but " +
                                                       (nv > 1 ? "velocity" : "acceleration") +
                                                       " has " + std::to_string(other) +
                                                       "; every list needs one value per joint");
        }
    }
    const std::size_t per_joint = std::max({nv, na, spec.jerk.size()});
    if (per_joint > 1) dof = {static_cast<int>(per_joint)};
    return spec;
}

json joint_limits_json(const task::JointLimitsSpec& limits) {
    // One value for every joint is written as a number, as it was read.
    const auto values = [](const std::vector<double>& v) {
        return v.size() == 1 ? json(v[0]) : json(v);
    };
    json out = {{"velocity", values(limits.velocity)},
                {"acceleration", values(limits.acceleration)}};
    if (!limits.jerk.empty()) out["jerk"] = values(limits.jerk);
    return out;
}

int whole_number(const json& j, const std::string& part, int lo, int hi, const char* what) {
    const bool integral =
        j.is_number_integer() || (j.is_number_float() && std::isfinite(j.get<double>()) &&
                                  j.get<double>() == std::floor(j.get<double>()));
    if (!integral)
        throw InputError(
            part, std::string("expected a whole number of ") + what + ", got " + describe(j));
    const double v = j.get<double>();
    if (v < lo || v > hi)
        throw InputError(part, describe(j) + " " + what + " is not supported; expected " +
                                   std::to_string(lo) + " to " + std::to_string(hi));
    return static_cast<int>(v);
}

namespace {

geometry::Vec3 three_numbers(const json& j, const std::string& part, const char* form) {
    if (!j.is_array())
        throw InputError(part, std::string("expected ") + form + ", got " + describe(j));
    if (j.size() != 3)
        throw InputError(part, std::string("expected ") + form + " with 3 numbers, got a list of " +
                                   std::to_string(j.size()));
    const char* names[3] = {"x", "y", "z"};
    geometry::Vec3 p;
    for (int k = 0; k < 3; ++k) {
        const json& c = j[static_cast<std::size_t>(k)];
        if (!c.is_number() || !std::isfinite(c.get<double>()))
            throw InputError(part, std::string("the ") + names[k] +
                                       " coordinate must be a finite number, got " + describe(c));
        p[k] = c.get<double>();
    }
    return p;
}

}  // namespace

geometry::Vec3 point3(const json& j, const std::string& part) {
    const geometry::Vec3 p = three_numbers(j, part, "a point [x, y, z]");
    const char* names[3] = {"x", "y", "z"};
    for (int k = 0; k < 3; ++k) {
        if (std::fabs(p[k]) > task::kMaxCoordinate)
            throw InputError(part, std::string("the ") + names[k] + " coordinate " + metres(p[k]) +
                                       " m is beyond the " + text::compact(task::kMaxCoordinate) +
                                       " m from the origin allowed");
    }
    return p;
}

geometry::Vec3 direction3(const json& j, const std::string& part) {
    const geometry::Vec3 v = three_numbers(j, part, "a direction [x, y, z]");
    if (!(v.cwiseAbs().maxCoeff() > 0.0))
        throw InputError(part, "must be a non-zero vector, got [0, 0, 0]");
    return v;
}

std::vector<double> joint_limit_values(const json& j, const std::string& part, const char* unit,
                                       const std::vector<int>& dof) {
    const auto value = [&](const json& v, const std::string& p) {
        const double x = finite_number(v, p, (std::string("a limit in ") + unit).c_str());
        if (x <= 0.0)
            throw InputError(
                p, "must be greater than 0 " + std::string(unit) + ", got " + text::compact(x));
        if (x < task::kMinJointLimit || x > task::kMaxJointLimit)
            throw InputError(p, text::compact(x) + " " + unit + " is outside the " +
                                    text::compact(task::kMinJointLimit) + " to " +
                                    text::compact(task::kMaxJointLimit) + " allowed");
        return x;
    };
    if (!j.is_array()) return {value(j, part)};
    if (std::find(dof.begin(), dof.end(), static_cast<int>(j.size())) == dof.end()) {
        std::string allowed;
        for (int n : dof) allowed += (allowed.empty() ? "" : " or ") + std::to_string(n);
        throw InputError(part, "has " + std::to_string(j.size()) +
                                   " values, but a list needs one per joint and the robot may "
                                   "have " +
                                   allowed + " joints (robot.dof)");
    }
    std::vector<double> out;
    for (std::size_t i = 0; i < j.size(); ++i) out.push_back(value(j[i], element(part, i)));
    return out;
}

}  // namespace modsynth::io::values
