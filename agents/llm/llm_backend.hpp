#pragma once
// The "LLM" part of every agent: an instruction in, a JSON configuration out, validated
// against the agent's output schema. Backends: `offline` (a deterministic English interpreter,
// the default) and `openai` (any OpenAI-compatible endpoint, see openai_backend.hpp).
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

namespace chatsim::agents::llm {

struct Prompt {
  std::string agent;          // manager, view, deletion, asset, motion
  std::string system;         // role, actions, inputs, few-shot examples (agents/prompts/<agent>.md)
  nlohmann::json schema;      // output schema (agents/prompts/<agent>.schema.json)
};

// Loads agents/prompts/<agent>.md and .schema.json from the prompt directory
// ($CHATSIM_PROMPTS, else the source tree's agents/prompts).
const Prompt& prompt_for(const std::string& agent);

class Backend {
 public:
  virtual ~Backend() = default;
  virtual std::string name() const = 0;
  // The configuration for one instruction; throws BackendError when no valid answer comes.
  virtual nlohmann::json complete(const Prompt& prompt, const std::string& instruction) = 0;
};

class BackendError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "offline" (default) or the value of $CHATSIM_LLM.
std::unique_ptr<Backend> make_backend(const std::string& name = "");

// A subset of JSON Schema (type, properties, required, additionalProperties: false, enum,
// items, minimum, maximum, minItems, maxItems): returns "" when valid, else where and why.
std::string validate(const nlohmann::json& value, const nlohmann::json& schema, const std::string& path = "$");

}  // namespace chatsim::agents::llm
