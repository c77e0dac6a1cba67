#pragma once
// Naming the parts of a document in messages, shared by its readers: the
// JSON path of the offending part ("trajectory[1].center") is what a user
// needs to find it.
#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

namespace modsynth::io {

/// The part a message names when the whole document is at fault.
inline constexpr const char* kDocument = "(document)";

inline std::string member(const std::string& part, const char* key) {
    return part.empty() ? std::string(key) : part + "." + key;
}

inline std::string element(const std::string& part, std::size_t i) {
    return part + "[" + std::to_string(i) + "]";
}

/// The value of an optional key, or nullptr.
inline const nlohmann::json* optional(const nlohmann::json& obj, const char* key) {
    const auto it = obj.find(key);
    return it == obj.end() ? nullptr : &*it;
}

}  // namespace modsynth::io
