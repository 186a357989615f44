// A small JSON Schema subset validator: Debian has no C++ JSON-schema package, and the agents'
// output schemas use only these keywords.
#include "agents/llm/llm_backend.hpp"

namespace chatsim::agents::llm {
namespace {

bool type_ok(const nlohmann::json& v, const std::string& type) {
  if (type == "object") return v.is_object();
  if (type == "array") return v.is_array();
  if (type == "string") return v.is_string();
  if (type == "number") return v.is_number();
  if (type == "integer") return v.is_number_integer();
  if (type == "boolean") return v.is_boolean();
  if (type == "null") return v.is_null();
  return true;
}

}  // namespace

std::string validate(const nlohmann::json& v, const nlohmann::json& schema, const std::string& path) {
  if (schema.contains("type")) {
    const auto& t = schema["type"];
    bool ok = false;
    if (t.is_string()) ok = type_ok(v, t.get<std::string>());
    else
      for (const auto& one : t) ok = ok || type_ok(v, one.get<std::string>());
    if (!ok) return path + ": expected " + t.dump() + ", found " + v.type_name();
  }
  if (schema.contains("enum")) {
    bool found = false;
    for (const auto& e : schema["enum"]) found = found || e == v;
    if (!found) return path + ": " + v.dump() + " is not one of " + schema["enum"].dump();
  }
  if (v.is_number()) {
    if (schema.contains("minimum") && v.get<double>() < schema["minimum"].get<double>())
      return path + ": " + v.dump() + " is below the minimum " + schema["minimum"].dump();
    if (schema.contains("maximum") && v.get<double>() > schema["maximum"].get<double>())
      return path + ": " + v.dump() + " is above the maximum " + schema["maximum"].dump();
  }
  if (v.is_string()) {  // lengths in bytes: the schemas' strings are ASCII words
    const size_t n = v.get_ref<const std::string&>().size();
    if (schema.contains("minLength") && n < schema["minLength"].get<size_t>())
      return path + ": " + v.dump() + " is shorter than " + schema["minLength"].dump() + " characters";
    if (schema.contains("maxLength") && n > schema["maxLength"].get<size_t>())
      return path + ": " + v.dump() + " is longer than " + schema["maxLength"].dump() + " characters";
  }
  if (v.is_object()) {
    for (const auto& r : schema.value("required", nlohmann::json::array()))
      if (!v.contains(r.get<std::string>())) return path + ": missing required field '" + r.get<std::string>() + "'";
    const auto props = schema.value("properties", nlohmann::json::object());
    for (const auto& [key, value] : v.items()) {
      if (props.contains(key)) {
        if (auto e = validate(value, props[key], path + "." + key); !e.empty()) return e;
      } else if (schema.contains("additionalProperties") && schema["additionalProperties"] == false) {
        return path + ": unexpected field '" + key + "'";
      }
    }
  }
  if (v.is_array()) {
    if (schema.contains("minItems") && v.size() < schema["minItems"].get<size_t>())
      return path + ": needs at least " + schema["minItems"].dump() + " items";
    if (schema.contains("maxItems") && v.size() > schema["maxItems"].get<size_t>())
      return path + ": allows at most " + schema["maxItems"].dump() + " items";
    if (schema.contains("items"))
      for (size_t i = 0; i < v.size(); ++i)
        if (auto e = validate(v[i], schema["items"], path + "[" + std::to_string(i) + "]"); !e.empty()) return e;
  }
  return "";
}

}  // namespace chatsim::agents::llm
