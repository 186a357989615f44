// Output folders: written whole, never over what chatsim did not make.
#include "common/util/output_dir.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <iterator>

#include <gtest/gtest.h>

#include "tests/support/scratch_dir.hpp"

namespace chatsim {
namespace {
namespace fs = std::filesystem;

class OutputDir : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = scratch::dir() / ("output-dir-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(root_);
    fs::create_directories(root_);
  }
  static void write(const fs::path& file, const std::string& text) {
    fs::create_directories(file.parent_path());
    std::ofstream(file) << text;
  }
  static std::string read(const fs::path& file) {
    std::ifstream in(file);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }
  // Everything in the test's folder, so a left-behind temporary folder shows.
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(root_)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
  // Writes `file` into `dir` as a whole output of `kind`.
  static void write_output(const fs::path& dir, const std::string& kind, const std::string& file, bool force = false) {
    StagedOutputDir out(dir, kind, force);
    write(out.path() / file, file);
    out.commit();
  }
  fs::path root_;
};

TEST_F(OutputDir, ANewFolderIsWrittenWholeWithItsMarker) {
  const fs::path dir = root_ / "result";
  write_output(dir, "result", "video.mp4");
  EXPECT_EQ(read(dir / "video.mp4"), "video.mp4");
  EXPECT_EQ(output_kind(dir), "result");
  EXPECT_EQ(entries(), std::vector<std::string>{"result"});  // no temporary folder left
}

TEST_F(OutputDir, AFolderOfSomeoneElsesFilesIsRefusedAndKeptEvenWithForce) {
  const fs::path dir = root_ / "p";
  write(dir / "thesis.txt", "years of work");
  for (const bool force : {false, true}) {
    try {
      StagedOutputDir out(dir, "scene", force);
      FAIL() << "a folder chatsim did not write was accepted";
    } catch (const OutputDirError& e) {
      EXPECT_NE(std::string(e.what()).find(dir.string()), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("chatsim did not write it"), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(read(dir / "thesis.txt"), "years of work");
  EXPECT_EQ(entries(), std::vector<std::string>{"p"});
}

TEST_F(OutputDir, ItsOwnOutputOfTheSameKindIsReplaced) {
  const fs::path dir = root_ / "result";
  write_output(dir, "result", "first.png");
  write_output(dir, "result", "second.png");
  EXPECT_FALSE(fs::exists(dir / "first.png"));
  EXPECT_TRUE(fs::exists(dir / "second.png"));
  EXPECT_EQ(entries(), std::vector<std::string>{"result"});
}

TEST_F(OutputDir, ItsOwnOutputOfAnotherKindIsReplacedOnlyWithForce) {
  const fs::path dir = root_ / "x";
  write_output(dir, "scene", "scene.json");
  try {
    StagedOutputDir out(dir, "result", false);
    FAIL() << "a scene was about to be replaced by a result without --force";
  } catch (const OutputDirError& e) {
    EXPECT_NE(std::string(e.what()).find("--force"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::exists(dir / "scene.json"));
  write_output(dir, "result", "video.mp4", true);
  EXPECT_FALSE(fs::exists(dir / "scene.json"));
  EXPECT_EQ(output_kind(dir), "result");
}

TEST_F(OutputDir, AnEarlierChatsimResultWithoutMarkerIsReplacedOnlyWithForce) {
  const fs::path dir = root_ / "demo";
  write(dir / "result.json", R"({"video": "v.mp4", "seconds": {}, "reused": {}, "scene": "s"})");
  write(dir / "edit.json", "{}");
  EXPECT_THROW(StagedOutputDir(dir, "result", false), OutputDirError);
  EXPECT_THROW(StagedOutputDir(dir, "scene", true), OutputDirError);  // a result is not taken for a scene
  write_output(dir, "result", "video.mp4", true);
  EXPECT_FALSE(fs::exists(dir / "edit.json"));
}

TEST_F(OutputDir, AnEmptyFolderIsUsed) {
  const fs::path dir = root_ / "empty";
  fs::create_directories(dir);
  write_output(dir, "renders", "a.png");
  EXPECT_TRUE(fs::exists(dir / "a.png"));
}

TEST_F(OutputDir, AFileOrAFolderBelowAFileOrTheRootIsRefused) {
  write(root_ / "notes.txt", "x");
  EXPECT_THROW(check_output_dir(root_ / "notes.txt", "result", true), OutputDirError);
  EXPECT_THROW(check_output_dir(root_ / "notes.txt" / "out", "result", true), OutputDirError);
  EXPECT_THROW(check_output_dir("/", "result", true), OutputDirError);
  EXPECT_THROW(check_output_dir("", "result", true), OutputDirError);
  EXPECT_EQ(read(root_ / "notes.txt"), "x");
}

TEST_F(OutputDir, AnUnwritableParentIsRefusedBeforeAnyWork) {
  const fs::path locked = root_ / "locked";
  fs::create_directories(locked);
  fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read | fs::perms::group_exec |
                              fs::perms::others_read | fs::perms::others_exec);
  // Root writes anywhere: as root, the checks run in a child that has become nobody.
  const auto refused = [&] {
    int n = 0;
    try {
      check_output_dir(locked / "out", "result", false);
    } catch (const OutputDirError&) {
      ++n;
    }
    try {
      prepare_output_file(locked / "report.json");
    } catch (const OutputDirError&) {
      ++n;
    }
    return n;
  };
  if (::geteuid() != 0) {
    EXPECT_EQ(refused(), 2);
  } else {
    const pid_t child = ::fork();
    if (child == 0) _exit(::setgid(65534) == 0 && ::setuid(65534) == 0 ? refused() : 99);
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 2) << "99: could not become nobody";
  }
  fs::permissions(locked, fs::perms::owner_all);
  EXPECT_TRUE(fs::is_empty(locked));
}

TEST_F(OutputDir, NotCommittedLeavesNothingBehind) {
  {
    StagedOutputDir out(root_ / "result", "result", false);
    write(out.path() / "frames" / "a.png", "a");
  }
  EXPECT_TRUE(entries().empty());
}

TEST_F(OutputDir, WhatAKilledRunLeftIsRemovedAndNothingElse) {
  const fs::path dir = root_ / "result";
  std::string left;
  {
    StagedOutputDir out(dir, "result", false);
    left = out.path().filename().string();  // result.part-<host>-<pid>-0
  }
  const pid_t gone = ::fork();
  if (gone == 0) _exit(0);
  ::waitpid(gone, nullptr, 0);
  const std::string mine = "-" + std::to_string(::getpid()) + "-0";
  const std::string dead = left.substr(0, left.size() - mine.size()) + "-" + std::to_string(gone) + "-0";
  fs::create_directories(root_ / dead);
  std::ofstream(root_ / dead / ".chatsim-staging") << "x";
  write(root_ / dead / "frames" / "a.png", "a");
  const std::string alive = left;  // this process: still running
  fs::create_directories(root_ / alive);
  std::ofstream(root_ / alive / ".chatsim-staging") << "x";
  const std::string unmarked = left.substr(0, left.size() - mine.size()) + "-" + std::to_string(gone) + "-1";
  write(root_ / unmarked / "thesis.txt", "x");
  const std::string other_name = "results.part-x-" + std::to_string(gone) + "-0";
  write(root_ / other_name / ".chatsim-staging", "x");
  write_output(dir, "result", "video.mp4");
  std::vector<std::string> expected{"result", alive, unmarked, other_name};
  std::sort(expected.begin(), expected.end());  // as entries() lists them (pids decide the order)
  EXPECT_EQ(entries(), expected);
}

TEST_F(OutputDir, FilesThatAppearWhileItRunsAreNotRemovedAndTheResultIsKept) {
  const fs::path dir = root_ / "result";
  StagedOutputDir out(dir, "result", true);
  write(out.path() / "video.mp4", "v");
  write(dir / "thesis.txt", "years of work");  // the user, meanwhile
  try {
    out.commit();
    FAIL() << "commit went over a folder that filled meanwhile";
  } catch (const OutputDirError& e) {
    EXPECT_NE(std::string(e.what()).find(out.path().string()), std::string::npos) << e.what();
  }
  EXPECT_EQ(read(dir / "thesis.txt"), "years of work");
  EXPECT_TRUE(fs::exists(out.path() / "video.mp4"));
}

TEST_F(OutputDir, ALinkToItsOwnOutputReplacesWhatItPointsToAndStaysALink) {
  const fs::path real = root_ / "real", link = root_ / "link";
  write_output(real, "result", "first.png");
  fs::create_directory_symlink(real, link);
  write_output(link, "result", "second.png");
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_TRUE(fs::exists(real / "second.png"));
  EXPECT_FALSE(fs::exists(real / "first.png"));
}

TEST_F(OutputDir, DotsInThePathAreResolvedBeforeDeciding) {
  write(root_ / "mine" / "thesis.txt", "x");
  EXPECT_THROW(check_output_dir(root_ / "other" / ".." / "mine", "result", true), OutputDirError);
  EXPECT_THROW(check_output_dir(root_ / "mine" / ".", "result", true), OutputDirError);
  EXPECT_EQ(check_output_dir(root_ / "mine" / ".." / "new", "result", false), root_ / "new");
}

TEST_F(OutputDir, AnOutputRootIsMadeWithItsMarkerAndKeepsItsRounds) {
  const fs::path dir = root_ / "chat";
  EXPECT_EQ(prepare_output_root(dir, "rounds", false, "--out-root"), dir);
  EXPECT_EQ(output_kind(dir), "rounds");
  write_output(dir / "round-1", "result", "video.mp4");
  prepare_output_root(dir, "rounds", false, "--out-root");
  EXPECT_TRUE(fs::exists(dir / "round-1" / "video.mp4"));
  write(root_ / "home" / "thesis.txt", "x");
  EXPECT_THROW(prepare_output_root(root_ / "home", "rounds", true, "--out-root"), OutputDirError);
  EXPECT_FALSE(fs::exists(root_ / "home" / kOutputMarker));
}

TEST_F(OutputDir, AnOutputFileMayNotBeAFolderAndGetsItsParentFolders) {
  write(root_ / "dir" / "thesis.txt", "x");
  EXPECT_THROW(prepare_output_file(root_ / "dir"), OutputDirError);
  EXPECT_THROW(prepare_output_file(root_ / "dir" / "thesis.txt" / "r.json"), OutputDirError);
  EXPECT_EQ(prepare_output_file(root_ / "a" / "b" / "r.json"), root_ / "a" / "b" / "r.json");
  EXPECT_TRUE(fs::is_directory(root_ / "a" / "b"));
  EXPECT_EQ(read(root_ / "dir" / "thesis.txt"), "x");
}

}  // namespace
}  // namespace chatsim
