#pragma once
// Reading JSON fields with errors that name the file and the field path, e.g.
// "scene.json: frames[3].ego_to_world: not a rigid transform ...".
#include <filesystem>
#include <string>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

namespace chatsim::scene {

nlohmann::json read_json_file(const std::filesystem::path& file);

class FieldReader {
 public:
  FieldReader(std::filesystem::path file, const nlohmann::json& value, std::string path = "")
      : file_(std::move(file)), value_(value), path_(std::move(path)) {}

  const nlohmann::json& json() const { return value_; }
  const std::string& path() const { return path_; }
  bool has(const std::string& key) const { return value_.is_object() && value_.contains(key); }

  FieldReader at(const std::string& key) const;   // required member
  FieldReader at(size_t index) const;
  size_t array_size() const;                      // requires an array

  std::string str() const;
  double number() const;                          // finite
  int integer() const;
  bool boolean() const;
  Eigen::Vector3d vec3() const;
  // 16 numbers, row-major; must be a rigid transform (orthonormal rotation, last row 0 0 0 1).
  Eigen::Isometry3d rigid() const;

  std::string str_or(const std::string& key, const std::string& fallback) const;
  double number_or(const std::string& key, double fallback) const;
  bool bool_or(const std::string& key, bool fallback) const;

  [[noreturn]] void fail(const std::string& problem) const;

 private:
  std::filesystem::path file_;
  const nlohmann::json& value_;
  std::string path_;
};

nlohmann::json matrix_json(const Eigen::Isometry3d& m);

}  // namespace chatsim::scene
