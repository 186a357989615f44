#include "common/launch/launch_file.hpp"

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

#include <yaml-cpp/yaml.h>

namespace chatsim::launch {
namespace {

const std::vector<std::string> kTopKeys = {"bus", "stop_timeout_s", "curve_keys", "allowed_roots", "processes"};
const std::vector<std::string> kProcessKeys = {
    "name",          "kind",         "executable",          "args",          "env",
    "host",          "netns",        "respawn",      "respawn_delay_s",     "respawn_max_delay_s",
    "max_respawns",  "stable_after_s", "ready",             "ready_timeout_s",
    "bus_args",      "mock"};

size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] != b[j - 1])});
    }
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

class Reader {
 public:
  explicit Reader(std::filesystem::path path) : path_(std::move(path)) {}

  [[noreturn]] void fail(const YAML::Node& at, const std::string& what) const {
    std::ostringstream os;
    os << path_.string();
    if (at.IsDefined() && at.Mark().line >= 0) {
      os << ":" << at.Mark().line + 1 << ":" << at.Mark().column + 1;
    }
    os << ": " << what;
    throw LaunchFileError(os.str());
  }

  void check_keys(const YAML::Node& map, const std::vector<std::string>& allowed,
                  const std::string& where) const {
    for (const auto& kv : map) {
      if (!kv.first.IsScalar()) fail(kv.first, "a key in " + where + " must be a plain name, not a list or a map");
      const std::string key = kv.first.as<std::string>();
      if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
      std::string hint;
      for (const auto& a : allowed) {
        if (edit_distance(key, a) <= 2) hint = " (did you mean '" + a + "'?)";
      }
      std::string all;
      for (const auto& a : allowed) all += (all.empty() ? "" : ", ") + a;
      fail(kv.first, "unknown key '" + key + "' in " + where + hint + "; known keys: " + all);
    }
  }

  std::string str(const YAML::Node& n, const std::string& what) const {
    if (!n.IsScalar()) fail(n, what + " must be a string");
    return n.as<std::string>();
  }

  double number(const YAML::Node& n, const std::string& what, double min, double max) const {
    double v = 0;
    if (!n.IsScalar() || !YAML::convert<double>::decode(n, v)) fail(n, what + " must be a number");
    if (v < min || v > max) {
      std::ostringstream os;
      os << what << " is " << v << "; it must be from " << min << " to " << max;
      fail(n, os.str());
    }
    return v;
  }

  bool boolean(const YAML::Node& n, const std::string& what) const {
    bool v = false;
    if (!n.IsScalar() || !YAML::convert<bool>::decode(n, v)) fail(n, what + " must be true or false");
    return v;
  }

  ProcessSpec process(const YAML::Node& n, size_t index) const {
    const std::string where = "process #" + std::to_string(index + 1);
    if (!n.IsMap()) fail(n, where + " must be a map with at least 'name' and 'executable'");
    check_keys(n, kProcessKeys, where);
    ProcessSpec p;
    p.line = n.Mark().line + 1;
    if (!n["name"]) fail(n, where + " has no 'name'");
    p.name = str(n["name"], "name");
    if (p.name.empty() || p.name.find_first_of("/ \t") != std::string::npos) {
      fail(n["name"], "name '" + p.name + "' must be non-empty without '/' or spaces");
    }
    const std::string who = "process '" + p.name + "'";
    p.kind = n["kind"] ? str(n["kind"], "kind") : p.name;
    if (n["mock"]) {
      const auto script = std::filesystem::path(str(n["mock"], "mock"));
      p.mock_script = script.is_absolute() ? script : path_.parent_path() / script;
    }
    if (!n["executable"] && !p.mock_script) fail(n, who + " has no 'executable' (nor 'mock')");
    if (n["executable"]) p.executable = str(n["executable"], "executable");
    if (const auto a = n["args"]) {
      if (!a.IsSequence()) fail(a, who + ": args must be a list of strings");
      for (const auto& x : a) p.args.push_back(str(x, "each of args"));
    }
    if (const auto e = n["env"]) {
      if (!e.IsMap()) fail(e, who + ": env must be a map of NAME: value");
      for (const auto& kv : e) p.env[str(kv.first, "env name")] = str(kv.second, "env value");
    }
    if (n["host"]) p.host = str(n["host"], "host");
    if (n["netns"]) p.netns = str(n["netns"], "netns");
    if (const auto r = n["respawn"]) {
      const auto policy = parse_respawn_policy(str(r, "respawn"));
      if (!policy) fail(r, who + ": respawn must be never, on-failure or always");
      p.respawn = *policy;
    }
    if (n["respawn_delay_s"]) p.backoff.initial_delay_s = number(n["respawn_delay_s"], "respawn_delay_s", 0, 3600);
    if (n["respawn_max_delay_s"]) p.backoff.max_delay_s = number(n["respawn_max_delay_s"], "respawn_max_delay_s", 0, 3600);
    if (n["max_respawns"]) p.backoff.max_respawns = static_cast<int>(number(n["max_respawns"], "max_respawns", 0, 1e6));
    if (n["stable_after_s"]) p.backoff.stable_after_s = number(n["stable_after_s"], "stable_after_s", 0, 1e6);
    if (const auto r = n["ready"]) {
      const std::string v = str(r, "ready");
      if (v == "heartbeat") p.ready = Readiness::Heartbeat;
      else if (v == "none") p.ready = Readiness::None;
      else fail(r, who + ": ready must be heartbeat or none");
    }
    if (n["ready_timeout_s"]) p.ready_timeout_s = number(n["ready_timeout_s"], "ready_timeout_s", 0.1, 600);
    if (n["bus_args"]) p.bus_args = boolean(n["bus_args"], "bus_args");
    return p;
  }

