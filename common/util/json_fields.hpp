#pragma once
// Optional fields of the agents' JSON answers: written only when set, read only when present.
// nlohmann::json (Debian's 3.11) has no std::optional conversion of its own.
#include <optional>

#include <nlohmann/json.hpp>

namespace chatsim::util {

template <typename T>
void put_optional(nlohmann::json& j, const char* key, const std::optional<T>& value) {
  if (value) j[key] = *value;
}

template <typename T>
void get_optional(const nlohmann::json& j, const char* key, std::optional<T>& value) {
  if (j.contains(key)) value = j[key].get<T>();
}

}  // namespace chatsim::util
