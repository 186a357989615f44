// Our MCAP writer and reader: round trip across several chunks, metadata, damaged files.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "common/bag/mcap_reader.hpp"
#include "common/bag/mcap_writer.hpp"
#include "common/bag/recorder.hpp"
#include "tests/support/scratch_dir.hpp"

using namespace chatsim::bag;
namespace fs = std::filesystem;

namespace {
fs::path temp(const std::string& name) {
  return chatsim::scratch::dir() / ("chatsim-mcap-" + std::to_string(::getpid()) + "-" + name);
}
}  // namespace

TEST(Mcap, RoundTripAcrossChunksInTimeOrder) {
  const auto file = temp("roundtrip.mcap");
  {
    McapWriter::Options options;
    options.chunk_size = 1000;
    McapWriter w(file, options);
    const auto s = w.add_schema("test.Schema", "flatbuffer", std::string("\x01\x02\x03", 3));
    const auto a = w.add_channel(s, "/a", "flatbuffer");
    const auto b = w.add_channel(s, "/b", "flatbuffer", {{"k", "v"}});
    for (uint32_t i = 0; i < 300; ++i)
      w.write(i % 3 ? a : b, i, 1000 + i, 900 + i, std::string(i % 50, char('a' + i % 26)));
    w.add_metadata("chatsim.recording", {{"lost", "0"}});
    w.close();
    EXPECT_EQ(w.messages(), 300u);
  }
  const McapReader r(file);
  EXPECT_EQ(r.summary().message_count, 300u);
  EXPECT_GT(r.summary().chunk_count, 3u);
  EXPECT_EQ(r.summary().channels.size(), 2u);
  EXPECT_EQ(r.summary().channels.at(2).metadata.at("k"), "v");
  EXPECT_EQ(r.summary().channels.at(1).schema_name, "test.Schema");
  EXPECT_EQ(r.summary().metadata.at("chatsim.recording").at("lost"), "0");
  uint64_t last = 0, n = 0;
  r.for_each([&](const McapMessage& m) {
    EXPECT_GE(m.log_time, last);
    last = m.log_time;
    EXPECT_EQ(m.data.size(), (m.log_time - 1000) % 50);
    ++n;
  });
  EXPECT_EQ(n, 300u);
}

TEST(Mcap, DamagedFilesAreClearErrors) {
  const auto file = temp("damaged.mcap");
  {
    McapWriter w(file, {});
    const auto c = w.add_channel(w.add_schema("s", "flatbuffer", "x"), "/a", "flatbuffer");
    w.write(c, 1, 1, 1, "hello");
  }
  const auto size = fs::file_size(file);
  fs::resize_file(file, size - 20);  // an interrupted recording
  try {
    McapReader r(file);
    FAIL() << "expected McapError";
  } catch (const McapError& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos);
  }
  std::ofstream(temp("text.mcap")) << "not an mcap file at all";
  EXPECT_THROW(McapReader(temp("text.mcap")), McapError);
}

TEST(Mcap, Base64) {
  EXPECT_EQ(base64(""), "");
  EXPECT_EQ(base64("f"), "Zg==");
  EXPECT_EQ(base64("fo"), "Zm8=");
  EXPECT_EQ(base64("foo"), "Zm9v");
  EXPECT_EQ(base64("foobar"), "Zm9vYmFy");
}
