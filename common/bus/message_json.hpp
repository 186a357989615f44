#pragma once
// Bus messages as readable JSON, by FlatBuffers reflection from the binary schema
// (envelope.bfbs), not hand-written printers: new fields print without code changes.
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

namespace flatbuffers {
class Parser;
}

namespace chatsim::bus {

// Where envelope.bfbs is: $CHATSIM_MSGS_BFBS, else beside the executables
// (<bin>/../share/chatsim/msgs/envelope.bfbs), else the build tree it was built in.
std::filesystem::path envelope_bfbs_path();

class MessagePrinter {
 public:
  explicit MessagePrinter(const std::filesystem::path& bfbs = envelope_bfbs_path());  // throws on a bad file
  ~MessagePrinter();

  // The Envelope as JSON; arrays longer than max_array are replaced by "<N items>".
  std::string to_json(std::string_view envelope_bytes, size_t max_array = 32) const;
  // The binary schema itself (recorders store it).
  const std::string& schema_bytes() const { return bfbs_; }

 private:
  std::string bfbs_;
  std::unique_ptr<flatbuffers::Parser> parser_;
};

}  // namespace chatsim::bus
