#include "common/bag/recorder.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <fstream>
#include <map>
#include <mutex>
#include <thread>

#include <nlohmann/json.hpp>

#include "common/bag/mcap_bytes.hpp"
#include "common/bag/mcap_reader.hpp"
#include "common/bag/mcap_writer.hpp"
#include "common/bus/message_json.hpp"
#include "common/bus/node.hpp"
#include "common/bus/topics.hpp"
#include "common/util/clock.hpp"
#include "common/util/output_dir.hpp"

namespace chatsim::bag {
namespace fs = std::filesystem;

namespace {

constexpr const char* kImageSchema = R"({"title":"foxglove.CompressedImage","type":"object","properties":{
"timestamp":{"type":"object","properties":{"sec":{"type":"integer"},"nsec":{"type":"integer"}}},
"frame_id":{"type":"string"},"data":{"type":"string","contentEncoding":"base64"},"format":{"type":"string"}}})";

struct Item {
  std::string topic;
  std::string bytes;
  uint64_t log_time;
};

}  // namespace

std::string base64(std::string_view in) {
  static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((in.size() + 2) / 3 * 4);
  size_t i = 0;
  for (; i + 2 < in.size(); i += 3) {
    const uint32_t v = uint32_t(uint8_t(in[i])) << 16 | uint32_t(uint8_t(in[i + 1])) << 8 | uint8_t(in[i + 2]);
    out += {t[v >> 18], t[(v >> 12) & 63], t[(v >> 6) & 63], t[v & 63]};
  }
  if (i + 1 == in.size()) {
    const uint32_t v = uint32_t(uint8_t(in[i])) << 16;
    out += {t[v >> 18], t[(v >> 12) & 63], '=', '='};
  } else if (i + 2 == in.size()) {
    const uint32_t v = uint32_t(uint8_t(in[i])) << 16 | uint32_t(uint8_t(in[i + 1])) << 8;
    out += {t[v >> 18], t[(v >> 12) & 63], t[(v >> 6) & 63], '='};
  }
  return out;
}

namespace {

// A recording may go to `out` (see record() in the header).
void check_recording_path(const fs::path& out, bool force) {
  const fs::path file = prepare_output_file(out, "--output");
  const fs::path part = file.string() + ".part";
  if (fs::exists(part))
    throw OutputDirError("--output " + file.string() + ": an interrupted recording is there (" + part.string() +
                         "): move it away or remove it, or choose another name");
  if (!fs::exists(file)) return;
  std::ifstream in(file, std::ios::binary);
  char head[8] = {};
  const bool mcap = in.read(head, 8) && std::equal(head, head + 8, mcap::kMagic);
  if (!mcap)
    throw OutputDirError("--output " + file.string() + " exists and is not an MCAP recording: choose another name "
                         "(--force replaces only recordings)");
  if (!force)
    throw OutputDirError("--output " + file.string() + ": a recording is there already: choose another name, or pass "
                         "--force to replace it");
}

}  // namespace

