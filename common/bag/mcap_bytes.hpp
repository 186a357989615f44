#pragma once
// Little-endian encoding of MCAP's primitive types.
#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <string_view>

namespace chatsim::bag::mcap {

inline constexpr char kMagic[8] = {'\x89', 'M', 'C', 'A', 'P', '0', '\r', '\n'};

enum Op : uint8_t {
  kHeader = 0x01, kFooter = 0x02, kSchema = 0x03, kChannel = 0x04, kMessage = 0x05, kChunk = 0x06,
  kMessageIndex = 0x07, kChunkIndex = 0x08, kStatistics = 0x0B, kMetadata = 0x0C, kMetadataIndex = 0x0D,
  kSummaryOffset = 0x0E, kDataEnd = 0x0F,
};

template <typename T>
void put(std::string& out, T v) {
  char buf[sizeof(T)];
  std::memcpy(buf, &v, sizeof(T));  // the machines we build for are little-endian
  out.append(buf, sizeof(T));
}
inline void put_string(std::string& out, std::string_view s) {
  put<uint32_t>(out, uint32_t(s.size()));
  out.append(s);
}
inline void put_map(std::string& out, const std::map<std::string, std::string>& m) {
  std::string body;
  for (const auto& [k, v] : m) {
    put_string(body, k);
    put_string(body, v);
  }
  put<uint32_t>(out, uint32_t(body.size()));
  out += body;
}

// Reads from a byte range, throwing on overrun.
struct Cursor {
  const char* p;
  const char* end;
  template <typename T>
  T get() {
    if (size_t(end - p) < sizeof(T)) throw std::out_of_range("MCAP record ends early");
    T v;
    std::memcpy(&v, p, sizeof(T));
    p += sizeof(T);
    return v;
  }
  std::string_view bytes(size_t n) {
    if (size_t(end - p) < n) throw std::out_of_range("MCAP record ends early");
    std::string_view s(p, n);
    p += n;
    return s;
  }
  std::string_view string() { return bytes(get<uint32_t>()); }
  std::map<std::string, std::string> map() {
    Cursor c{p, p};
    const uint32_t len = get<uint32_t>();
    c = Cursor{p, p + len};
    bytes(len);
    std::map<std::string, std::string> m;
    while (c.p < c.end) {
      std::string k(c.string());
      m[k] = std::string(c.string());
    }
    return m;
  }
};

}  // namespace chatsim::bag::mcap
