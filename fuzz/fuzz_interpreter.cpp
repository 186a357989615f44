// libFuzzer: any text as a command. The offline interpreter and the manager must answer every
// input (possibly "not understood") without crashing, hanging or throwing.
#include <cstdint>
#include <filesystem>
#include <string>

#include "agents/core/agent_registry.hpp"
#include "agents/manager/decompose.hpp"
#include "agents/motion/motion_intent.hpp"
#include "agents/asset/asset_choice.hpp"
#include "agents/deletion/deletion.hpp"
#include "agents/view/view.hpp"
#include "fuzz/fuzz_scene_fixture.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace chatsim::agents;
  static const std::string scene = chatsim::fuzz::layout_scene_dir();
  static std::shared_ptr<llm::Backend> backend = llm::make_backend("offline");
  static manager::Manager mgr(local_caller(backend), backend);
  static int round = 0;
  const std::string text(reinterpret_cast<const char*>(data), std::min<size_t>(size, 400));
  manager::decompose(text);
  motion::parse_motion(text);
  asset::choose_asset(asset::parse_asset(text));
  deletion::parse_deletion(text);
  view::parse_view(text);
  // Conversations of a few rounds, so references across rounds are exercised too. Planning is
  // the slow part: every other input only.
  if (++round % 2 == 0) {
    if (round % 8 == 0) mgr.reset("fuzz");
    mgr.chat("fuzz", scene, text);
  }
  return 0;
}
