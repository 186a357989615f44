#pragma once
// The `openai` backend: any OpenAI-compatible chat-completions endpoint, over libcurl.
// Settings come from the environment; the API key is never logged, recorded or echoed.
#include <memory>
#include <string>

#include "agents/llm/llm_backend.hpp"

namespace chatsim::agents::llm {

struct OpenAiSettings {
  std::string base_url = "https://api.openai.com/v1";  // CHATSIM_OPENAI_BASE_URL
  std::string model = "gpt-4o-mini";                    // CHATSIM_OPENAI_MODEL
  std::string api_key;                                  // OPENAI_API_KEY (or CHATSIM_OPENAI_API_KEY)
  double timeout_s = 30;                                // CHATSIM_OPENAI_TIMEOUT_S
  int attempts = 3;                                     // CHATSIM_OPENAI_ATTEMPTS
};

OpenAiSettings openai_settings_from_env();
std::unique_ptr<Backend> make_openai_backend(OpenAiSettings settings);

}  // namespace chatsim::agents::llm
