// chatsim serve: a local web page where a user chats with the system and watches each round's
// video. One worker thread owns the conversation (the bus node is single-threaded); the HTTP
// handlers only queue commands and read its status.
#include <condition_variable>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <mutex>
#include <thread>

#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include "common/scene/scene.hpp"
#include "common/util/exit_codes.hpp"
#include "common/util/log.hpp"
#include "common/util/output_dir.hpp"
#include "common/util/signals.hpp"
#include "processes/cli/chat_page.hpp"
#include "processes/cli/chat_session.hpp"
#include "processes/cli/commands.hpp"

// Last: <resolv.h> (through httplib) defines a macro `_res` that Eigen's headers use as a name.
#include <httplib.h>

namespace chatsim::cli {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;

struct ServeArgs {
  std::string scene, out_root = "output/serve", bus, host = "127.0.0.1", port_file;
  int port = 8080;
  double timeout_s = 6 * 3600;
  bool force = false;
};

class ChatServer {
 public:
  ChatServer(const ServeArgs& a, std::string scene) : a_(a), scene_(std::move(scene)) {}

  void worker(const std::atomic<bool>& stop) {
    try {
      ChatSession session(a_.bus, scene_, "", [this](const std::string& stage, double f, const std::string& m) {
        std::lock_guard lock(mu_);
        stage_ = stage, fraction_ = f, message_ = m;
      });
      {
        std::lock_guard lock(mu_);
        ready_ = true;
      }
      while (!stop) {
        std::string command;
        {
          std::unique_lock lock(mu_);
          cv_.wait_for(lock, std::chrono::milliseconds(200), [&] { return !queue_.empty(); });
          if (queue_.empty()) continue;
          command = queue_;
          queue_.clear();
        }
        const int n = int(rounds_.size()) + 1;
        const fs::path out = fs::absolute(fs::path(a_.out_root) / ("round-" + std::to_string(n)));
        const auto r = session.round(command, out.string(), a_.timeout_s, "", a_.force);
        json round{{"command", command}, {"ok", r.ok}, {"message", r.message}};
        if (r.ok && !r.output_dir.empty()) {
          round["result"] = "/results/round-" + std::to_string(n);
          round["preview"] = preview_of(r.output_dir);
        }
        std::lock_guard lock(mu_);
        rounds_.push_back(round);
        busy_ = false;
        if (session.lost()) break;
      }
    } catch (const std::exception& e) {
      spdlog::error("{}", e.what());
      std::lock_guard lock(mu_);
      rounds_.push_back({{"command", ""}, {"ok", false}, {"message", std::string("the agents are not available: ") + e.what()}});
      busy_ = false;
    }
  }

  void routes(httplib::Server& srv) {
    srv.Get("/", [](const httplib::Request&, httplib::Response& res) { res.set_content(kChatPage, "text/html; charset=utf-8"); });
    srv.Get("/api/status", [this](const httplib::Request&, httplib::Response& res) {
      std::lock_guard lock(mu_);
      const json s{{"scene", fs::path(scene_).filename().string()}, {"ready", ready_}, {"busy", busy_}, {"stage", stage_},
                   {"fraction", fraction_}, {"message", message_}, {"rounds", rounds_}};
      res.set_content(s.dump(), "application/json");
    });
    srv.Post("/api/chat", [this](const httplib::Request& req, httplib::Response& res) {
      json body;
      try {
        body = json::parse(req.body);
      } catch (const json::parse_error&) {
        res.status = 400;
        res.set_content(json{{"error", "the body must be JSON: {\"command\": \"...\"}"}}.dump(), "application/json");
        return;
      }
      const std::string command = body.value("command", std::string());
      std::lock_guard lock(mu_);
      if (command.empty() || command.size() > 10000) {
        res.status = 400;
        res.set_content(json{{"error", "give a command of 1 to 10000 characters"}}.dump(), "application/json");
        return;
      }
      if (busy_) {
        res.status = 409;
        res.set_content(json{{"error", "still working on the previous command"}}.dump(), "application/json");
        return;
      }
      busy_ = true;
      stage_ = "decisions", fraction_ = 0, message_ = "queued";
      queue_ = command;
      cv_.notify_one();
      res.set_content(json{{"queued", command}}.dump(), "application/json");
    });
    // Results: only files under the output root, by relative path.
    srv.Get(R"(/results/(round-\d+)/(.+))", [this](const httplib::Request& req, httplib::Response& res) {
      const fs::path root = fs::absolute(a_.out_root).lexically_normal();
      const fs::path file = (root / std::string(req.matches[1]) / std::string(req.matches[2])).lexically_normal();
      if (file.string().rfind(root.string(), 0) != 0 || !fs::is_regular_file(file)) {
        res.status = 404;
        return;
      }
      const std::string ext = file.extension().string();
      const char* type = ext == ".mp4" ? "video/mp4" : ext == ".png" ? "image/png" : ext == ".json" ? "application/json" : "text/plain";
      std::ifstream in(file, std::ios::binary);
      res.set_content(std::string(std::istreambuf_iterator<char>(in), {}), type);
    });
  }

