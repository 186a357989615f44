// The openai backend against a fake OpenAI-compatible server started by the test.
#include <gtest/gtest.h>

#include <atomic>
#include <thread>

#include <httplib.h>

#include "agents/llm/openai_backend.hpp"

using namespace chatsim::agents::llm;
using nlohmann::json;

namespace {

const Prompt& view_prompt() { return prompt_for("view"); }

json completion(const std::string& content) {
  return {{"choices", {{{"message", {{"role", "assistant"}, {"content", content}}}}}}};
}

// A server on an OS-chosen port whose answers the test scripts request by request.
class FakeServer {
 public:
  explicit FakeServer(std::function<void(int call, const httplib::Request&, httplib::Response&)> handler)
      : handler_(std::move(handler)) {
    server_.Post("/v1/chat/completions", [this](const httplib::Request& req, httplib::Response& res) {
      const int n = ++calls;
      last_auth = req.get_header_value("Authorization");
      last_body = req.body;
      handler_(n, req, res);
    });
    port_ = server_.bind_to_any_port("127.0.0.1");
    thread_ = std::thread([this] { server_.listen_after_bind(); });
    while (!server_.is_running()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ~FakeServer() {
    server_.stop();
    thread_.join();
  }
  OpenAiSettings settings(double timeout_s = 2) const {
    OpenAiSettings s;
    s.base_url = "http://127.0.0.1:" + std::to_string(port_) + "/v1";
    s.model = "fake-model";
    s.api_key = "sk-test-secret-key-1234";
    s.timeout_s = timeout_s;
    s.attempts = 3;
    return s;
  }
  std::atomic<int> calls{0};
  std::string last_auth, last_body;

 private:
  std::function<void(int, const httplib::Request&, httplib::Response&)> handler_;
  httplib::Server server_;
  int port_ = 0;
  std::thread thread_;
};

}  // namespace

TEST(OpenAiBackend, ValidAnswerWithKeyAndSchemaInTheRequest) {
  FakeServer server([](int, const httplib::Request&, httplib::Response& res) {
    res.set_content(completion(R"({"translation_m": [5, 0, 0]})").dump(), "application/json");
  });
  auto backend = make_openai_backend(server.settings());
  const auto out = backend->complete(view_prompt(), "move the view 5 m ahead");
  EXPECT_EQ(out["translation_m"][0], 5);
  EXPECT_EQ(server.last_auth, "Bearer sk-test-secret-key-1234");
  const auto body = json::parse(server.last_body);
  EXPECT_EQ(body["model"], "fake-model");
  EXPECT_EQ(body["response_format"]["type"], "json_schema");
  EXPECT_EQ(body["messages"][1]["content"], "move the view 5 m ahead");
}

TEST(OpenAiBackend, RetriesWithTheValidationErrorAfterASchemaViolation) {
  FakeServer server([](int call, const httplib::Request& req, httplib::Response& res) {
    if (call == 1) {
      res.set_content(completion(R"({"yaw_deg": "left"})").dump(), "application/json");
    } else {
      const bool told = req.body.find("Schema validation failed") != std::string::npos;
      res.set_content(completion(told ? R"({"yaw_deg": 30})" : "{}").dump(), "application/json");
    }
  });
  auto backend = make_openai_backend(server.settings());
  EXPECT_EQ(backend->complete(view_prompt(), "turn left 30 degrees")["yaw_deg"], 30);
  EXPECT_EQ(server.calls, 2);
}

TEST(OpenAiBackend, RetriesAfterInvalidJson) {
  FakeServer server([](int call, const httplib::Request&, httplib::Response& res) {
    res.set_content(completion(call == 1 ? "Sure! Here it is: {yaw" : R"({"yaw_deg": -15})").dump(), "application/json");
  });
  auto backend = make_openai_backend(server.settings());
  EXPECT_EQ(backend->complete(view_prompt(), "look right 15 degrees")["yaw_deg"], -15);
}

TEST(OpenAiBackend, ServerErrorsFailClearlyWithoutTheKey) {
  FakeServer server([](int, const httplib::Request&, httplib::Response& res) {
    res.status = 500;
    res.set_content("boom sk-test-secret-key-1234", "text/plain");
  });
  auto backend = make_openai_backend(server.settings());
  try {
    backend->complete(view_prompt(), "move up");
    FAIL() << "expected BackendError";
  } catch (const BackendError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("HTTP 500"), std::string::npos) << what;
    EXPECT_EQ(what.find("sk-test-secret"), std::string::npos) << what;
  }
  EXPECT_EQ(server.calls, 3);
}

TEST(OpenAiBackend, ClientErrorsFailAtOnceAndRedactTheKey) {
  FakeServer server([](int, const httplib::Request&, httplib::Response& res) {
    res.status = 401;
    res.set_content(R"({"error": "bad key sk-test-secret-key-1234"})", "application/json");
  });
  auto backend = make_openai_backend(server.settings());
  try {
    backend->complete(view_prompt(), "move up");
    FAIL() << "expected BackendError";
  } catch (const BackendError& e) {
    EXPECT_NE(std::string(e.what()).find("HTTP 401"), std::string::npos);
    EXPECT_EQ(std::string(e.what()).find("sk-test-secret"), std::string::npos) << e.what();
  }
  EXPECT_EQ(server.calls, 1);
}

TEST(OpenAiBackend, TimeoutsFailWithinTheBudget) {
  FakeServer server([](int, const httplib::Request&, httplib::Response& res) {
    std::this_thread::sleep_for(std::chrono::milliseconds(700));
    res.set_content(completion("{}").dump(), "application/json");
  });
  auto settings = server.settings(0.2);
  settings.attempts = 2;
  auto backend = make_openai_backend(settings);
  const auto t0 = std::chrono::steady_clock::now();
  try {
    backend->complete(view_prompt(), "move up");
    FAIL() << "expected BackendError";
  } catch (const BackendError& e) {
    EXPECT_NE(std::string(e.what()).find("failed"), std::string::npos) << e.what();
  }
  EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(3));
}

TEST(OpenAiBackend, NoServerIsAClearError) {
  OpenAiSettings s;
  s.base_url = "http://127.0.0.1:1/v1";
  s.timeout_s = 1;
  s.attempts = 1;
  auto backend = make_openai_backend(s);
  EXPECT_THROW(backend->complete(view_prompt(), "move up"), BackendError);
}
