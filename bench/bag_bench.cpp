#include "bench/bag_bench.hpp"

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <random>
#include <thread>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "common/bag/recorder.hpp"
#include "common/bus/node.hpp"
#include "common/bus/proxy.hpp"
#include "common/util/clock.hpp"

namespace chatsim::bench {
namespace fs = std::filesystem;

namespace {

// A frame with texture, so JPEG has real work and a realistic size.
std::vector<uchar> camera_like_jpeg(int w, int h) {
  cv::Mat img(h, w, CV_8UC3);
  std::mt19937 rng(3);
  cv::randu(img, cv::Scalar::all(0), cv::Scalar::all(255));
  cv::GaussianBlur(img, img, cv::Size(0, 0), 2.0);
  for (int i = 0; i < 40; ++i)
    cv::rectangle(img, cv::Rect(int(rng() % w), int(rng() % h), 80 + int(rng() % 300), 40 + int(rng() % 200)),
                  cv::Scalar(rng() % 255, rng() % 255, rng() % 255), cv::FILLED);
  std::vector<uchar> jpeg;
  cv::imencode(".jpg", img, jpeg, {cv::IMWRITE_JPEG_QUALITY, 90});
  return jpeg;
}

}  // namespace

nlohmann::json run_bag_bench(const BagBenchConfig& c) {
  const auto jpeg = camera_like_jpeg(c.width, c.height);
  const fs::path dir = fs::temp_directory_path() / ("chatsim-bag-bench-" + std::to_string(getpid()));
  fs::create_directories(dir);

  // Baseline: the same bytes written to a plain file, as fast as possible.
  const int frames = int(c.seconds * c.fps);
  double raw_s = 0;
  {
    std::ofstream f(dir / "raw.bin", std::ios::binary);
    const double t0 = mono_s();
    for (int i = 0; i < frames; ++i) f.write(reinterpret_cast<const char*>(jpeg.data()), std::streamsize(jpeg.size()));
    f.flush();
    raw_s = mono_s() - t0;
  }

  auto ctx = std::make_shared<zmq::context_t>(1);
  bus::Proxy proxy(ctx, "tcp://127.0.0.1:0", 100000);
  std::atomic<bool> stop_proxy{false};
  std::thread forwarding([&] { proxy.run(stop_proxy); });

  std::atomic<bool> stop_record{false}, ready{false};
  bag::RecordOptions ro;
  ro.bus = proxy.endpoint();
  ro.topics = {"/camera/front/image"};
  ro.out = dir / "stream.mcap";
  ro.ready = &ready;
  bag::RecordReport report;
  std::thread recorder([&] { report = bag::record(ro, stop_record); });
  while (!ready) std::this_thread::sleep_for(std::chrono::milliseconds(10));

  bus::NodeOptions no;
  no.name = "camera";
  no.kind = "bench";
  no.bus = proxy.endpoint();
  no.heartbeat_period = std::chrono::milliseconds(0);
  bus::Node pub(no, ctx);
  pub.start();
  int sent = 0, blocked = 0;
  const double t0 = mono_s();
  for (int i = 0; i < frames; ++i) {
    const double due = t0 + i / c.fps;
    while (mono_s() < due) std::this_thread::sleep_for(std::chrono::microseconds(200));
    flatbuffers::FlatBufferBuilder fbb(jpeg.size() + 1024);
    const auto data = fbb.CreateVector(jpeg);
    const auto img = msgs::CreateImage(fbb, fbb.CreateString("front"), i, i / c.fps, uint32_t(c.width), uint32_t(c.height), 0,
                                       msgs::ImageEncoding::Jpeg, data);
    if (pub.publish("/camera/front/image", fbb, msgs::Payload::Image, img.Union()) == bus::PublishStatus::Sent) ++sent;
    else ++blocked;
  }
  const double publish_s = mono_s() - t0;
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));  // let the tail arrive and be written
  stop_record = true;
  recorder.join();
  pub.shutdown();
  stop_proxy = true;
  forwarding.join();
  const double stream_mb_s = jpeg.size() * c.fps / 1e6;
  const double raw_mb_s = double(jpeg.size()) * frames / raw_s / 1e6;
  const nlohmann::json out{
      {"frame", {{"width", c.width}, {"height", c.height}, {"jpeg_bytes", jpeg.size()}}},
      {"fps", c.fps},
      {"published", sent},
      {"publish_blocked", blocked},
      {"publish_seconds", publish_s},
      {"recorded", report.messages},
      {"lost", report.lost},
      {"overflow", report.overflow},
      {"missing", int64_t(sent) - int64_t(report.messages)},
      {"stream_mb_per_s", stream_mb_s},
      {"writer_mb_per_s", report.write_mb_s},
      {"raw_file_mb_per_s", raw_mb_s},
      {"ratios", {{"writer_vs_raw_file", report.write_mb_s / raw_mb_s}, {"writer_headroom_vs_stream", report.write_mb_s / stream_mb_s}}},
      {"cores", std::thread::hardware_concurrency()}};
  fs::remove_all(dir);
  return out;
}

}  // namespace chatsim::bench
