// chatsim topic list|echo|hz|bw: look at a running bus.
#include <unistd.h>

#include <chrono>
#include <iostream>
#include <map>
#include <set>

#include <spdlog/spdlog.h>

#include "common/bus/endpoint.hpp"
#include "common/bus/message_json.hpp"
#include "common/bus/node.hpp"
#include "common/bus/topics.hpp"
#include "common/util/exit_codes.hpp"
#include "common/util/signals.hpp"
#include "processes/cli/command_errors.hpp"
#include "processes/cli/commands.hpp"

namespace chatsim::cli {
namespace {

struct TopicArgs {
  std::string bus;
  std::string topic;
  double duration_s = 2;
  int count = 0;
  bool all = false;
};

bus::NodeOptions node_options(const TopicArgs& a) {
  bus::NodeOptions o;
  o.name = "topic-" + std::to_string(getpid());
  o.kind = "cli";
  o.curve = bus::curve_client_from_env();
  o.bus = a.bus.empty() ? bus::default_bus_endpoint() : a.bus;
  o.heartbeat_period = std::chrono::milliseconds(0);  // a viewer is not a participant
  o.handshake_timeout = std::chrono::milliseconds(2000);
  return o;
}

bool internal(std::string_view topic) {
  return bus::topics::is_probe(topic) || topic.rfind("/reply/", 0) == 0;
}

int run_list(const TopicArgs& a) {
  bus::Node node(node_options(a));
  struct Seen {
    std::set<std::string> publishers, types;
    uint64_t count = 0;
  };
  std::map<std::string, Seen> topics;
  node.subscribe_prefix("", [&](const bus::Message& m) {
    if (!a.all && internal(m.topic())) return;
    auto& s = topics[std::string(m.topic())];
    s.publishers.insert(std::string(m.sender()));
    s.types.insert(msgs::EnumNamePayload(m.type()));
    ++s.count;
  });
  node.start();
  const auto& stop = install_stop_signals();
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(a.duration_s);
  while (!stop && std::chrono::steady_clock::now() < end) node.spin_once(std::chrono::milliseconds(50));
  node.shutdown();
  if (topics.empty()) std::cout << "(no messages in " << a.duration_s << " s)\n";
  for (const auto& [topic, s] : topics) {
    std::cout << topic << "  [";
    bool first = true;
    for (const auto& t : s.types) std::cout << (first ? "" : ", ") << t, first = false;
    std::cout << "]  " << s.count << " msgs  from:";
    for (const auto& p : s.publishers) std::cout << " " << p;
    std::cout << "\n";
  }
  return exit_code::kOk;
}

int run_echo(const TopicArgs& a) {
  const bus::MessagePrinter printer;
  bus::Node node(node_options(a));
  int n = 0;
  node.subscribe(a.topic, [&](const bus::Message& m) {
    std::cout << printer.to_json({reinterpret_cast<const char*>(m.data()), m.size()}) << std::endl;
    ++n;
  });
  node.start();
  const auto& stop = install_stop_signals();
  while (!stop && (a.count == 0 || n < a.count)) node.spin_once(std::chrono::milliseconds(100));
  node.shutdown();
  return exit_code::kOk;
}

// hz and bw: a sliding report every second until Ctrl-C or --duration-s.
int run_rate(const TopicArgs& a, bool bandwidth) {
  bus::Node node(node_options(a));
  uint64_t count = 0, bytes = 0, total = 0;
  node.subscribe(a.topic, [&](const bus::Message& m) {
    ++count;
    ++total;
    bytes += m.size() + m.topic().size();
  });
  node.start();
  const auto& stop = install_stop_signals();
  const auto t0 = std::chrono::steady_clock::now();
  auto last = t0;
  while (!stop) {
    node.spin_once(std::chrono::milliseconds(50));
    const auto now = std::chrono::steady_clock::now();
    const double dt = std::chrono::duration<double>(now - last).count();
    if (dt >= 1.0) {
      if (bandwidth) std::printf("%s: %.3f MB/s (%.1f msgs/s, mean %.0f B)\n", a.topic.c_str(), bytes / dt / 1e6, count / dt,
                                 count ? double(bytes) / count : 0.0);
      else std::printf("%s: %.2f Hz (%llu msgs so far)\n", a.topic.c_str(), count / dt, (unsigned long long)total);
      std::fflush(stdout);
      count = bytes = 0;
      last = now;
    }
    if (a.duration_s > 0 && std::chrono::duration<double>(now - t0).count() >= a.duration_s) break;
  }
  node.shutdown();
  return exit_code::kOk;
}

}  // namespace

void add_topic_command(CLI::App& app, int& result) {
  auto* topic = app.add_subcommand("topic", "Look at a running bus: list, echo, hz, bw");
  topic->require_subcommand(1);
  auto args = std::make_shared<TopicArgs>();
  auto* list = topic->add_subcommand("list", "Topics seen during --duration-s, with message types and publishers");
  list->add_option("--duration-s", args->duration_s, "how long to listen")->check(CLI::PositiveNumber);
  list->add_flag("--all", args->all, "include probe and reply topics");
  list->add_option("--bus", args->bus, "bus endpoint (default: $CHATSIM_BUS or tcp://127.0.0.1:7700)");
  list->callback([args, &result] { result = exit_code_of([&] { return run_list(*args); }); });
  auto* echo = topic->add_subcommand("echo", "Print each message on TOPIC as JSON (FlatBuffers reflection)");
  echo->add_option("topic", args->topic, "topic, e.g. /bus/heartbeat")->required();
  echo->add_option("--count,-n", args->count, "stop after this many (default: until Ctrl-C)");
  echo->add_option("--bus", args->bus, "bus endpoint (default: $CHATSIM_BUS or tcp://127.0.0.1:7700)");
  echo->callback([args, &result] { result = exit_code_of([&] { return run_echo(*args); }); });
  auto* hz = topic->add_subcommand("hz", "Message rate on TOPIC, once a second");
  hz->add_option("topic", args->topic, "topic")->required();
  hz->add_option("--duration-s", args->duration_s, "stop after this long (0: until Ctrl-C)");
  hz->add_option("--bus", args->bus, "bus endpoint (default: $CHATSIM_BUS or tcp://127.0.0.1:7700)");
  hz->callback([args, &result] { result = exit_code_of([&] { return run_rate(*args, false); }); });
  auto* bw = topic->add_subcommand("bw", "Bandwidth on TOPIC, once a second");
  bw->add_option("topic", args->topic, "topic")->required();
  bw->add_option("--duration-s", args->duration_s, "stop after this long (0: until Ctrl-C)");
  bw->add_option("--bus", args->bus, "bus endpoint (default: $CHATSIM_BUS or tcp://127.0.0.1:7700)");
  bw->callback([args, &result] { result = exit_code_of([&] { return run_rate(*args, true); }); });
}

}  // namespace chatsim::cli
