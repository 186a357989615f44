// Scale-out: two network namespaces stand in for two worker hosts. Rendering workers placed
// there (background and foreground, one thread each) give the same frames as one worker of
// each on this host, and the rendering stages finish faster with two. Needs root and ip netns;
// skipped otherwise. Namespaces and processes are always cleaned up.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/support/subprocess.hpp"

using namespace chatsim;
using namespace std::chrono_literals;
using test_support::bin;
using test_support::ScopedProcess;
namespace fs = std::filesystem;

namespace {

int sh(const std::string& cmd) { return std::system((cmd + " >/dev/null 2>&1").c_str()); }

// Two namespaces, each a "host" reached over its own veth link; the bus listens on 10.77.1.1.
struct Hosts {
  bool ok = false;
  Hosts() {
    if (geteuid() != 0 || sh("command -v ip") != 0) return;
    down();
    ok = true;
    for (int i : {1, 2}) {
      const std::string ns = "chatsim-host" + std::to_string(i), root_if = "csroot" + std::to_string(i),
                        ns_if = "csns" + std::to_string(i), net = "10.77." + std::to_string(i);
      ok = ok && sh("ip netns add " + ns) == 0 && sh("ip link add " + root_if + " type veth peer name " + ns_if) == 0 &&
           sh("ip link set " + ns_if + " netns " + ns) == 0 && sh("ip addr add " + net + ".1/24 dev " + root_if) == 0 &&
           sh("ip link set " + root_if + " up") == 0 && sh("ip -n " + ns + " addr add " + net + ".2/24 dev " + ns_if) == 0 &&
           sh("ip -n " + ns + " link set " + ns_if + " up") == 0 && sh("ip -n " + ns + " link set lo up") == 0 &&
           sh("ip -n " + ns + " route add default via " + net + ".1") == 0;
    }
  }
  ~Hosts() { down(); }
  static void down() {
    for (int i : {1, 2}) {
      sh("ip netns del chatsim-host" + std::to_string(i));
      sh("ip link del csroot" + std::to_string(i));
    }
  }
};

std::string launch_file(bool cluster, const fs::path& cache) {
  std::string f = "bus: tcp://10.77.1.1:0\nstop_timeout_s: 3\nprocesses:\n"
                  "  - {name: bus, kind: bus, executable: chatsim-bus}\n";
  for (const char* k : {"manager", "view", "deletion", "asset", "motion"})
    f += std::string("  - {name: ") + k + ", executable: chatsim-" + k + "}\n";
  const std::string env = "env: {CHATSIM_THREADS: \"1\", CHATSIM_CACHE: \"" + cache.string() + "\", CHATSIM_TRAIN_ITERATIONS: \"40\"}";
  if (cluster) {
    for (int i : {1, 2}) {
      const std::string n = std::to_string(i), ns = "chatsim-host" + n;
      f += "  - {name: bg" + n + ", kind: background, executable: chatsim-background, netns: " + ns + ", " + env + "}\n";
      f += "  - {name: fg" + n + ", kind: foreground, executable: chatsim-foreground, netns: " + ns + ", " + env + "}\n";
    }
  } else {
    f += "  - {name: background, executable: chatsim-background, " + env + "}\n";
    f += "  - {name: foreground, executable: chatsim-foreground, " + env + "}\n";
  }
  return f;
}

struct RunResult {
  nlohmann::json result;
  bool ok = false;
};

RunResult run_on(const std::string& yaml, const fs::path& dir, const fs::path& scene, const fs::path& out) {
  fs::create_directories(dir);
  std::ofstream(dir / "graph.yaml") << yaml;
  const fs::path ep = dir / "endpoint";
  ScopedProcess graph(test_support::spawn({bin("chatsim"), "launch", (dir / "graph.yaml").string(), "--endpoint-file", ep.string()},
                                          (dir / "launch.log").string()));
  RunResult r;
  for (int i = 0; i < 300 && !fs::exists(ep); ++i) std::this_thread::sleep_for(100ms);
  if (!fs::exists(ep)) return r;
  std::string endpoint = test_support::read_file(ep);
  endpoint.erase(endpoint.find_last_not_of(" \n") + 1);
  // The endpoint file is written as soon as the bus is up; the workers follow. The speed
  // comparison needs every worker known to the manager before the run spreads its work.
  for (int i = 0; i < 600 && test_support::read_file(dir / "launch.log").find("processes ready") == std::string::npos; ++i)
    std::this_thread::sleep_for(100ms);
  std::this_thread::sleep_for(1500ms);  // a few heartbeats from the last one reach the manager
  const std::string cmd = "CHATSIM_CACHE=" + (dir / "cache").string() + " timeout 300 " + bin("chatsim") + " run --timeout-s 240 --bus " + endpoint +
                          " --scene " + scene.string() + " --out " + out.string() +
                          " 'Add a red car 12 m ahead and move the view 1 m to the left' > " + (dir / "run.log").string() + " 2>&1";
  r.ok = std::system(cmd.c_str()) == 0;
  if (r.ok) r.result = nlohmann::json::parse(test_support::read_file(out / "result.json"));
  kill(graph.pid, SIGINT);
  graph.wait(20s);
  return r;
}

// How many cores' worth of work this machine does in parallel right now: the same busy loop
// on one thread, then on two at once. About 2 on an idle 2-core machine; near 1 where the
// machine is shared or throttled, and there two workers cannot be faster.
double parallel_capacity() {
  auto spin = [] {
    volatile double x = 1.0;
    for (long i = 0; i < 150'000'000; ++i) x = x * 1.0000001 + 1e-9;
  };
  auto seconds = [](int threads, auto work) {
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<std::thread> ts;
    for (int i = 0; i < threads; ++i) ts.emplace_back(work);
    for (auto& t : ts) t.join();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  const double one = seconds(1, spin), two = seconds(2, spin);
  return 2.0 * one / two;
}

}  // namespace

TEST(Cluster, WorkersInOtherNetworkNamespacesGiveTheSameFramesFaster) {
  Hosts hosts;
  if (!hosts.ok) GTEST_SKIP() << "needs root and ip netns (network namespaces) to stand in for worker hosts";
  const fs::path root = test_support::temp_path("cluster-test");
  fs::remove_all(root);
  ASSERT_EQ(sh(bin("chatsim") + " scene demo --out " + (root / "scene").string() +
               " --preset small --frames 16 --no-plates --no-views --seed 6"),
            0);
  const double capacity_before = parallel_capacity();
  const RunResult one = run_on(launch_file(false, root / "one" / "cache"), root / "one", root / "scene", root / "one-out");
  ASSERT_TRUE(one.ok) << test_support::read_file(root / "one" / "run.log") << test_support::read_file(root / "one" / "launch.log");
  const RunResult two = run_on(launch_file(true, root / "two" / "cache"), root / "two", root / "scene", root / "two-out");
  ASSERT_TRUE(two.ok) << test_support::read_file(root / "two" / "run.log") << test_support::read_file(root / "two" / "launch.log");
  const double capacity = std::min(capacity_before, parallel_capacity());
  // The same frames, bit for bit.
  int compared = 0;
  for (const auto& cam : fs::directory_iterator(root / "one-out" / "frames"))
    for (const auto& f : fs::directory_iterator(cam.path())) {
      const fs::path other = root / "two-out" / "frames" / cam.path().filename() / f.path().filename();
      ASSERT_TRUE(fs::exists(other)) << other;
      EXPECT_EQ(test_support::read_file(f.path()), test_support::read_file(other)) << f.path().filename() << " differs";
      ++compared;
    }
  EXPECT_EQ(compared, 48);  // 3 cameras x 16 frames
  // Faster with two workers per kind (one thread each) than with one, by as much as the cores
  // this machine gives in parallel allow: under 0.85 of one worker's time with two cores'
  // worth (0.59 and 0.61 seen here), relaxed toward 1 as the measured capacity falls.
  auto stages = [](const nlohmann::json& r) { return r["seconds"]["background"].get<double>() + r["seconds"]["foreground"].get<double>(); };
  RecordProperty("one_worker_s", std::to_string(stages(one.result)));
  RecordProperty("two_workers_s", std::to_string(stages(two.result)));
  RecordProperty("parallel_capacity", std::to_string(capacity));
  std::cout << "parallel capacity " << capacity << " cores; one worker " << stages(one.result) << " s, two " << stages(two.result) << " s\n";
  if (capacity >= 1.3) {
    const double bound = 1.0 - 0.3 * (1.0 - 1.0 / std::min(capacity, 2.0));
    EXPECT_LT(stages(two.result), bound * stages(one.result))
        << "one worker: " << stages(one.result) << " s, two: " << stages(two.result) << " s, capacity " << capacity;
  } else {
    std::cout << "the speed comparison is not asserted: this machine gave " << capacity << " cores' worth in parallel\n";
  }
  for (const char* name : {"chatsim-manager", "chatsim-backgro", "chatsim-bus"})
    EXPECT_EQ(test_support::count_with_env(name, root.string()), 0) << name;
  if (HasFailure()) std::cout << "kept for a look: " << root << "\n";  // logs and result.json of both runs
  else fs::remove_all(root);
}
