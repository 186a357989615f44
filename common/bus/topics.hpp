#pragma once
// Topic names. Channels an agent serves are derived from its kind so launch files can rename
// nodes freely; a request's response goes to the requester's own reply topic.
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

namespace chatsim::bus::topics {

inline constexpr std::string_view kHeartbeat = "/bus/heartbeat";
inline constexpr std::string_view kProbePrefix = "/bus/probe/";
inline constexpr std::string_view kChatRequest = "/chat/request";
inline constexpr std::string_view kChatProgress = "/chat/progress";

inline std::string hex(uint64_t v) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(v));
  return buf;
}

// Requests to an agent kind, e.g. "/agent/motion/request".
inline std::string agent_request(std::string_view kind) {
  return "/agent/" + std::string(kind) + "/request";
}

// Requests to one named process of a kind (fan-out to workers), e.g.
// "/agent/foreground/worker/fg2/request".
inline std::string agent_worker_request(std::string_view kind, std::string_view name) {
  return "/agent/" + std::string(kind) + "/worker/" + std::string(name) + "/request";
}

inline std::string reply(std::string_view node, uint64_t instance) {
  return "/reply/" + std::string(node) + "/" + hex(instance);
}

// Handshake probes: bus plumbing, not traffic worth showing or recording.
inline bool is_probe(std::string_view topic) { return topic.substr(0, kProbePrefix.size()) == kProbePrefix; }

inline std::string probe(std::string_view node, uint64_t instance, uint64_t n) {
  return std::string(kProbePrefix) + std::string(node) + "/" + hex(instance) + "/" + std::to_string(n);
}

}  // namespace chatsim::bus::topics
