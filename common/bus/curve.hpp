#pragma once
// ZeroMQ CURVE on the bus: encryption, and authentication of every node by its public key.
// Keys live in one folder as <name>.pub and <name>.secret (Z85 text, 40 characters); the
// proxy uses bus.secret and admits exactly the public keys in that folder.
#include <atomic>
#include <filesystem>
#include <memory>
#include <set>
#include <string>
#include <thread>

#include <zmq.hpp>

namespace chatsim::bus {

struct CurveKeyPair {
  std::string public_key;  // Z85
  std::string secret_key;  // Z85
};

CurveKeyPair generate_curve_keys();
// Writes <dir>/<name>.pub and <dir>/<name>.secret (the secret readable by its owner only).
void write_curve_keys(const std::filesystem::path& dir, const std::string& name, const CurveKeyPair& keys);
// Reads one Z85 key file; throws std::runtime_error naming the file when it is not one.
std::string read_curve_key(const std::filesystem::path& file);

// What a node needs: the proxy's public key and its own pair. Empty: no CURVE.
struct CurveClient {
  std::string server_public;
  CurveKeyPair own;
  bool enabled() const { return !server_public.empty(); }
};
// <dir>/bus.pub and <dir>/<name>.{pub,secret}.
CurveClient curve_client_from_dir(const std::filesystem::path& dir, const std::string& name);
void apply_curve_client(zmq::socket_t& socket, const CurveClient& curve);
// For command-line tools: the keys folder in $CHATSIM_CURVE_KEYS with the key pair "cli",
// or no CURVE when it is unset.
CurveClient curve_client_from_env();

// What the proxy needs: its secret key and the public keys it admits.
struct CurveServer {
  std::string secret_key;
  std::set<std::string> authorized;  // Z85 public keys
  bool enabled() const { return !secret_key.empty(); }
};
// <dir>/bus.secret, and every <dir>/*.pub as an admitted key.
CurveServer curve_server_from_dir(const std::filesystem::path& dir);
void apply_curve_server(zmq::socket_t& socket);

// Answers ZeroMQ's authentication requests (ZAP, RFC 27) for one context: a CURVE client is
// admitted when its public key is authorized; anything else is refused.
class ZapAuthenticator {
 public:
  ZapAuthenticator(zmq::context_t& context, std::set<std::string> authorized_z85);
  ~ZapAuthenticator();
  uint64_t refused() const { return refused_; }

 private:
  void run();
  zmq::socket_t socket_;
  std::set<std::string> authorized_;
  std::atomic<bool> stop_{false};
  std::atomic<uint64_t> refused_{0};
  std::thread thread_;
};

}  // namespace chatsim::bus
