#include "common/scene/scene_json.hpp"

#include <cmath>
#include <fstream>

#include "common/scene/scene.hpp"

namespace chatsim::scene {

nlohmann::json read_json_file(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw SceneError(file, "", "cannot open the file (does it exist and is it readable?)");
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {  // parse_error and the other errors the parser throws
    throw SceneError(file, "", std::string("not valid JSON: ") + e.what());
  }
}

void FieldReader::fail(const std::string& problem) const { throw SceneError(file_, path_, problem); }

FieldReader FieldReader::at(const std::string& key) const {
  if (!value_.is_object()) fail("expected an object");
  const auto it = value_.find(key);
  const std::string child = path_.empty() ? key : path_ + "." + key;
  if (it == value_.end()) throw SceneError(file_, child, "missing (required)");
  return FieldReader(file_, *it, child);
}

FieldReader FieldReader::at(size_t index) const {
  if (!value_.is_array()) fail("expected an array");
  return FieldReader(file_, value_.at(index), path_ + "[" + std::to_string(index) + "]");
}

size_t FieldReader::array_size() const {
  if (!value_.is_array()) fail("expected an array");
  return value_.size();
}

std::string FieldReader::str() const {
  if (!value_.is_string()) fail("expected a string, found " + std::string(value_.type_name()));
  return value_.get<std::string>();
}

double FieldReader::number() const {
  if (!value_.is_number()) fail("expected a number, found " + std::string(value_.type_name()));
  const double v = value_.get<double>();
  if (!std::isfinite(v)) fail("not a finite number");
  return v;
}

int FieldReader::integer() const {
  if (!value_.is_number_integer()) fail("expected an integer, found " + std::string(value_.type_name()));
  return value_.get<int>();
}

bool FieldReader::boolean() const {
  if (!value_.is_boolean()) fail("expected true or false, found " + std::string(value_.type_name()));
  return value_.get<bool>();
}

Eigen::Vector3d FieldReader::vec3() const {
  if (array_size() != 3) fail("expected 3 numbers, found " + std::to_string(value_.size()));
  return {at(0).number(), at(1).number(), at(2).number()};
}

Eigen::Isometry3d FieldReader::rigid() const {
  if (array_size() != 16) fail("expected a row-major 4x4 matrix of 16 numbers, found " + std::to_string(value_.size()));
  Eigen::Matrix4d m;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m(r, c) = at(size_t(r * 4 + c)).number();
  const Eigen::Matrix3d rot = m.topLeftCorner<3, 3>();
  const double orth = (rot.transpose() * rot - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (orth > 1e-3 || std::abs(rot.determinant() - 1) > 1e-3)
    fail("not a rigid transform: the rotation part is not orthonormal with determinant +1 (error " +
         std::to_string(orth) + "); re-export the pose as rotation + translation");
  if ((m.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).cwiseAbs().maxCoeff() > 1e-9)
    fail("not a rigid transform: the last row must be 0 0 0 1");
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  // Re-orthonormalise so small rounding in files does not accumulate.
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(rot, Eigen::ComputeFullU | Eigen::ComputeFullV);
  out.linear() = svd.matrixU() * svd.matrixV().transpose();
  out.translation() = m.topRightCorner<3, 1>();
  return out;
}

std::string FieldReader::str_or(const std::string& key, const std::string& fallback) const {
  return has(key) ? at(key).str() : fallback;
}
double FieldReader::number_or(const std::string& key, double fallback) const {
  return has(key) ? at(key).number() : fallback;
}
bool FieldReader::bool_or(const std::string& key, bool fallback) const {
  return has(key) ? at(key).boolean() : fallback;
}

nlohmann::json matrix_json(const Eigen::Isometry3d& m) {
  nlohmann::json out = nlohmann::json::array();
  const Eigen::Matrix4d mm = m.matrix();
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) out.push_back(mm(r, c));
  return out;
}

}  // namespace chatsim::scene
