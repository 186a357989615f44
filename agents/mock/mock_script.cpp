#include "agents/mock/mock_script.hpp"

#include <chrono>
#include <fstream>
#include <sstream>
#include <thread>

#include <yaml-cpp/yaml.h>

namespace chatsim::agents {
namespace {

nlohmann::json to_json(const YAML::Node& n) {
  switch (n.Type()) {
    case YAML::NodeType::Null:
    case YAML::NodeType::Undefined:
      return nullptr;
    case YAML::NodeType::Sequence: {
      auto a = nlohmann::json::array();
      for (const auto& x : n) a.push_back(to_json(x));
      return a;
    }
    case YAML::NodeType::Map: {
      auto o = nlohmann::json::object();
      for (const auto& kv : n) o[kv.first.as<std::string>()] = to_json(kv.second);
      return o;
    }
    case YAML::NodeType::Scalar: {
      if (n.Tag() == "!") return n.as<std::string>();  // quoted: keep as text
      bool b = false;
      long long i = 0;
      double d = 0;
      if (YAML::convert<long long>::decode(n, i)) return i;
      if (YAML::convert<double>::decode(n, d)) return d;
      if (YAML::convert<bool>::decode(n, b)) return b;
      return n.as<std::string>();
    }
  }
  return nullptr;
}

class Reader {
 public:
  explicit Reader(std::filesystem::path path) : path_(std::move(path)) {}

  [[noreturn]] void fail(const YAML::Node& at, const std::string& what) const {
    std::string where = path_.string();
    if (at.IsDefined() && at.Mark().line >= 0) {
      where += ":" + std::to_string(at.Mark().line + 1) + ":" + std::to_string(at.Mark().column + 1);
    }
    throw MockScriptError(where + ": " + what);
  }

  void only(const YAML::Node& map, std::initializer_list<const char*> keys, const std::string& where) const {
    for (const auto& kv : map) {
      const auto k = kv.first.as<std::string>();
      bool known = false;
      for (const char* a : keys) known = known || k == a;
      if (!known) fail(kv.first, "unknown key '" + k + "' in " + where);
    }
  }

  MockResponse response(const YAML::Node& n, size_t i) const {
    const std::string where = "responses[" + std::to_string(i) + "]";
    if (!n.IsMap()) fail(n, where + " must be a map with 'result' or 'error'");
    only(n, {"match", "delay_ms", "result", "error"}, where);
    MockResponse r;
    if (const auto m = n["match"]) {
      if (!m.IsMap()) fail(m, where + ".match must be a map");
      only(m, {"action", "args_contains"}, where + ".match");
      if (m["action"]) r.match_action = m["action"].as<std::string>();
      if (m["args_contains"]) r.match_args_contains = m["args_contains"].as<std::string>();
    }
    if (n["delay_ms"]) r.delay_ms = n["delay_ms"].as<int>();
    if (n["result"] && n["error"]) fail(n, where + " has both 'result' and 'error'; keep one");
    if (const auto e = n["error"]) {
      r.is_error = true;
      only(e, {"code", "message"}, where + ".error");
      const std::string code = e["code"] ? e["code"].as<std::string>() : "internal";
      if (code == "not_implemented") r.error = ErrorKind::NotImplemented;
      else if (code == "bad_request") r.error = ErrorKind::BadRequest;
      else if (code == "unavailable") r.error = ErrorKind::Unavailable;
      else if (code == "internal") r.error = ErrorKind::Internal;
      else fail(e["code"], "error code '" + code + "': use not_implemented, bad_request, unavailable or internal");
      r.error_message = e["message"] ? e["message"].as<std::string>() : "error injected by the mock";
    } else if (n["result"]) {
      r.result = to_json(n["result"]);
    } else {
      fail(n, where + " needs 'result' or 'error'");
    }
    return r;
  }

  MockScript script(const std::string& text) const {
    YAML::Node root;
    try {
      root = YAML::Load(text);
    } catch (const YAML::ParserException& e) {
      throw MockScriptError(path_.string() + ":" + std::to_string(e.mark.line + 1) + ": not valid YAML/JSON: " + e.msg);
    }
    if (!root.IsMap()) fail(root, "a mock script is a map with 'agent' and 'responses'");
    try {
      only(root, {"agent", "seed", "failure_rate", "delay_ms", "responses"}, "the script");
      MockScript s;
      if (!root["agent"]) fail(root, "missing 'agent' (the agent kind it stands in for)");
      s.agent = root["agent"].as<std::string>();
      if (root["seed"]) s.seed = root["seed"].as<uint64_t>();
      if (root["failure_rate"]) {
        s.failure_rate = root["failure_rate"].as<double>();
        if (s.failure_rate < 0 || s.failure_rate > 1) fail(root["failure_rate"], "failure_rate must be from 0 to 1");
      }
      if (root["delay_ms"]) s.delay_ms = root["delay_ms"].as<int>();
      const auto rs = root["responses"];
      if (!rs || !rs.IsSequence()) fail(rs ? rs : root, "'responses' must be a list");
      for (size_t i = 0; i < rs.size(); ++i) s.responses.push_back(response(rs[i], i));
      return s;
    } catch (const YAML::BadConversion& e) {
      throw MockScriptError(path_.string() + ":" + std::to_string(e.mark.line + 1) + ": wrong type: " + e.msg);
    }
  }

 private:
  std::filesystem::path path_;
};

}  // namespace

MockScript parse_mock_script(const std::string& text, const std::filesystem::path& path) {
  return Reader(path).script(text);
}

MockScript load_mock_script(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw MockScriptError(path.string() + ": cannot open the mock script");
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_mock_script(ss.str(), path);
}

MockAgent::MockAgent(MockScript script) : script_(std::move(script)), rng_(script_.seed) {}

AgentOutcome MockAgent::handle(const AgentCall& call) {
  const std::string args = call.args.dump();
  const MockResponse* chosen = nullptr;
  for (const auto& r : script_.responses) {
    if (r.match_action && *r.match_action != call.action) continue;
    if (r.match_args_contains && args.find(*r.match_args_contains) == std::string::npos) continue;
    chosen = &r;
    break;
  }
  const bool inject = std::uniform_real_distribution<double>(0.0, 1.0)(rng_) < script_.failure_rate;
  last_delay_ms_ = chosen != nullptr && chosen->delay_ms >= 0 ? chosen->delay_ms : script_.delay_ms;
  if (last_delay_ms_ > 0) std::this_thread::sleep_for(std::chrono::milliseconds(last_delay_ms_));
  if (inject) return AgentOutcome::failure(ErrorKind::Internal, "failure injected by the mock (failure_rate)");
  if (chosen == nullptr) {
    return AgentOutcome::failure(ErrorKind::BadRequest,
                                 "the mock script has no response matching action '" + call.action + "'");
  }
  if (chosen->is_error) return AgentOutcome::failure(chosen->error, chosen->error_message);
  return AgentOutcome::success(chosen->result);
}

}  // namespace chatsim::agents
