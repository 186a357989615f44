// libFuzzer: any text as a launch file. Parsing either succeeds or throws LaunchFileError.
#include <cstdint>
#include <string>

#include "common/launch/launch_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    chatsim::launch::parse_launch_file(std::string(reinterpret_cast<const char*>(data), size), "fuzz.yaml");
  } catch (const chatsim::launch::LaunchFileError&) {
  }
  return 0;
}