  LaunchFile file(const std::string& text) const {
    YAML::Node root;
    try {
      root = YAML::Load(text);
    } catch (const YAML::ParserException& e) {
      throw LaunchFileError(path_.string() + ":" + std::to_string(e.mark.line + 1) + ":" +
                            std::to_string(e.mark.column + 1) + ": not valid YAML: " + e.msg);
    }
    if (!root.IsMap()) fail(root, "a launch file is a map with 'bus' and 'processes'");
    check_keys(root, kTopKeys, "the launch file");
    LaunchFile f;
    f.path = path_;
    f.bus = root["bus"] ? str(root["bus"], "bus") : "";
    if (root["stop_timeout_s"]) f.stop_timeout_s = number(root["stop_timeout_s"], "stop_timeout_s", 0.1, 600);
    if (root["curve_keys"]) {
      // Relative to the launch file, so a file and its keys folder travel together.
      const std::filesystem::path keys = str(root["curve_keys"], "curve_keys");
      f.curve_keys = keys.is_absolute() ? keys : path_.parent_path() / keys;
    }
    if (const auto roots = root["allowed_roots"]) {
      if (!roots.IsSequence()) fail(roots, "allowed_roots must be a list of folders");
      for (const auto& r : roots) {
        const std::filesystem::path dir = str(r, "allowed_roots");
        f.allowed_roots.push_back(dir.is_absolute() ? dir : path_.parent_path() / dir);
      }
    }
    const auto procs = root["processes"];
    if (!procs || !procs.IsSequence() || procs.size() == 0) {
      fail(procs ? procs : root, "'processes' must be a non-empty list");
    }
    std::set<std::string> names;
    for (size_t i = 0; i < procs.size(); ++i) {
      ProcessSpec p = process(procs[i], i);
      if (!names.insert(p.name).second) fail(procs[i]["name"], "duplicate process name '" + p.name + "'");
      f.processes.push_back(std::move(p));
    }
    return f;
  }

 private:
  std::filesystem::path path_;
};

}  // namespace

const ProcessSpec* LaunchFile::find(const std::string& name) const {
  for (const auto& p : processes) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

LaunchFile parse_launch_file(const std::string& text, const std::filesystem::path& path) {
  try {
    return Reader(path).file(text);
  } catch (const YAML::Exception& e) {
    // Anything yaml-cpp refuses that our checks did not name first: still the file's fault.
    std::ostringstream os;
    os << path.string();
    if (e.mark.line >= 0) os << ":" << e.mark.line + 1 << ":" << e.mark.column + 1;
    os << ": " << e.msg;
    throw LaunchFileError(os.str());
  }
}

LaunchFile load_launch_file(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw LaunchFileError(path.string() + ": cannot open the launch file");
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_launch_file(ss.str(), path);
}

void swap_for_mock(LaunchFile& file, const std::string& name, const std::filesystem::path& script) {
  for (auto& p : file.processes) {
    if (p.name != name) continue;
    p.mock_script = script;
    return;
  }
  std::string names;
  for (const auto& p : file.processes) names += (names.empty() ? "" : ", ") + p.name;
  throw LaunchFileError(file.path.string() + ": --mock names process '" + name +
                        "', which the file does not have (it has: " + names + ")");
}

}  // namespace chatsim::launch
