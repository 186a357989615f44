// Every chatsim command that writes somewhere (--out, --out-root, --save, --save-views, --work,
// --chart, bag record's --output), pointed at a folder of someone else's files: refused before any
// work with exit 2 and a message naming the path, every file kept, nothing left beside it. And a
// folder chatsim wrote is replaced by the same command.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "tests/support/subprocess.hpp"

using namespace chatsim;
using namespace std::chrono_literals;
using test_support::bin;
using test_support::ScopedProcess;
namespace fs = std::filesystem;

namespace {

struct Outcome {
  int code = -1;
  std::string said;  // stdout and stderr
};

class Outputs : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = new fs::path(test_support::temp_path("outputs-test"));
    fs::create_directories(*root_);
    ASSERT_EQ(chatsim({"scene", "demo", "--out", scene(), "--preset", "small", "--frames", "2", "--no-plates", "--no-views"}).code, 0);
    ASSERT_EQ(chatsim({"scene", "demo", "--layout-only", "--out", (*root_ / "layout").string()}).code, 0);
  }
  static void TearDownTestSuite() {
    fs::remove_all(*root_);
    delete root_;
  }
  static std::string scene() { return (*root_ / "scene").string(); }

  // Runs chatsim (or another of the build's programs) with `args` (stdin empty), within 60 s.
  static Outcome chatsim(std::vector<std::string> args, const std::string& program = "chatsim") {
    static int n = 0;
    const fs::path log = *root_ / ("log-" + std::to_string(++n));
    args.insert(args.begin(), bin(program));
    std::string cmd;
    for (const auto& a : args) cmd += "'" + a + "' ";
    ScopedProcess p(test_support::spawn({"/bin/sh", "-c", cmd + "< /dev/null > " + log.string() + " 2>&1"}));
    const auto status = p.wait(60s);
    Outcome o;
    o.said = test_support::read_file(log);
    if (status && WIFEXITED(*status)) o.code = WEXITSTATUS(*status);
    return o;
  }

  // A folder holding a user's file, named after the test.
  static fs::path users_folder(const std::string& name) {
    const fs::path dir = *root_ / name;
    fs::create_directories(dir);
    std::ofstream(dir / "thesis.txt") << "years of work";
    return dir;
  }

  // `args` with {out} replaced by a folder of the user's: refused, kept, nothing beside it.
  static void expect_refused(const std::string& name, std::vector<std::string> args, const std::string& program = "chatsim") {
    SCOPED_TRACE(name);
    const fs::path dir = users_folder(name);
    for (auto& a : args) a = std::regex_replace(a, std::regex("\\{out\\}"), dir.string());
    const Outcome o = chatsim(args, program);
    EXPECT_EQ(o.code, 2) << o.said;
    EXPECT_NE(o.said.find(dir.string()), std::string::npos) << "the message should name the folder: " << o.said;
    EXPECT_EQ(test_support::read_file(dir / "thesis.txt"), "years of work");
    std::vector<std::string> inside;
    for (const auto& e : fs::directory_iterator(dir)) inside.push_back(e.path().filename().string());
    EXPECT_EQ(inside, std::vector<std::string>{"thesis.txt"});
    for (const auto& e : fs::directory_iterator(*root_))
      EXPECT_NE(e.path().filename().string().rfind(name + ".", 0), 0u) << "left beside it: " << e.path();
  }

  static fs::path* root_;
};
fs::path* Outputs::root_ = nullptr;

TEST_F(Outputs, SceneCommandsRefuseAFolderOfSomeoneElsesFiles) {
  expect_refused("demo-layout", {"scene", "demo", "--layout-only", "--out", "{out}"});
  expect_refused("demo-render", {"scene", "demo", "--preset", "small", "--out", "{out}", "--force"});
  expect_refused("import-nuscenes", {"scene", "import", "nuscenes", "--dataroot", scene(), "--scene", "s", "--out", "{out}"});
}

TEST_F(Outputs, RenderingCommandsRefuseAFolderOfSomeoneElsesFiles) {
  expect_refused("run", {"run", "--scene", scene(), "--out", "{out}", "--force", "Remove all cars"});
  expect_refused("chat", {"chat", "--scene", scene(), "--out-root", "{out}"});
  expect_refused("serve", {"serve", "--scene", scene(), "--out-root", "{out}", "--port", "0"});
  expect_refused("render", {"render", "--model", scene() + "/scene.json", "--scene", scene(), "--out", "{out}"});
  expect_refused("train", {"train", "--scene", scene(), "--out", "{out}"});
  expect_refused("light-estimate", {"light", "estimate", "--scene", scene(), "--out", "{out}"});
  expect_refused("asset-preview", {"asset", "preview", "sedan", "--out", "{out}"});
}

