#include "agents/llm/openai_backend.hpp"

#include <curl/curl.h>

#include <chrono>
#include <cstdlib>
#include <mutex>
#include <thread>

namespace chatsim::agents::llm {
namespace {

using nlohmann::json;

std::string env_or(const char* name, const std::string& fallback) {
  const char* v = std::getenv(name);
  return v != nullptr && *v != '\0' ? v : fallback;
}

size_t append(char* data, size_t size, size_t n, void* out) {
  static_cast<std::string*>(out)->append(data, size * n);
  return size * n;
}

struct HttpReply {
  long status = 0;
  std::string body;
  std::string transport_error;  // empty when the request went through
};

HttpReply post_json(const std::string& url, const std::string& body, const std::string& api_key, double timeout_s) {
  static std::once_flag init;
  std::call_once(init, [] { curl_global_init(CURL_GLOBAL_DEFAULT); });
  HttpReply reply;
  CURL* curl = curl_easy_init();
  if (curl == nullptr) {
    reply.transport_error = "libcurl could not start";
    return reply;
  }
  curl_slist* headers = curl_slist_append(nullptr, "Content-Type: application/json");
  const std::string auth = "Authorization: Bearer " + api_key;
  if (!api_key.empty()) headers = curl_slist_append(headers, auth.c_str());
  curl_easy_setopt(curl, CURLOPT_URL, url.c_str());
  curl_easy_setopt(curl, CURLOPT_HTTPHEADER, headers);
  curl_easy_setopt(curl, CURLOPT_POSTFIELDS, body.c_str());
  curl_easy_setopt(curl, CURLOPT_POSTFIELDSIZE, long(body.size()));
  curl_easy_setopt(curl, CURLOPT_WRITEFUNCTION, append);
  curl_easy_setopt(curl, CURLOPT_WRITEDATA, &reply.body);
  curl_easy_setopt(curl, CURLOPT_TIMEOUT_MS, long(timeout_s * 1000));
  curl_easy_setopt(curl, CURLOPT_CONNECTTIMEOUT_MS, long(std::min(timeout_s, 10.0) * 1000));
  curl_easy_setopt(curl, CURLOPT_NOSIGNAL, 1L);
  const CURLcode rc = curl_easy_perform(curl);
  if (rc != CURLE_OK) reply.transport_error = curl_easy_strerror(rc);
  curl_easy_getinfo(curl, CURLINFO_RESPONSE_CODE, &reply.status);
  curl_slist_free_all(headers);
  curl_easy_cleanup(curl);
  return reply;
}

// Removes the key from any text that might reach a log or a message.
std::string redact(std::string text, const std::string& key) {
  if (key.size() < 4) return text;
  for (size_t at = text.find(key); at != std::string::npos; at = text.find(key)) text.replace(at, key.size(), "***");
  return text;
}

class OpenAiBackend : public Backend {
 public:
  explicit OpenAiBackend(OpenAiSettings s) : s_(std::move(s)) {}
  std::string name() const override { return "openai"; }

  json complete(const Prompt& prompt, const std::string& instruction) override {
    json messages = json::array();
    messages.push_back({{"role", "system"},
                        {"content", prompt.system + "\n\nOutput JSON schema:\n" + prompt.schema.dump()}});
    messages.push_back({{"role", "user"}, {"content", instruction}});
    std::string last_problem;
    for (int attempt = 1; attempt <= std::max(1, s_.attempts); ++attempt) {
      const json body{{"model", s_.model},
                      {"temperature", 0},
                      {"messages", messages},
                      {"response_format",
                       {{"type", "json_schema"},
                        {"json_schema", {{"name", prompt.agent + "_config"}, {"schema", prompt.schema}}}}}};
      const auto reply = post_json(s_.base_url + "/chat/completions", body.dump(), s_.api_key, s_.timeout_s);
      if (!reply.transport_error.empty()) {
        last_problem = "request to " + s_.base_url + " failed: " + reply.transport_error;
        continue;  // timeouts and refused connections may pass
      }
      if (reply.status >= 500 || reply.status == 429) {
        last_problem = s_.base_url + " answered HTTP " + std::to_string(reply.status);
        std::this_thread::sleep_for(std::chrono::milliseconds(200 * attempt));
        continue;
      }
      if (reply.status != 200)
        throw BackendError(redact(s_.base_url + " answered HTTP " + std::to_string(reply.status) + ": " +
                                      reply.body.substr(0, 300) + " (check CHATSIM_OPENAI_MODEL and the API key)",
                                  s_.api_key));
      std::string content;
      try {
        content = json::parse(reply.body).at("choices").at(0).at("message").at("content").get<std::string>();
      } catch (const json::exception& e) {
        last_problem = "the endpoint's reply is not a chat completion: " + std::string(e.what());
        continue;
      }
      json answer;
      try {
        answer = json::parse(content);
      } catch (const json::parse_error& e) {
        last_problem = "the model's answer is not JSON: " + content.substr(0, 200);
        messages.push_back({{"role", "assistant"}, {"content", content}});
        messages.push_back({{"role", "user"}, {"content", "That was not valid JSON (" + std::string(e.what()) +
                                                              "). Answer with JSON only, matching the schema."}});
        continue;
      }
      const std::string problem = validate(answer, prompt.schema);
      if (problem.empty()) return answer;
      last_problem = "the model's answer breaks the schema: " + problem;
      messages.push_back({{"role", "assistant"}, {"content", content}});
      messages.push_back({{"role", "user"}, {"content", "Schema validation failed: " + problem +
                                                            ". Answer again with JSON matching the schema."}});
    }
    throw BackendError(redact("no valid answer from the " + prompt.agent + " prompt after " +
                                  std::to_string(std::max(1, s_.attempts)) + " attempts: " + last_problem,
                              s_.api_key));
  }

 private:
  OpenAiSettings s_;
};

}  // namespace

OpenAiSettings openai_settings_from_env() {
  OpenAiSettings s;
  s.base_url = env_or("CHATSIM_OPENAI_BASE_URL", s.base_url);
  while (!s.base_url.empty() && s.base_url.back() == '/') s.base_url.pop_back();
  s.model = env_or("CHATSIM_OPENAI_MODEL", s.model);
  s.api_key = env_or("CHATSIM_OPENAI_API_KEY", env_or("OPENAI_API_KEY", ""));
  s.timeout_s = std::atof(env_or("CHATSIM_OPENAI_TIMEOUT_S", "30").c_str());
  if (s.timeout_s <= 0) s.timeout_s = 30;
  s.attempts = std::max(1, std::atoi(env_or("CHATSIM_OPENAI_ATTEMPTS", "3").c_str()));
  return s;
}

std::unique_ptr<Backend> make_openai_backend(OpenAiSettings settings) {
  return std::make_unique<OpenAiBackend>(std::move(settings));
}

}  // namespace chatsim::agents::llm
