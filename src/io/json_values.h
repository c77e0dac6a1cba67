#pragma once
// Reading the values of a task document with messages that name the part
// and say what was expected instead of what was found ("a length in metres
// (a number), got the text \"abc\""), for both task readers.
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <modsynth/geometry/vec3.h>
#include <modsynth/task/input_error.h>
#include <modsynth/task/task.h>

namespace modsynth::io::values {

/// A length for a message: 3 decimals, or as many as a tiny non-zero value
/// needs, so that a rejected 2e-6 m gap does not read "0.000 m".
std::string metres(double value);
std::string point_text(const geometry::Vec3& p);
/// What the document holds instead of what was expected, in plain words.
std::string describe(const nlohmann::json& j);

void require_object(const nlohmann::json& j, const std::string& part, const char* example);
void require_array(const nlohmann::json& j, const std::string& part, const char* what);
/// More than `cap` elements in a list is refused before any is read.
void require_count_cap(const nlohmann::json& list, const std::string& part, const char* what,
                       std::size_t cap);
/// The value of a key that must be present; `why` says what needs it.
const nlohmann::json& required(const nlohmann::json& obj, const std::string& part, const char* key,
                               const char* why);

/// A finite number; `what` names it in the message ("a length in metres").
double finite_number(const nlohmann::json& j, const std::string& part, const char* what);
/// Lengths: finite, at most task::kMaxLength.
double positive_length(const nlohmann::json& j, const std::string& part);
double non_negative_length(const nlohmann::json& j, const std::string& part);
std::string text(const nlohmann::json& j, const std::string& part, const char* what);
/// One joint limit (`unit`: "rad/s", ...): a positive number for every
/// joint, or a list with one per joint whose length is an allowed joint
/// count (`dof`).
std::vector<double> joint_limit_values(const nlohmann::json& j, const std::string& part,
                                       const char* unit, const std::vector<int>& dof);
/// `robot.joint_limits` (formats.md "Joint limits and timing"), the same in
/// the plane and in space: velocity, acceleration and optional jerk, each a
/// number or a list per joint (lists of one length). `dof` is narrowed to a
/// list's length.
task::JointLimitsSpec joint_limits(const nlohmann::json& limits, const std::string& part,
                                   std::vector<int>& dof);
/// The limits as the readers take them: one value for every joint written
/// as a number.
nlohmann::json joint_limits_json(const task::JointLimitsSpec& limits);

/// A whole number of joints from lo to hi.
int whole_number(const nlohmann::json& j, const std::string& part, int lo, int hi,
                 const char* what);

/// [x, y, z] within task::kMaxCoordinate of the origin.
geometry::Vec3 point3(const nlohmann::json& j, const std::string& part);
/// A non-zero vector [x, y, z] of any finite length, as given.
geometry::Vec3 direction3(const nlohmann::json& j, const std::string& part);

}  // namespace modsynth::io::values
