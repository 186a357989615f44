#include "common/bus/curve.hpp"

#include <sys/stat.h>
#include <zmq.h>  // zmq_utils.h is deprecated: zmq.h has the CURVE and Z85 helpers

#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <vector>

namespace chatsim::bus {
namespace fs = std::filesystem;

CurveKeyPair generate_curve_keys() {
  char pub[41] = {}, sec[41] = {};
  if (zmq_curve_keypair(pub, sec) != 0) throw std::runtime_error("ZeroMQ was built without CURVE (libsodium)");
  return {pub, sec};
}

void write_curve_keys(const fs::path& dir, const std::string& name, const CurveKeyPair& keys) {
  fs::create_directories(dir);
  std::ofstream(dir / (name + ".pub")) << keys.public_key << "\n";
  const fs::path secret = dir / (name + ".secret");
  {
    std::ofstream out(secret);
    out << keys.secret_key << "\n";
  }
  ::chmod(secret.c_str(), 0600);
}

std::string read_curve_key(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": cannot read the key file (make keys with: chatsim keys new)");
  std::string key;
  in >> key;
  uint8_t raw[32];
  if (key.size() != 40 || zmq_z85_decode(raw, key.c_str()) == nullptr)
    throw std::runtime_error(file.string() + ": not a CURVE key (expected 40 Z85 characters)");
  return key;
}

CurveClient curve_client_from_dir(const fs::path& dir, const std::string& name) {
  return {read_curve_key(dir / "bus.pub"), {read_curve_key(dir / (name + ".pub")), read_curve_key(dir / (name + ".secret"))}};
}

CurveClient curve_client_from_env() {
  const char* dir = std::getenv("CHATSIM_CURVE_KEYS");
  if (dir == nullptr || *dir == '\0') return {};
  return curve_client_from_dir(dir, "cli");
}

void apply_curve_client(zmq::socket_t& s, const CurveClient& c) {
  if (!c.enabled()) return;
  s.set(zmq::sockopt::curve_serverkey, c.server_public);
  s.set(zmq::sockopt::curve_publickey, c.own.public_key);
  s.set(zmq::sockopt::curve_secretkey, c.own.secret_key);
}

CurveServer curve_server_from_dir(const fs::path& dir) {
  CurveServer s;
  s.secret_key = read_curve_key(dir / "bus.secret");
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".pub") s.authorized.insert(read_curve_key(e.path()));
  return s;
}

void apply_curve_server(zmq::socket_t& s) {
  s.set(zmq::sockopt::curve_server, true);
  s.set(zmq::sockopt::zap_domain, "chatsim");  // every connection goes through the authenticator
}

ZapAuthenticator::ZapAuthenticator(zmq::context_t& context, std::set<std::string> authorized)
    : socket_(context, zmq::socket_type::rep), authorized_(std::move(authorized)) {
  socket_.set(zmq::sockopt::linger, 0);
  socket_.set(zmq::sockopt::rcvtimeo, 100);
  socket_.bind("inproc://zeromq.zap.01");
  thread_ = std::thread([this] { run(); });
}

ZapAuthenticator::~ZapAuthenticator() {
  stop_ = true;
  thread_.join();
}

void ZapAuthenticator::run() {
  while (!stop_) {
    std::vector<zmq::message_t> frames;
    zmq::message_t f;
    try {
      if (!socket_.recv(f)) continue;  // timeout: look at stop_
      frames.push_back(std::move(f));
      while (frames.back().more()) {
        zmq::message_t next;
        if (!socket_.recv(next)) break;
        frames.push_back(std::move(next));
      }
    } catch (const zmq::error_t&) {
      return;  // context closing
    }
    // version, request id, domain, address, identity, mechanism, credentials...
    bool ok = false;
    if (frames.size() >= 7 && frames[5].to_string() == "CURVE" && frames[6].size() == 32) {
      char z85[41] = {};
      zmq_z85_encode(z85, static_cast<const uint8_t*>(frames[6].data()), 32);
      ok = authorized_.count(z85) != 0;
    }
    if (!ok) refused_++;
    const std::string request_id = frames.size() > 1 ? frames[1].to_string() : "";
    socket_.send(zmq::str_buffer("1.0"), zmq::send_flags::sndmore);
    socket_.send(zmq::buffer(request_id), zmq::send_flags::sndmore);
    socket_.send(zmq::buffer(std::string(ok ? "200" : "400")), zmq::send_flags::sndmore);
    socket_.send(zmq::buffer(std::string(ok ? "OK" : "key not authorized")), zmq::send_flags::sndmore);
    socket_.send(zmq::str_buffer(""), zmq::send_flags::sndmore);
    socket_.send(zmq::str_buffer(""), zmq::send_flags::none);
  }
}

}  // namespace chatsim::bus
