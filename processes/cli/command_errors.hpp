#pragma once
// How a command ends on an exception: no bus is exit 3; input the user can fix (a scene, a
// nuScenes import or a recording that does not load, an output path it may not write, an
// invalid argument) is a usage error; anything else a failure. The message goes to stderr.
#include <functional>
#include <iostream>
#include <stdexcept>

#include <spdlog/spdlog.h>

#include "common/bag/mcap_writer.hpp"
#include "common/bus/node.hpp"
#include "common/import/nuscenes_import.hpp"
#include "common/scene/scene.hpp"
#include "common/util/exit_codes.hpp"
#include "common/util/output_dir.hpp"

namespace chatsim::cli {

// The exit code an exception means.
inline int exit_code_for(const std::exception& e) {
  if (dynamic_cast<const bus::BusError*>(&e) != nullptr) return exit_code::kBusUnavailable;
  const bool users_input = dynamic_cast<const scene::SceneError*>(&e) != nullptr || dynamic_cast<const import::ImportError*>(&e) != nullptr ||
                           dynamic_cast<const bag::McapError*>(&e) != nullptr || dynamic_cast<const std::invalid_argument*>(&e) != nullptr ||
                           dynamic_cast<const OutputDirError*>(&e) != nullptr;
  return users_input ? exit_code::kUsage : exit_code::kFailure;
}

inline void print_error(const std::exception& e) { std::cerr << "error: " << e.what() << "\n"; }
inline void log_error(const std::exception& e) { spdlog::error("{}", e.what()); }  // for commands that log

// Runs a command's body; an exception it throws is reported (`report`: to stderr by default)
// and becomes the exit code it means.
template <class Body>
int exit_code_of(Body&& body, const std::function<void(const std::exception&)>& report = print_error) {
  try {
    return body();
  } catch (const std::exception& e) {
    report(e);
    return exit_code_for(e);
  }
}

}  // namespace chatsim::cli