 private:
  // A frame from the middle of the clip, front camera if there is one.
  static std::string preview_of(const fs::path& result) {
    std::vector<fs::path> cams;
    for (const auto& d : fs::directory_iterator(result / "frames")) cams.push_back(d.path());
    if (cams.empty()) return "";
    std::sort(cams.begin(), cams.end());
    fs::path cam = cams.front();
    for (const auto& c : cams)
      if (c.filename() == "front" || c.filename() == "CAM_FRONT") cam = c;
    std::vector<fs::path> frames;
    for (const auto& f : fs::directory_iterator(cam)) frames.push_back(f.path());
    std::sort(frames.begin(), frames.end());
    return frames.empty() ? "" : fs::relative(frames[frames.size() / 2], result).string();
  }

  ServeArgs a_;
  std::string scene_;
  std::mutex mu_;
  std::condition_variable cv_;
  std::string queue_;
  bool ready_ = false, busy_ = false;
  std::string stage_, message_;
  double fraction_ = 0;
  json rounds_ = json::array();
};

int run_serve(const ServeArgs& a) {
  init_logging("serve");
  const std::string scene = fs::absolute(a.scene).lexically_normal().string();
  try {
    const auto s = scene::load_scene(scene);
    if (s.layout_only) {
      spdlog::error("{} is a layout-only scene: nothing to render", scene);
      return exit_code::kUsage;
    }
  } catch (const scene::SceneError& e) {
    spdlog::error("{}", e.what());
    return exit_code::kUsage;
  }
  try {
    prepare_rounds_root(a.out_root, scene, a.force);  // before any process starts
  } catch (const OutputDirError& e) {
    spdlog::error("{}", e.what());
    return exit_code::kUsage;
  }
  const auto& stop = install_stop_signals();
  ChatServer chat(a, scene);
  std::thread worker([&] { chat.worker(stop); });
  httplib::Server srv;
  chat.routes(srv);
  const int port = a.port == 0 ? srv.bind_to_any_port(a.host) : (srv.bind_to_port(a.host, a.port) ? a.port : -1);
  if (port < 0) {
    spdlog::error("cannot listen on {}:{} (in use? try --port 0)", a.host, a.port);
    return exit_code::kUsage;
  }
  if (!a.port_file.empty()) std::ofstream(a.port_file) << port << "\n";
  std::cerr << "chatsim serve: open http://" << a.host << ":" << port << "/ (Ctrl-C stops)" << std::endl;
  std::thread http([&] { srv.listen_after_bind(); });
  while (!stop) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  srv.stop();
  http.join();
  worker.join();
  return exit_code::kOk;
}

}  // namespace

void add_serve_command(CLI::App& app, int& result) {
  auto a = std::make_shared<ServeArgs>();
  auto* cmd = app.add_subcommand("serve", "A local web page to chat with the system and watch each result's video "
                                          "(starts the agent processes when no bus runs; Ctrl-C stops everything)");
  cmd->add_option("--scene", a->scene, "scene directory (with images)")->required();
  cmd->add_option("--port", a->port, "port on 127.0.0.1 (0: any free one)")->check(CLI::Range(0, 65535));
  cmd->add_option("--host", a->host, "address to listen on");
  cmd->add_option("--port-file", a->port_file, "write the chosen port here");
  cmd->add_option("--out-root", a->out_root, kRoundsRootHelp)->capture_default_str();
  cmd->add_flag("--force", a->force, kForceHelp);
  cmd->add_option("--bus", a->bus, "use this running bus instead of starting processes");
  cmd->callback([a, &result] { result = run_serve(*a); });
}

}  // namespace chatsim::cli
