#pragma once
// One scratch folder per test process in the temporary folder (ctest runs tests in parallel),
// removed with everything in it when the process exits, so test runs leave nothing behind.
#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

namespace chatsim::scratch {

inline const std::filesystem::path& dir() {
  struct Owned {
    std::filesystem::path path;
    Owned() : path(std::filesystem::temp_directory_path() / ("chatsim-tests-" + std::to_string(::getpid()))) {
      std::filesystem::create_directories(path);
    }
    ~Owned() {
      std::error_code ignored;  // a folder that cannot be removed must not fail the run
      std::filesystem::remove_all(path, ignored);
    }
  };
  static const Owned owned;
  return owned.path;
}

}  // namespace chatsim::scratch
