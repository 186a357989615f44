#include "agents/llm/llm_backend.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <stdexcept>

#include "agents/asset/asset_choice.hpp"
#include "agents/deletion/deletion.hpp"
#include "agents/language/lexicon.hpp"
#include "agents/manager/decompose.hpp"
#include "agents/llm/openai_backend.hpp"
#include "agents/motion/motion_intent.hpp"
#include "agents/view/view.hpp"

namespace chatsim::agents::llm {
namespace {

std::filesystem::path prompt_dir() {
  if (const char* env = std::getenv("CHATSIM_PROMPTS"); env != nullptr && *env != '\0') return env;
  return CHATSIM_PROMPTS_DIR;
}

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw BackendError("cannot read the prompt file " + file.string() + " (set CHATSIM_PROMPTS to the agents/prompts folder)");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The deterministic English interpreter, one function per agent.
class OfflineBackend : public Backend {
 public:
  OfflineBackend() {
    // Loaded at the start, not on the first command; a broken file is reported by that command.
    try {
      lexicon::load_vocabulary();
    } catch (const std::runtime_error&) {
    }
  }
  std::string name() const override { return "offline"; }
  nlohmann::json complete(const Prompt& prompt, const std::string& instruction) override {
    nlohmann::json out;
    try {
      if (prompt.agent == "manager") out = manager::to_json(manager::decompose(instruction));
      else if (prompt.agent == "view") out = view::to_json(view::parse_view(instruction));
      else if (prompt.agent == "deletion") out = deletion::to_json(deletion::parse_deletion(instruction));
      else if (prompt.agent == "asset") out = asset::to_json(asset::parse_asset(instruction));
      else if (prompt.agent == "motion") out = motion::to_json(motion::parse_motion(instruction));
      else throw BackendError("the offline interpreter has no part for agent '" + prompt.agent + "'");
    } catch (const BackendError&) {
      throw;
    } catch (const std::runtime_error& e) {  // its vocabulary files missing or broken
      throw BackendError(e.what());
    }
    if (auto problem = validate(out, prompt.schema); !problem.empty())
      throw BackendError("offline interpreter produced JSON that breaks the " + prompt.agent + " schema: " + problem);
    return out;
  }
};

}  // namespace

const Prompt& prompt_for(const std::string& agent) {
  static std::mutex mu;
  static std::map<std::string, Prompt> cache;
  std::lock_guard lock(mu);
  auto it = cache.find(agent);
  if (it != cache.end()) return it->second;
  Prompt p;
  p.agent = agent;
  p.system = read_text(prompt_dir() / (agent + ".md"));
  try {
    p.schema = nlohmann::json::parse(read_text(prompt_dir() / (agent + ".schema.json")));
  } catch (const nlohmann::json::parse_error& e) {
    throw BackendError("prompt schema " + (prompt_dir() / (agent + ".schema.json")).string() + " is not valid JSON: " + e.what());
  }
  return cache.emplace(agent, std::move(p)).first->second;
}

std::unique_ptr<Backend> make_backend(const std::string& requested) {
  std::string name = requested;
  if (name.empty()) {
    const char* env = std::getenv("CHATSIM_LLM");
    name = env != nullptr && *env != '\0' ? env : "offline";
  }
  if (name == "offline") return std::make_unique<OfflineBackend>();
  if (name == "openai") return make_openai_backend(openai_settings_from_env());
  throw BackendError("LLM backend '" + name + "' is not known (use 'offline' or 'openai')");
}

}  // namespace chatsim::agents::llm
