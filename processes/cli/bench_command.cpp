#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "bench/bag_bench.hpp"
#include "bench/chart.hpp"
#include "bench/bus_bench.hpp"
#include "common/util/exit_codes.hpp"
#include "common/util/output_dir.hpp"
#include "processes/cli/commands.hpp"

namespace chatsim::cli {
namespace {

struct BusBenchArgs {
  bench::BusBenchConfig config;
  std::string out = "bench/results/bus.json";
  bool quick = false;
};

int run_bus_bench(BusBenchArgs a) {
  if (!a.out.empty()) prepare_output_file(a.out);  // before any work
  if (a.quick) {
    a.config.small_count = 20000;
    a.config.image_count = 20;
    a.config.latency_count = 1000;
    a.config.repeats = 1;
  }
  std::cerr << "bench bus: raw ZeroMQ PUB/SUB vs the bus, tcp loopback (takes ~"
            << (a.quick ? "3" : "25") << " s on 2 cores)..." << std::endl;
  const auto report = bench::run_bus_bench(a.config);
  auto mark = [](bool ok) { return ok ? "met" : "MISSED"; };
  const auto& raw = report["raw_zmq"];
  for (const char* side : {"bus", "bus_direct"}) {
    const auto& b = report[side];
    const auto& r = b["ratios"];
    const auto& t = b["targets_met"];
    std::printf("%s\n", std::string(side) == "bus" ? "through the proxy (publish/subscribe, two hops):"
                                                    : "direct links (responses and streams to an inbox, one hop):");
    std::printf("  1 KB throughput : %.0f msg/s, raw %.0f msg/s, ratio %.2f (target >= 0.70: %s)\n",
                b["small"]["messages_per_s"].get<double>(), raw["small"]["messages_per_s"].get<double>(),
                r["small_throughput"].get<double>(), mark(t["small_throughput"]));
    std::printf("  6 MB throughput : %.0f MB/s, raw %.0f MB/s, ratio %.2f (target >= 0.80: %s)\n",
                b["image"]["mb_per_s"].get<double>(), raw["image"]["mb_per_s"].get<double>(),
                r["image_throughput"].get<double>(), mark(t["image_throughput"]));
    std::printf("  1 KB round trip : p50 %.3f ms p99 %.3f ms, raw p50 %.3f ms p99 %.3f ms (target p99 < 1 ms: %s)\n",
                b["latency"]["rtt_p50_ms"].get<double>(), b["latency"]["rtt_p99_ms"].get<double>(),
                raw["latency"]["rtt_p50_ms"].get<double>(), raw["latency"]["rtt_p99_ms"].get<double>(),
                mark(t["latency_p99"]));
  }
  if (!a.out.empty()) {
    const std::filesystem::path out(a.out);
    if (out.has_parent_path()) std::filesystem::create_directories(out.parent_path());
    const auto tmp = out.string() + ".tmp";
    std::ofstream(tmp) << report.dump(2) << "\n";
    std::filesystem::rename(tmp, out);
    std::printf("wrote %s\n", out.c_str());
    auto delivered = [&](const char* side, const char* kind) {
      const auto& m = report[side][kind];
      return 1.0 - m["lost"].get<double>() / std::max(1.0, m["messages"].get<double>());
    };
    // For a person: each path's throughput as a share of raw ZeroMQ's, measured in the same run.
    std::filesystem::path png = out;
    png.replace_extension(".png");
    std::vector<bench::StackedBar> bars;
    for (const auto& [ratio, size] : {std::pair{"small_throughput", "1 KB"}, std::pair{"image_throughput", "6 MB"}}) {
      const std::string prefix(size);
      bars.push_back({prefix + " raw ZeroMQ PUB/SUB", {{"raw ZeroMQ", 1.0}}});
      bars.push_back({prefix + " through the proxy",
                      {{"through the proxy (publish/subscribe)", report["bus"]["ratios"][ratio].get<double>()}}});
      bars.push_back({prefix + " direct link", {{"direct link (inbox)", report["bus_direct"]["ratios"][ratio].get<double>()}}});
    }
    bench::write_stacked_bars_png(png, "Bus throughput as a share of raw ZeroMQ (same run; targets 0.7 for 1 KB, 0.8 for 6 MB)",
                                  "share of raw ZeroMQ's throughput", bars, "%.2f");
    std::printf("wrote %s\n", png.c_str());
    // Speed against accuracy (the share of messages delivered), every path.
    std::filesystem::path delivery = out;
    delivery.replace_extension();
    delivery += "-delivery.png";
    bench::write_scatter_png(delivery, {"Bus vs raw ZeroMQ (same run): throughput and delivery", "throughput [MB/s]",
                                        "share delivered", true},
                             {{"raw 1 KB", report["raw_zmq"]["small"]["mb_per_s"].get<double>(), delivered("raw_zmq", "small")},
                              {"bus 1 KB", report["bus"]["small"]["mb_per_s"].get<double>(), delivered("bus", "small")},
                              {"raw 6 MB", report["raw_zmq"]["image"]["mb_per_s"].get<double>(), delivered("raw_zmq", "image")},
                              {"bus 6 MB", report["bus"]["image"]["mb_per_s"].get<double>(), delivered("bus", "image")},
                              {"direct 1 KB", report["bus_direct"]["small"]["mb_per_s"].get<double>(), delivered("bus_direct", "small")},
                              {"direct 6 MB", report["bus_direct"]["image"]["mb_per_s"].get<double>(), delivered("bus_direct", "image")}});
    std::printf("wrote %s\n", delivery.c_str());
  }
  return exit_code::kOk;
}

struct BagBenchArgs {
  bench::BagBenchConfig config;
  std::string out = "bench/results/bag.json";
};

int run_bag_bench(const BagBenchArgs& a) {
  if (!a.out.empty()) prepare_output_file(a.out);  // before any work
  std::cerr << "bench bag: " << a.config.fps << " frames/s of " << a.config.width << "x" << a.config.height
            << " JPEG through the bus into the recorder for " << a.config.seconds << " s..." << std::endl;
  const auto r = bench::run_bag_bench(a.config);
  std::printf("published %d, recorded %llu, missing %lld, lost (gaps) %llu; frame %.0f KB = %.1f MB/s stream\n",
              r["published"].get<int>(), (unsigned long long)r["recorded"].get<uint64_t>(),
              (long long)r["missing"].get<int64_t>(), (unsigned long long)r["lost"].get<uint64_t>(),
              r["frame"]["jpeg_bytes"].get<double>() / 1e3, r["stream_mb_per_s"].get<double>());
  std::printf("writer %.0f MB/s vs plain file writes %.0f MB/s (ratio %.2f); headroom over the stream x%.1f\n",
              r["writer_mb_per_s"].get<double>(), r["raw_file_mb_per_s"].get<double>(),
              r["ratios"]["writer_vs_raw_file"].get<double>(), r["ratios"]["writer_headroom_vs_stream"].get<double>());
  if (!a.out.empty()) {
    const std::filesystem::path out(a.out);
    if (out.has_parent_path()) std::filesystem::create_directories(out.parent_path());
    std::ofstream(out.string() + ".tmp") << r.dump(2) << "\n";
    std::filesystem::rename(out.string() + ".tmp", out);
    std::printf("wrote %s\n", out.c_str());
    std::filesystem::path png = out;
    png.replace_extension(".png");
    const double recorded = r["recorded"].get<double>() / std::max(1, r["published"].get<int>());
    bench::write_scatter_png(png, {"Recorder under a 30 fps 1920x1280 JPEG stream (same run)", "throughput [MB/s]",
                                   "share of frames recorded", true},
                             {{"camera stream (needed)", r["stream_mb_per_s"].get<double>(), recorded},
                              {"recorder: zstd + disk", r["writer_mb_per_s"].get<double>(), recorded},
                              {"baseline: plain file writes", r["raw_file_mb_per_s"].get<double>(), 1.0}});
    std::printf("wrote %s\n", png.c_str());
  }
  return r["missing"].get<int64_t>() == 0 && r["lost"].get<uint64_t>() == 0 ? exit_code::kOk : exit_code::kFailure;
}

}  // namespace

void add_bench_command(CLI::App& app, int& result) {
  auto* bench = app.add_subcommand("bench", "Benchmarks; results go to bench/results/");
  bench->require_subcommand(1);
  auto args = std::make_shared<BusBenchArgs>();
  auto* bus = bench->add_subcommand(
      "bus", "Bus latency and throughput against raw ZeroMQ PUB/SUB in the same run");
  bus->add_option("--out", args->out, "JSON report path (empty: do not write)")->capture_default_str();
  bus->add_flag("--quick", args->quick, "fewer messages: a smoke run, not a measurement");
  bus->add_option("--small-count", args->config.small_count, "number of 1 KB messages");
  bus->add_option("--image-count", args->config.image_count, "number of 6 MB messages");
  bus->add_option("--repeats", args->config.repeats, "median of N per throughput measurement");
  bus->callback([args, &result] { result = run_bus_bench(*args); });
  auto bag_args = std::make_shared<BagBenchArgs>();
  auto* bag = bench->add_subcommand(
      "bag", "The recorder under a 30 frames/s stream of 1920x1280 JPEG frames: loss and writer throughput");
  bag->add_option("--out", bag_args->out, "JSON report path (empty: do not write)")->capture_default_str();
  bag->add_option("--seconds", bag_args->config.seconds, "stream length")->check(CLI::PositiveNumber);
  bag->callback([bag_args, &result] { result = run_bag_bench(*bag_args); });
  add_render_bench_commands(*bench, result);
  add_e2e_bench_command(*bench, result);
}

}  // namespace chatsim::cli