TEST_F(Outputs, EvaluationsRefuseAFolderOfSomeoneElsesFiles) {
  const std::string model = scene() + "/scene.json";  // never read: the output is checked first
  expect_refused("eval-nvs-save", {"eval", "nvs", "--scene", scene(), "--model", model, "--save", "{out}"});
  expect_refused("eval-light-out", {"eval", "light", "--scene", scene(), "--out", "{out}"});
  expect_refused("eval-light-views", {"eval", "light", "--scene", scene(), "--save-views", "{out}"});
  expect_refused("eval-deletion-out", {"eval", "deletion", "--scene", scene(), "--out", "{out}"});
  expect_refused("eval-deletion-save", {"eval", "deletion", "--scene", scene(), "--save", "{out}"});
  const fs::path cases = *root_ / "cases.jsonl";
  std::ofstream(cases) << "\n";
  const std::string layout = (*root_ / "layout").string();
  expect_refused("eval-commands-out", {"eval", "commands", "--cases", cases.string(), "--scene", layout, "--out", "{out}"});
  expect_refused("eval-commands-chart", {"eval", "commands", "--cases", cases.string(), "--scene", layout, "--chart", "{out}"});
}

TEST_F(Outputs, BenchmarksRefuseAFolderOfSomeoneElsesFiles) {
  const std::string hdri = scene() + "/scene.json";  // an existing file: the output is checked first
  expect_refused("bench-foreground", {"bench", "foreground", "--out", "{out}"});
  expect_refused("bench-light-out", {"bench", "light", "--hdri", hdri, "--out", "{out}"});
  expect_refused("bench-light-views", {"bench", "light", "--hdri", hdri, "--save-views", "{out}"});
  expect_refused("bench-deletion-out", {"bench", "deletion", "--scene", scene(), "--out", "{out}"});
  expect_refused("bench-deletion-save", {"bench", "deletion", "--scene", scene(), "--save", "{out}"});
  expect_refused("bench-nvs", {"bench", "nvs", "--scene", scene(), "--out", "{out}"});
  expect_refused("bench-e2e-out", {"bench", "e2e", "--scene", scene(), "--out", "{out}"});
  expect_refused("bench-e2e-work", {"bench", "e2e", "--scene", scene(), "--work", "{out}"});
  expect_refused("bench-bus", {"bench", "bus", "--out", "{out}"});
  expect_refused("bench-bag", {"bench", "bag", "--out", "{out}"});
  expect_refused("soak", {"--count", "1", "--out", "{out}"}, "chatsim-soak");
}

TEST_F(Outputs, BagRecordRefusesAFolderAFileThatIsNoRecordingAndAnInterruptedOne) {
  const std::vector<std::string> record = {"bag", "record", "--all", "--duration-s", "0.1", "--bus", "tcp://127.0.0.1:1", "-o"};
  auto with = [&](const std::string& out) {
    auto args = record;
    args.push_back(out);
    return args;
  };
  expect_refused("bag-record", with("{out}"));
  const fs::path notes = *root_ / "notes.mcap";
  std::ofstream(notes) << "not a recording";
  Outcome o = chatsim(with(notes.string()));
  EXPECT_EQ(o.code, 2) << o.said;
  o = chatsim([&] { auto a = with(notes.string()); a.push_back("--force"); return a; }());
  EXPECT_EQ(o.code, 2) << o.said;
  EXPECT_EQ(test_support::read_file(notes), "not a recording");
  const fs::path part = *root_ / "crashed.mcap.part";
  std::ofstream(part) << "chunks a crashed recorder wrote";
  o = chatsim(with((*root_ / "crashed.mcap").string()));
  EXPECT_EQ(o.code, 2) << o.said;
  EXPECT_NE(o.said.find("interrupted"), std::string::npos) << o.said;
  EXPECT_EQ(test_support::read_file(part), "chunks a crashed recorder wrote");
}

TEST_F(Outputs, AFolderChatsimWroteIsReplacedAndAnotherKindOnlyWithForce) {
  const fs::path dir = *root_ / "again";
  ASSERT_EQ(chatsim({"scene", "demo", "--layout-only", "--out", dir.string(), "--seed", "1"}).code, 0);
  const std::string first = test_support::read_file(dir / "objects.json");
  ASSERT_EQ(chatsim({"scene", "demo", "--layout-only", "--out", dir.string(), "--seed", "2"}).code, 0);
  EXPECT_NE(test_support::read_file(dir / "objects.json"), first);
  // A scene is not a result: run refuses it (before any process starts) unless --force.
  const Outcome o = chatsim({"run", "--scene", scene(), "--out", dir.string(), "Remove all cars"});
  EXPECT_EQ(o.code, 2) << o.said;
  EXPECT_NE(o.said.find("--force"), std::string::npos) << o.said;
  EXPECT_TRUE(fs::exists(dir / "scene.json"));
  // Nor may a result replace the scene it renders, or a folder holding it, even with --force.
  const fs::path rendered = *root_ / "rendered", copy = rendered / "scene";
  fs::create_directories(rendered);
  fs::copy(scene(), copy, fs::copy_options::recursive);
  for (const fs::path& out : {copy, rendered}) {
    const Outcome over = chatsim({"run", "--scene", copy.string(), "--out", out.string(), "--force", "Remove all cars"});
    EXPECT_EQ(over.code, 2) << over.said;
    EXPECT_NE(over.said.find("remove what the command reads"), std::string::npos) << over.said;
    EXPECT_TRUE(fs::exists(copy / "scene.json"));
  }
}

}  // namespace
