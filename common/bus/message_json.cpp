#include "common/bus/message_json.hpp"

#include "common/util/executable_dir.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <flatbuffers/idl.h>
#include <nlohmann/json.hpp>

namespace chatsim::bus {
namespace fs = std::filesystem;

namespace {

void shorten(nlohmann::json& j, size_t max_array) {
  if (j.is_array()) {
    if (j.size() > max_array) {
      j = "<" + std::to_string(j.size()) + " items>";
      return;
    }
    for (auto& v : j) shorten(v, max_array);
  } else if (j.is_object()) {
    for (auto& [_, v] : j.items()) shorten(v, max_array);
  }
}

}  // namespace

fs::path envelope_bfbs_path() {
  if (const char* env = std::getenv("CHATSIM_MSGS_BFBS"); env != nullptr && *env != '\0') return env;
  const fs::path beside = executable_dir() / ".." / "share" / "chatsim" / "msgs" / "envelope.bfbs";
  if (fs::exists(beside)) return beside;
  return CHATSIM_MSGS_BFBS;
}

MessagePrinter::MessagePrinter(const fs::path& bfbs) : parser_(std::make_unique<flatbuffers::Parser>()) {
  std::ifstream in(bfbs, std::ios::binary);
  if (!in) throw std::runtime_error(bfbs.string() + ": cannot read the binary schema (set CHATSIM_MSGS_BFBS)");
  std::ostringstream s;
  s << in.rdbuf();
  bfbs_ = s.str();
  parser_->opts.strict_json = true;
  parser_->opts.output_default_scalars_in_json = false;
  parser_->opts.indent_step = -1;
  if (!parser_->Deserialize(reinterpret_cast<const uint8_t*>(bfbs_.data()), bfbs_.size()))
    throw std::runtime_error(bfbs.string() + ": not a FlatBuffers binary schema");
}

MessagePrinter::~MessagePrinter() = default;

std::string MessagePrinter::to_json(std::string_view bytes, size_t max_array) const {
  std::string text;
  if (!flatbuffers::GenerateText(*parser_, bytes.data(), &text)) return R"({"error": "not printable as JSON"})";
  try {
    auto j = nlohmann::json::parse(text);
    shorten(j, max_array);
    return j.dump();
  } catch (const nlohmann::json::parse_error&) {
    return text;
  }
}

}  // namespace chatsim::bus
