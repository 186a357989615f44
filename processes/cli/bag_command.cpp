// chatsim bag record|info|play: MCAP recordings of the bus.
#include <cstdio>
#include <iostream>

#include "common/bag/mcap_reader.hpp"
#include "common/bag/recorder.hpp"
#include "common/bus/endpoint.hpp"
#include "common/bus/node.hpp"
#include "common/util/exit_codes.hpp"
#include "common/util/log.hpp"
#include "common/util/signals.hpp"
#include "processes/cli/command_errors.hpp"
#include "processes/cli/commands.hpp"

namespace chatsim::cli {
namespace {

struct BagArgs {
  std::string bus;
  std::string out;
  std::vector<std::string> topics;
  bool all = false;
  double duration_s = 0;
  std::string file;
  double rate = 1.0;
  bool loop = false, force = false;
};

std::string endpoint(const std::string& bus) { return bus.empty() ? bus::default_bus_endpoint() : bus; }

int run_record(const BagArgs& a) {
  if (a.topics.empty() && !a.all) {
    std::cerr << "error: name the topics to record, or --all\n";
    return exit_code::kUsage;
  }
  bag::RecordOptions o;
  o.bus = endpoint(a.bus);
  o.topics = a.topics;
  o.all = a.all;
  o.duration_s = a.duration_s;
  o.out = a.out.empty() ? "chatsim-" + std::to_string(std::time(nullptr)) + ".mcap" : a.out;
  o.force = a.force;
  const auto& stop = install_stop_signals();
  std::cerr << "recording " << (a.all ? "every topic" : std::to_string(a.topics.size()) + " topic(s)") << " from " << o.bus
            << " to " << o.out.string() << " (Ctrl-C stops)\n";
  const auto r = bag::record(o, stop, [](const bag::RecordReport& p) {
    std::fprintf(stderr, "\r  %llu messages, %.1f MB, lost %llu   ", (unsigned long long)p.messages, p.bytes / 1e6,
                 (unsigned long long)p.lost);
  });
  std::fprintf(stderr, "\n");
  std::printf("%s: %llu messages, %.1f MB in %.1f s; lost %llu (sequence gaps), invalid %llu, overflow %llu; "
              "writer %.0f MB/s\n",
              o.out.c_str(), (unsigned long long)r.messages, r.bytes / 1e6, r.seconds, (unsigned long long)r.lost,
              (unsigned long long)r.invalid, (unsigned long long)r.overflow, r.write_mb_s);
  return r.lost + r.overflow + r.invalid > 0 ? exit_code::kFailure : exit_code::kOk;
}

int run_info(const BagArgs& a) {
  const bag::McapReader reader(a.file);
  const auto& s = reader.summary();
  const double duration = s.message_count ? (s.end_ns - s.start_ns) * 1e-9 : 0.0;
  std::printf("%s\n  messages: %llu in %u chunks over %.2f s\n", a.file.c_str(), (unsigned long long)s.message_count,
              s.chunk_count, duration);
  for (const auto& [id, ch] : s.channels) {
    const auto it = s.channel_counts.find(id);
    std::printf("  %-40s %8llu  [%s, %s]\n", ch.topic.c_str(), (unsigned long long)(it == s.channel_counts.end() ? 0 : it->second),
                ch.schema_name.c_str(), ch.message_encoding.c_str());
  }
  const auto rec = s.metadata.find("chatsim.recording");
  if (rec != s.metadata.end()) {
    auto get = [&](const char* k) { return rec->second.count(k) ? rec->second.at(k) : std::string("?"); };
    std::printf("  lost while recording: %s (sequence gaps), invalid %s, overflow %s\n", get("lost").c_str(),
                get("invalid").c_str(), get("overflow").c_str());
  } else {
    std::printf("  lost while recording: unknown (not recorded by chatsim)\n");
  }
  return exit_code::kOk;
}

int run_play(const BagArgs& a) {
  bag::PlayOptions o;
  o.bus = endpoint(a.bus);
  o.file = a.file;
  o.rate = a.rate;
  o.topics = a.topics;
  o.loop = a.loop;
  const auto& stop = install_stop_signals();
  const auto n = bag::play(o, stop);
  std::printf("played %llu messages from %s\n", (unsigned long long)n, a.file.c_str());
  return exit_code::kOk;
}

}  // namespace

void add_bag_command(CLI::App& app, int& result) {
  auto* bag = app.add_subcommand("bag", "Record the bus to MCAP files, inspect them, play them back");
  bag->require_subcommand(1);
  auto args = std::make_shared<BagArgs>();
  auto* rec = bag->add_subcommand("record", "Record topics (or --all) to an MCAP file: flatbuffer schemas and channels, "
                                            "zstd chunks, indexes, summary; compressed images also as foxglove.CompressedImage");
  rec->add_option("topics", args->topics, "exact topics to record");
  rec->add_flag("--all", args->all, "record every topic (probe topics excepted)");
  rec->add_option("-o,--output", args->out, "output file (default chatsim-<time>.mcap); written as FILE.part until complete; "
                                            "an existing file is refused");
  rec->add_flag("--force", args->force, "replace an earlier recording at --output (never a file that is not one)");
  rec->add_option("--duration-s", args->duration_s, "stop after this long (default: until Ctrl-C)");
  rec->add_option("--bus", args->bus, "bus endpoint (default: $CHATSIM_BUS or tcp://127.0.0.1:7700)");
  rec->callback([args, &result] { result = exit_code_of([&] { return run_record(*args); }); });
  auto* info = bag->add_subcommand("info", "Topics, counts, duration and lost messages of a recording");
  info->add_option("file", args->file, "MCAP file")->required()->check(CLI::ExistingFile);
  info->callback([args, &result] { result = exit_code_of([&] { return run_info(*args); }); });
  auto* play = bag->add_subcommand("play", "Republish a recording with its original timing (per-topic order kept)");
  play->add_option("file", args->file, "MCAP file")->required()->check(CLI::ExistingFile);
  play->add_option("--rate", args->rate, "speed factor; 0 = as fast as possible")->check(CLI::NonNegativeNumber);
  play->add_option("--topics", args->topics, "only these topics");
  play->add_flag("--loop", args->loop, "start again at the end until Ctrl-C");
  play->add_option("--bus", args->bus, "bus endpoint (default: $CHATSIM_BUS or tcp://127.0.0.1:7700)");
  play->callback([args, &result] { result = exit_code_of([&] { return run_play(*args); }); });
}

}  // namespace chatsim::cli
