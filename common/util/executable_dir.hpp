#pragma once
// The folder of the running executable: where sibling chatsim-* programs and the installed
// share/ folder are found.
#include <filesystem>

namespace chatsim {

inline std::filesystem::path executable_dir() {
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::current_path() : exe.parent_path();
}

}  // namespace chatsim