RecordReport record(const RecordOptions& o, const std::atomic<bool>& stop,
                    const std::function<void(const RecordReport&)>& progress) {
  check_recording_path(o.out, o.force);
  const bus::MessagePrinter schema_source;  // the binary schema goes into the file
  const fs::path part = o.out.string() + ".part";
  McapWriter writer(part, {});
  const uint16_t schema = writer.add_schema("chatsim.msgs.Envelope", "flatbuffer", schema_source.schema_bytes());
  uint16_t image_schema = 0;
  std::map<std::string, uint16_t> channels, image_channels;

  std::mutex mu;
  std::condition_variable cv;
  std::deque<Item> queue;
  size_t queued_bytes = 0;
  bool done = false;
  RecordReport report;
  double busy_s = 0;

  // The writer thread: compression and disk never hold up receiving.
  std::thread writer_thread([&] {
    for (;;) {
      Item item;
      {
        std::unique_lock lock(mu);
        cv.wait(lock, [&] { return done || !queue.empty(); });
        if (queue.empty()) return;
        item = std::move(queue.front());
        queue.pop_front();
        queued_bytes -= item.bytes.size();
      }
      const double t0 = mono_s();
      auto it = channels.find(item.topic);
      if (it == channels.end()) it = channels.emplace(item.topic, writer.add_channel(schema, item.topic, "flatbuffer")).first;
      const auto* env = msgs::GetEnvelope(item.bytes.data());
      writer.write(it->second, uint32_t(env->header()->seq()), item.log_time, env->header()->stamp_ns(), item.bytes);
      // Compressed images also go out as foxglove.CompressedImage, so Foxglove shows them.
      if (const auto* img = env->payload_as_Image();
          img != nullptr && img->data() != nullptr &&
          (img->encoding() == msgs::ImageEncoding::Jpeg || img->encoding() == msgs::ImageEncoding::Png)) {
        if (image_schema == 0) image_schema = writer.add_schema("foxglove.CompressedImage", "jsonschema", kImageSchema);
        auto ic = image_channels.find(item.topic);
        if (ic == image_channels.end())
          ic = image_channels.emplace(item.topic, writer.add_channel(image_schema, item.topic + "/foxglove", "json")).first;
        const double ts = img->timestamp_s();
        const nlohmann::json j{{"timestamp", {{"sec", int64_t(ts)}, {"nsec", int64_t((ts - int64_t(ts)) * 1e9)}}},
                               {"frame_id", img->camera() ? img->camera()->str() : ""},
                               {"format", img->encoding() == msgs::ImageEncoding::Jpeg ? "jpeg" : "png"},
                               {"data", base64({reinterpret_cast<const char*>(img->data()->data()), img->data()->size()})}};
        writer.write(ic->second, uint32_t(env->header()->seq()), item.log_time, env->header()->stamp_ns(), j.dump());
      }
      busy_s += mono_s() - t0;
      std::lock_guard lock(mu);
      report.messages++;
      report.bytes += item.bytes.size();
    }
  });

  bus::NodeOptions no;
  no.name = "bag-record-" + std::to_string(getpid());
  no.kind = "recorder";
  no.curve = bus::curve_client_from_env();
  no.bus = o.bus;  // it beats, so launchers and tests can see it is up
  std::unique_ptr<bus::Node> node;
  try {
    node = std::make_unique<bus::Node>(no);
    auto handler = [&](const bus::Message& m) {
      if (!o.all && o.topics.empty()) return;
      if (o.all && bus::topics::is_probe(m.topic())) return;
      Item item{std::string(m.topic()), std::string(reinterpret_cast<const char*>(m.data()), m.size()), uint64_t(now_ns())};
      std::lock_guard lock(mu);
      if (queued_bytes + item.bytes.size() > o.max_queue_bytes) {
        report.overflow++;
        return;
      }
      queued_bytes += item.bytes.size();
      queue.push_back(std::move(item));
      cv.notify_one();
    };
    if (o.all || o.topics.empty()) node->subscribe_prefix("", handler);
    else
      for (const auto& t : o.topics) node->subscribe(t, handler);
    node->start();
    if (o.ready != nullptr) o.ready->store(true);
  } catch (...) {
    {
      std::lock_guard lock(mu);
      done = true;
    }
    cv.notify_one();
    writer_thread.join();
    writer.close();
    fs::remove(part);
    throw;
  }
  const double t0 = mono_s();
  double last_progress = t0;
  while (!stop && (o.duration_s <= 0 || mono_s() - t0 < o.duration_s)) {
    node->spin_once(std::chrono::milliseconds(50));
    if (progress && mono_s() - last_progress >= 1.0) {
      last_progress = mono_s();
      RecordReport r;
      {
        std::lock_guard lock(mu);
        r = report;
      }
      r.lost = node->stats().gaps;
      r.seconds = mono_s() - t0;
      progress(r);
    }
  }
  node->shutdown();
  {
    std::lock_guard lock(mu);
    done = true;
  }
  cv.notify_one();
  writer_thread.join();
  report.seconds = mono_s() - t0;
  report.lost = node->stats().gaps;
  report.invalid = node->stats().invalid;
  report.write_mb_s = busy_s > 0 ? report.bytes / busy_s / 1e6 : 0;
  writer.add_metadata("chatsim.recording", {{"bus", o.bus},
                                            {"lost", std::to_string(report.lost)},
                                            {"invalid", std::to_string(report.invalid)},
                                            {"overflow", std::to_string(report.overflow)},
                                            {"messages", std::to_string(report.messages)}});
  writer.close();
  report.file_bytes = writer.bytes_written();
  fs::rename(part, o.out);  // complete files only under the asked name
  return report;
}

uint64_t play(const PlayOptions& o, const std::atomic<bool>& stop) {
  const McapReader reader(o.file);
  bus::NodeOptions no;
  no.name = "bag-play-" + std::to_string(getpid());
  no.kind = "player";
  no.curve = bus::curve_client_from_env();
  no.bus = o.bus;
  bus::Node node(no);
  node.start();
  uint64_t sent = 0;
  do {
    const double wall0 = mono_s();
    uint64_t first = 0;
    bool have_first = false;
    reader.for_each([&](const McapMessage& m) {
      if (stop || m.channel->message_encoding != "flatbuffer") return;
      if (!o.topics.empty() && std::find(o.topics.begin(), o.topics.end(), m.channel->topic) == o.topics.end()) return;
      if (!have_first) {
        first = m.log_time;
        have_first = true;
      }
      if (o.rate > 0) {
        const double due = double(m.log_time - first) * 1e-9 / o.rate;
        while (!stop && mono_s() - wall0 < due) {
          node.spin_once(std::chrono::milliseconds(0));
          std::this_thread::sleep_for(std::chrono::microseconds(
              std::max<int64_t>(50, std::min<int64_t>(5000, int64_t((due - (mono_s() - wall0)) * 1e6)))));
        }
      }
      // Times move to now: a replayed request keeps the time it had left, not a deadline long past.
      std::string bytes(m.data);
      if (auto* header = msgs::GetMutableEnvelope(bytes.data())->mutable_header()) {
        const int64_t shift = now_ns() - header->stamp_ns();
        header->mutate_stamp_ns(header->stamp_ns() + shift);
        if (header->deadline_ns() != 0) header->mutate_deadline_ns(header->deadline_ns() + shift);
      }
      while (!stop && node.republish(m.channel->topic, bytes) == bus::PublishStatus::WouldBlock)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      ++sent;
    });
  } while (o.loop && !stop);
  // Give the last messages time to leave before the socket closes (linger is finite).
  for (const double until = mono_s() + 0.3; mono_s() < until;) node.spin_once(std::chrono::milliseconds(20));
  node.shutdown();
  return sent;
}

}  // namespace chatsim::bag
