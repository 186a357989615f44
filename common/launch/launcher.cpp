#include "common/launch/launcher.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstring>
#include <fstream>
#include <thread>

#include <spdlog/spdlog.h>

#include "common/bus/endpoint.hpp"
#include "common/bus/node.hpp"
#include "common/bus/topics.hpp"
#include "common/launch/child_registry.hpp"
#include "common/launch/process_tree.hpp"
#include "common/util/clock.hpp"

namespace chatsim::launch {
namespace {

bool is_local(const std::string& host) {
  return host.empty() || host == "localhost" || host == "127.0.0.1";
}

std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

Launcher::Launcher(LaunchFile file, LauncherOptions options)
    : file_(std::move(file)), options_(std::move(options)) {
  bus_ = !options_.bus_override.empty() ? options_.bus_override
         : !file_.bus.empty()           ? file_.bus
                                        : bus::default_bus_endpoint();
  children_.reserve(file_.processes.size());
  for (const auto& spec : file_.processes) {
    Child c;
    c.spec = &spec;
    c.backoff = RespawnBackoff(spec.respawn, spec.backoff);
    children_.push_back(std::move(c));
  }
  const bool has_bus = std::any_of(file_.processes.begin(), file_.processes.end(),
                                   [](const ProcessSpec& p) { return p.kind == "bus"; });
  if (bus::asks_for_os_chosen_port(bus_) && !has_bus) {
    throw LaunchFileError(file_.path.string() + ": bus " + bus_ +
                          " asks for an OS-chosen port, but no process has kind 'bus' to choose it");
  }
}

Launcher::~Launcher() { stop_all(); }

std::string Launcher::resolve(const std::string& executable) const {
  if (executable.find('/') != std::string::npos) return executable;
  const auto sibling = options_.executable_dir / executable;
  if (access(sibling.c_str(), X_OK) == 0) return sibling.string();
  const char* path = std::getenv("PATH");
  std::string dirs = path != nullptr ? path : "/usr/bin:/bin";
  size_t start = 0;
  while (start <= dirs.size()) {
    const size_t end = std::min(dirs.find(':', start), dirs.size());
    const auto candidate = std::filesystem::path(dirs.substr(start, end - start)) / executable;
    if (access(candidate.c_str(), X_OK) == 0) return candidate.string();
    start = end + 1;
  }
  return {};
}

std::vector<std::string> Launcher::command_line(const ProcessSpec& spec) const {
  std::vector<std::string> argv;
  std::string exe = spec.executable;
  std::vector<std::string> args = spec.args;
  if (spec.mock_script) {
    exe = "chatsim-mock";
    args = {"--agent", spec.kind, "--script", spec.mock_script->string()};
  }
  if (is_local(spec.host)) {
    const std::string resolved = resolve(exe);
    if (resolved.empty()) {
      throw LaunchFileError(file_.path.string() + ":" + std::to_string(spec.line) +
                            ": process '" + spec.name + "': executable '" + exe +
                            "' not found beside chatsim (" + options_.executable_dir.string() +
                            ") nor in PATH");
    }
    argv.push_back(resolved);
  } else {
    argv.push_back(exe);
  }
  argv.insert(argv.end(), args.begin(), args.end());
  if (spec.bus_args) {
    argv.push_back("--bus");
    argv.push_back(bus_);
    argv.push_back("--name");
    argv.push_back(spec.name);
    if (spec.kind == "bus" && !bus_port_file_.empty()) {
      argv.push_back("--endpoint-file");
      argv.push_back(bus_port_file_.string());
    }
    for (const auto& root : file_.allowed_roots) {
      argv.push_back("--allowed-root");
      argv.push_back(root.string());
    }
    if (!file_.curve_keys.empty()) {
      argv.push_back("--curve-keys");
      argv.push_back(file_.curve_keys.string());
    }
  }
  if (is_local(spec.host)) {
    if (spec.netns.empty()) return argv;
    // In a network namespace of this machine: another "host" as far as the bus can tell.
    std::vector<std::string> in_ns{resolve("ip").empty() ? "ip" : resolve("ip"), "netns", "exec", spec.netns};
    in_ns.insert(in_ns.end(), argv.begin(), argv.end());
    return in_ns;
  }
  // Remote: ssh with a pseudo-terminal, so ending ssh hangs up (and ends) the remote process.
  std::string remote = "exec env";
  for (const auto& [k, v] : spec.env) remote += " " + shell_quote(k + "=" + v);
  for (const auto& a : argv) remote += " " + shell_quote(a);
  return {resolve("ssh").empty() ? "ssh" : resolve("ssh"), "-o", "BatchMode=yes", "-tt",
          spec.host, remote};
}

pid_t Launcher::spawn(Child& child) {
  const ProcessSpec& spec = *child.spec;
  const std::vector<std::string> argv_s = command_line(spec);
  // Everything the child needs is prepared before fork: only async-signal-safe calls after it.
  std::vector<char*> argv;
  for (const auto& a : argv_s) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  std::vector<std::string> env_s;
  for (char** e = environ; *e != nullptr; ++e) {
    const std::string kv = *e;
    const std::string key = kv.substr(0, kv.find('='));
    if (!is_local(spec.host) || spec.env.count(key) == 0) env_s.push_back(kv);
  }
  if (is_local(spec.host)) {
    for (const auto& [k, v] : spec.env) env_s.push_back(k + "=" + v);
  }
  std::vector<char*> envp;
  for (const auto& e : env_s) envp.push_back(const_cast<char*>(e.c_str()));
  envp.push_back(nullptr);

  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error(std::string("fork failed: ") + std::strerror(errno));
  if (pid == 0) {
    setpgid(0, 0);                       // own process group: stopping it reaches grandchildren
    prctl(PR_SET_PDEATHSIG, SIGTERM);    // a launcher killed with -9 still takes them down
    if (getppid() != parent) _exit(127);
    sigset_t none;
    sigemptyset(&none);
    sigprocmask(SIG_SETMASK, &none, nullptr);
    signal(SIGINT, SIG_DFL);
    signal(SIGTERM, SIG_DFL);
    signal(SIGPIPE, SIG_DFL);
    execve(argv[0], argv.data(), envp.data());
    const char msg[] = "chatsim launch: exec failed\n";
    (void)!write(2, msg, sizeof msg - 1);
    _exit(127);
  }
  setpgid(pid, pid);  // also from the parent, so the group exists before we may signal it
  child_registry::add(pid);
  child.pid = pid;
  child.started_s = mono_s();
  child.restart_at_s = -1;
  spdlog::info("started '{}' (pid {}): {}", spec.name, pid, argv_s.front());
  return pid;
}

void Launcher::ensure_bus_node(double timeout_s) {
  if (node_) return;
  bus::NodeOptions o;
  o.name = "launch-" + std::to_string(getpid());
  o.kind = "launcher";
  o.bus = bus_;
  if (!file_.curve_keys.empty()) o.curve = bus::curve_client_from_dir(file_.curve_keys, "launch");
  o.handshake_timeout = std::chrono::milliseconds(static_cast<int64_t>(timeout_s * 1000));
  auto node = std::make_unique<bus::Node>(o);
  node->subscribe(std::string(bus::topics::kHeartbeat), [this](const bus::Message& m) {
    const auto* hb = m.payload<msgs::Heartbeat>();
    if (hb == nullptr) return;
    const std::string name(bus::view(hb->node()));
    const double now = mono_s();
    monitor_.observe(name, now, hb->period_ms() / 1000.0, hb->state() == msgs::NodeState::Stopping);
    last_beat_[name] = Beat{now, hb->pid()};
  });
  node->start();
  node_ = std::move(node);
}

void Launcher::poll_bus(double seconds) {
  if (node_) {
    node_->spin_once(std::chrono::milliseconds(static_cast<int64_t>(seconds * 1000)));
  } else {
    std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
  }
}

bool Launcher::wait_for_endpoint_file(Child& child, const std::filesystem::path& file,
                                      const std::atomic<bool>& stop) {
  const double deadline = mono_s() + child.spec->ready_timeout_s;
  while (mono_s() < deadline && !stop.load()) {
    std::ifstream in(file);
    std::string endpoint;
    if (in >> endpoint && !endpoint.empty()) {
      bus_ = endpoint;
      return true;
    }
    reap(false);
    if (child.pid < 0) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

bool Launcher::wait_ready(Child& child, const std::atomic<bool>& stop) {
  const ProcessSpec& spec = *child.spec;
  if (spec.ready == Readiness::None) return true;
  const double deadline = mono_s() + spec.ready_timeout_s;
  try {
    ensure_bus_node(spec.ready_timeout_s);
  } catch (const std::exception& e) {
    spdlog::error("'{}' started, but the bus did not answer: {}", spec.name, e.what());
    return false;
  }
  while (mono_s() < deadline && !stop.load()) {
    const auto it = last_beat_.find(spec.name);
    if (it != last_beat_.end() && it->second.seen_s >= child.started_s) return true;
    poll_bus(0.02);
    reap(false);
    // A process started earlier that died meanwhile (the bus, whose beats this wait needs) is
    // respawned by its policy now, not only once every process is ready.
    respawn_due();
    if (child.pid < 0) {
      spdlog::error("'{}' exited before it was ready", spec.name);
      return false;
    }
  }
  if (!stop.load()) {
    spdlog::error("'{}' sent no heartbeat within {} s (ready_timeout_s in {})", spec.name,
                  spec.ready_timeout_s, file_.path.string());
  }
  return false;
}

bool Launcher::start_in_order(const std::atomic<bool>& stop) {
  for (auto& child : children_) {
    if (stop.load()) return false;
    const bool choose_port = child.spec->kind == "bus" && bus::asks_for_os_chosen_port(bus_);
    if (choose_port) {
      char tmpl[] = "/tmp/chatsim-bus-endpoint-XXXXXX";
      const int fd = mkstemp(tmpl);
      if (fd < 0) throw std::runtime_error("cannot create a temporary file for the bus endpoint");
      close(fd);
      bus_port_file_ = tmpl;
      std::filesystem::remove(bus_port_file_);  // the bus writes it once bound
    }
    spawn(child);
    if (choose_port) {
      const bool ok = wait_for_endpoint_file(child, bus_port_file_, stop);
      std::filesystem::remove(bus_port_file_);
      bus_port_file_.clear();
      if (!ok) {
        spdlog::error("the bus process '{}' did not report its endpoint in time", child.spec->name);
        return false;
      }
      spdlog::info("bus endpoint: {}", bus_);
    }
    if (!options_.endpoint_file.empty() && child.spec->kind == "bus") {
      std::ofstream(options_.endpoint_file) << bus_ << "\n";
    }
    if (!wait_ready(child, stop)) return false;
  }
  if (!options_.endpoint_file.empty() && !std::filesystem::exists(options_.endpoint_file)) {
    std::ofstream(options_.endpoint_file) << bus_ << "\n";
  }
  return true;
}

void Launcher::reap(bool stopping) {
  // Adopted orphans (we are a subreaper) are reaped too, now and then: scanning /proc costs.
  if (mono_s() - orphans_reaped_s_ > 0.5) {
    orphans_reaped_s_ = mono_s();
    child_registry::reap_unowned();
  }
  for (Child& c : children_) {
    if (c.pid <= 0) continue;
    int status = 0;
    if (waitpid(c.pid, &status, WNOHANG) != c.pid) continue;  // only our own: another launcher may share the process
    child_registry::remove(c.pid);
    c.pid = -1;
    const double ran = mono_s() - c.started_s;
    const bool failed = !(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    if (WIFEXITED(status)) {
      spdlog::log(stopping || !failed ? spdlog::level::info : spdlog::level::warn,
                  "'{}' exited with code {} after {:.1f} s", c.spec->name, WEXITSTATUS(status), ran);
    } else {
      spdlog::log(stopping ? spdlog::level::info : spdlog::level::warn,
                  "'{}' was ended by signal {} ({}) after {:.1f} s", c.spec->name,
                  WTERMSIG(status), strsignal(WTERMSIG(status)), ran);
    }
    if (stopping) {
      c.done = true;
      continue;
    }
    const auto delay = c.backoff.on_exit(failed, ran);
    if (delay) {
      c.restart_at_s = mono_s() + *delay;
      spdlog::info("respawning '{}' in {:.1f} s (policy {})", c.spec->name, *delay,
                   to_string(c.spec->respawn));
    } else {
      c.done = true;
      c.failed = failed;
      if (c.backoff.exhausted()) {
        spdlog::error("'{}' failed {} times in a row; not restarting it again", c.spec->name,
                      c.backoff.consecutive());
      }
    }
  }
}

void Launcher::respawn_due() {
  const double now = mono_s();
  for (auto& c : children_) {
    if (c.pid < 0 && !c.done && c.restart_at_s >= 0 && now >= c.restart_at_s) {
      try {
        spawn(c);
      } catch (const std::exception& e) {
        spdlog::error("cannot respawn '{}': {}", c.spec->name, e.what());
        c.done = c.failed = true;
      }
    }
  }
}

int Launcher::run(const std::atomic<bool>& stop) {
  prctl(PR_SET_CHILD_SUBREAPER, 1);  // orphaned grandchildren come to us, so we can end them
  bool started = false;
  try {
    started = start_in_order(stop);
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
  }
  if (!started) {
    stop_all();
    return stop.load() ? 0 : 1;
  }
  spdlog::info("all {} processes ready on bus {}", children_.size(), bus_);
  double last_overdue_check = mono_s();
  while (!stop.load()) {
    poll_bus(0.05);
    reap(false);
    respawn_due();
    const double now = mono_s();
    if (now - last_overdue_check > 1.0) {
      last_overdue_check = now;
      for (const auto& name : monitor_.overdue(now)) {
        spdlog::warn("node '{}' stopped sending heartbeats", name);
        monitor_.observe(name, now, 0, true);  // report once, until it beats again
      }
    }
    if (std::all_of(children_.begin(), children_.end(), [](const Child& c) { return c.done; })) {
      const bool any_failed = std::any_of(children_.begin(), children_.end(),
                                          [](const Child& c) { return c.failed; });
      spdlog::info("every process has ended");
      stop_all();
      return any_failed ? 1 : 0;
    }
  }
  stop_all();
  return 0;
}

void Launcher::stop_all() {
  if (node_) {
    node_->shutdown();
    node_.reset();
  }
  // Stop in reverse start order, each group at once, then wait for all.
  for (auto it = children_.rbegin(); it != children_.rend(); ++it) {
    if (it->pid > 0) kill(-it->pid, SIGTERM);
    it->done = true;
    it->restart_at_s = -1;
  }
  const double deadline = mono_s() + file_.stop_timeout_s;
  auto any_running = [this] {
    return std::any_of(children_.begin(), children_.end(), [](const Child& c) { return c.pid > 0; });
  };
  while (any_running() && mono_s() < deadline) {
    reap(true);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  for (auto& c : children_) {
    if (c.pid > 0) {
      spdlog::warn("'{}' did not stop within {} s; killing it", c.spec->name, file_.stop_timeout_s);
      kill(-c.pid, SIGKILL);
    }
  }
  while (any_running()) {
    reap(true);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  // Whatever is left below us (orphans re-parented to this subreaper, or escaped process
  // groups) is ended too.
  for (int round = 0; round < 50; ++round) {
    const auto rest = child_registry::unowned_descendants();
    if (rest.empty()) break;
    for (pid_t p : rest) kill(p, round == 0 ? SIGTERM : SIGKILL);
    std::this_thread::sleep_for(std::chrono::milliseconds(round == 0 ? 200 : 20));
    child_registry::reap_unowned();
  }
}

}  // namespace chatsim::launch
