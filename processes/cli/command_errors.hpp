#pragma once
// How a command ends on an exception: no bus is exit 3; input the user can fix (a scene, a
// nuScenes import or a recording that does not load, an invalid argument) is a usage error;
// anything else a failure. The message goes to stderr.
#include <iostream>
#include <stdexcept>

#include "common/bag/mcap_writer.hpp"
#include "common/bus/node.hpp"
#include "common/import/nuscenes_import.hpp"
#include "common/scene/scene.hpp"
#include "common/util/exit_codes.hpp"

namespace chatsim::cli {

template <class Body>
int exit_code_of(Body&& body) {
  try {
    return body();
  } catch (const bus::BusError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return exit_code::kBusUnavailable;
  } catch (const scene::SceneError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return exit_code::kUsage;
  } catch (const import::ImportError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return exit_code::kUsage;
  } catch (const bag::McapError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return exit_code::kUsage;
  } catch (const std::invalid_argument& e) {
    std::cerr << "error: " << e.what() << "\n";
    return exit_code::kUsage;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return exit_code::kFailure;
  }
}

}  // namespace chatsim::cli
