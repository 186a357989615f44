#include "common/util/output_dir.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <system_error>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/util/path_policy.hpp"

namespace chatsim {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// What a would-be output folder holds now.
enum class Holds { Nothing, EmptyFolder, OwnSameKind, OwnOtherKind, EarlierResult, Foreign, NotAFolder };

struct Inspection {
  Holds holds = Holds::Nothing;
  std::string kind;  // the marker's kind (OwnSameKind, OwnOtherKind)
};

std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

std::optional<json> read_json(const fs::path& file) {
  std::ifstream in(file);
  if (!in) return std::nullopt;
  try {
    return json::parse(in);
  } catch (const json::exception&) {
    return std::nullopt;
  }
}

// A rendered result of a chatsim from before the marker: result.json says what chatsim run
// writes (the video, the stages' times) and edit.json is beside it.
bool is_earlier_result(const fs::path& dir) {
  if (!fs::is_regular_file(dir / "edit.json")) return false;
  const auto r = read_json(dir / "result.json");
  return r && r->is_object() && r->contains("video") && r->contains("seconds") && r->contains("reused");
}

Inspection inspect(const fs::path& p, const std::string& kind) {
  std::error_code ec;
  const auto st = fs::symlink_status(p, ec);
  if (ec || !fs::exists(st)) return {Holds::Nothing, ""};
  if (!fs::is_directory(st)) return {Holds::NotAFolder, ""};
  if (fs::is_empty(p, ec) && !ec) return {Holds::EmptyFolder, ""};
  if (const auto k = output_kind(p)) return {*k == kind ? Holds::OwnSameKind : Holds::OwnOtherKind, *k};
  if (kind == "result" && is_earlier_result(p)) return {Holds::EarlierResult, "result"};
  return {Holds::Foreign, ""};
}

// Why nothing can be written at or below `p`, if so: the nearest folder that exists must be
// one this process may write in.
std::optional<std::string> unwritable(const fs::path& p) {
  fs::path a = p;
  std::error_code ec;
  while (!fs::exists(fs::symlink_status(a, ec)) && a.has_relative_path()) a = a.parent_path();
  if (!fs::is_directory(a, ec)) return quoted(a) + " is a file, so no folder can be made below it";
  if (::access(a.c_str(), W_OK | X_OK) != 0)
    return "cannot write in " + quoted(a) + " (" + std::strerror(errno) + ")";
  return std::nullopt;
}

// The path as the file system will see it: absolute, "." and ".." gone, symbolic links of the
// part that exists followed, no trailing separator.
fs::path resolve(const fs::path& dir, const std::string& option) {
  if (dir.empty()) throw OutputDirError(option + ": no path given");
  std::error_code ec;
  fs::path p = fs::weakly_canonical(fs::absolute(dir), ec);
  if (ec) throw OutputDirError(option + " " + quoted(dir) + ": " + ec.message());
  if (!p.has_filename() && p.has_relative_path()) p = p.parent_path();
  if (!p.has_relative_path()) throw OutputDirError(option + " " + quoted(p) + ": the file system's root cannot be an output folder");
  return p;
}

// The refusal for what `p` holds, if it may not become an output of `kind`.
std::optional<std::string> refusal(const fs::path& p, const Inspection& in, const std::string& kind, bool force,
                                   const std::string& option) {
  const std::string head = option + " " + quoted(p);
  switch (in.holds) {
    case Holds::Nothing:
    case Holds::EmptyFolder:
    case Holds::OwnSameKind:
      return std::nullopt;
    case Holds::OwnOtherKind:
      if (force) return std::nullopt;
      return head + " holds a chatsim " + in.kind + ", not a " + kind + ": pass --force to replace it, or choose another folder";
    case Holds::EarlierResult:
      if (force) return std::nullopt;
      return head + " looks like a result of an earlier chatsim (result.json and edit.json, but no " + kOutputMarker +
             " marker): pass --force to replace it, or choose another folder";
    case Holds::NotAFolder:
      return head + " is a file, not a folder: choose a folder path";
    case Holds::Foreign:
      break;
  }
  return head + " is not empty and chatsim did not write it (it has no " + kOutputMarker +
         " marker): nothing was changed. Choose a new or empty folder, or remove this one yourself if it holds nothing "
         "you need (--force replaces only chatsim's own outputs)";
}

void write_marker(const fs::path& dir, const std::string& kind) {
  std::ofstream out(dir / kOutputMarker);
  out << json{{"written_by", "chatsim"}, {"kind", kind}}.dump() << "\n";
  if (!out) throw OutputDirError("cannot write " + quoted(dir / kOutputMarker));
}

// Marks a folder being written beside its target, so that one a killed process left can be
// told from anything else there.
constexpr const char* kStagingMarker = ".chatsim-staging";

std::string host_name() {
  char name[256] = {};
  ::gethostname(name, sizeof name - 1);
  return name;
}

// How this host's folders beside `target` begin ("<target>.<tag>-<host>-"), before "<pid>-<n>".
std::string sibling_prefix(const fs::path& target, const std::string& tag) {
  return target.filename().string() + "." + tag + "-" + host_name() + "-";
}

// A new folder beside `target`, marked; mkdir never takes over an existing name.
fs::path make_sibling(const fs::path& target, const std::string& tag) {
  fs::create_directories(target.parent_path());
  for (int n = 0; n < 1000; ++n) {
    const fs::path p = target.parent_path() / (sibling_prefix(target, tag) + std::to_string(::getpid()) + "-" + std::to_string(n));
    if (::mkdir(p.c_str(), 0777) == 0) {
      std::ofstream(p / kStagingMarker) << "a folder chatsim writes; removed when done\n";
      return p;
    }
    if (errno != EEXIST) throw OutputDirError("cannot make a folder beside " + quoted(target) + ": " + std::strerror(errno));
  }
  throw OutputDirError("cannot make a folder beside " + quoted(target) + ": 1000 names taken");
}

// Removes the marked folders beside `target` that a process of this host made and left when it
// was killed (its pid is gone); nothing else.
void reap_abandoned(const fs::path& target) {
  std::error_code ec;
  std::vector<fs::path> abandoned;
  for (const auto& e : fs::directory_iterator(target.parent_path(), ec)) {
    const std::string name = e.path().filename().string();
    for (const char* tag : {"part", "old"}) {
      const std::string prefix = sibling_prefix(target, tag);
      if (name.rfind(prefix, 0) != 0) continue;
      const long pid = std::strtol(name.c_str() + prefix.size(), nullptr, 10);
      const bool gone = pid > 0 && ::kill(pid_t(pid), 0) != 0 && errno == ESRCH;
      if (gone && fs::is_regular_file(e.path() / kStagingMarker, ec)) abandoned.push_back(e.path());
    }
  }
  for (const auto& p : abandoned) fs::remove_all(p, ec);
}

// Puts `fresh` where `old` (chatsim's own folder) is, then removes what `old` held. On failure
// `old` is where it was and `fresh` untouched.
void replace_own(const fs::path& fresh, const fs::path& old) {
  std::error_code ignored;  // the new folder is in place: failing to remove the old one loses nothing
  // One atomic swap where the file system has it: the target is never absent.
  if (::renameat2(AT_FDCWD, fresh.c_str(), AT_FDCWD, old.c_str(), RENAME_EXCHANGE) == 0) {
    fs::remove_all(fresh, ignored);
    return;
  }
  const fs::path aside = make_sibling(old, "old");
  fs::rename(old, aside / "old");
  try {
    fs::rename(fresh, old);
  } catch (const fs::filesystem_error&) {
    fs::rename(aside / "old", old);
    fs::remove_all(aside, ignored);
    throw;
  }
  fs::remove_all(aside, ignored);
}

}  // namespace

std::optional<std::string> output_kind(const fs::path& dir) {
  const auto m = read_json(dir / kOutputMarker);
  if (!m || !m->is_object() || m->value("written_by", "") != "chatsim" || !(*m)["kind"].is_string()) return std::nullopt;
  return (*m)["kind"].get<std::string>();
}

namespace {

// check_output_dir, also saying what the folder holds.
std::pair<fs::path, Inspection> checked(const fs::path& dir, const std::string& kind, bool force, const std::string& option) {
  const fs::path p = resolve(dir, option);
  const Inspection in = inspect(p, kind);
  if (auto why = refusal(p, in, kind, force, option)) throw OutputDirError(*why);
  // Written beside the target and renamed: its parent must be writable, and the target itself
  // when what it holds is to be removed.
  if (auto why = unwritable(p.parent_path())) throw OutputDirError(option + " " + quoted(p) + ": " + *why);
  if (in.holds != Holds::Nothing)
    if (auto why = unwritable(p)) throw OutputDirError(option + " " + quoted(p) + ": " + *why);
  return {p, in};
}

}  // namespace

fs::path check_output_dir(const fs::path& dir, const std::string& kind, bool force, const std::string& option) {
  return checked(dir, kind, force, option).first;
}

void refuse_output_over_input(const fs::path& dir, const fs::path& input, const std::string& option,
                              const std::string& input_option) {
  if (dir.empty() || input.empty()) return;
  const fs::path out = resolve(dir, option), in = resolve(input, input_option);
  const fs::path rel = in.lexically_relative(out);
  if (!rel.empty() && stays_inside(rel))
    throw OutputDirError(option + " " + quoted(out) + " holds " + input_option + " " + quoted(in) +
                         ": writing there would remove what the command reads; choose another folder");
}

StagedOutputDir::StagedOutputDir(const fs::path& dir, std::string kind, bool force, std::string option)
    : kind_(std::move(kind)), option_(std::move(option)), force_(force) {
  target_ = check_output_dir(dir, kind_, force_, option_);
  reap_abandoned(target_);
  staging_ = make_sibling(target_, "part");
}

StagedOutputDir::~StagedOutputDir() {
  if (done_) return;
  std::error_code ignored;  // never throw from here; the folder is ours to remove
  fs::remove_all(staging_, ignored);
}

void StagedOutputDir::commit() {
  if (done_) throw OutputDirError(quoted(target_) + " was committed already");
  fs::remove(staging_ / kStagingMarker);
  write_marker(staging_, kind_);
  const Inspection in = inspect(target_, kind_);
  if (auto why = refusal(target_, in, kind_, force_, option_)) {
    done_ = true;  // keep the work: it is the user's result
    throw OutputDirError(*why + " (it changed while the command ran; the result is kept in " + quoted(staging_) + ")");
  }
  done_ = true;  // from here on the work is kept, whatever happens
  try {
    if (in.holds == Holds::Nothing || in.holds == Holds::EmptyFolder) fs::rename(staging_, target_);
    else replace_own(staging_, target_);
  } catch (const std::exception& e) {
    throw OutputDirError("cannot move the result into " + quoted(target_) + " (" + e.what() + "); it is kept in " +
                         quoted(staging_));
  }
}

fs::path prepare_output_root(const fs::path& dir, const std::string& kind, bool force, const std::string& option) {
  const auto [p, in] = checked(dir, kind, force, option);
  if (in.holds == Holds::OwnSameKind) return p;
  if (in.holds == Holds::Nothing || in.holds == Holds::EmptyFolder) {
    fs::create_directories(p);
    write_marker(p, kind);
    return p;
  }
  StagedOutputDir fresh(p, kind, force, option);  // --force: chatsim's other output, replaced by an empty root
  fresh.commit();
  return p;
}

fs::path prepare_output_file(const fs::path& file, const std::string& option) {
  if (file.empty()) throw OutputDirError(option + ": no file given");
  const fs::path p = fs::absolute(file).lexically_normal();
  std::error_code ec;
  if (!p.has_filename() || fs::is_directory(p, ec))
    throw OutputDirError(option + " " + quoted(p) + " is a folder: give the path of a file (in it, or anywhere else)");
  if (auto why = unwritable(p.parent_path())) throw OutputDirError(option + " " + quoted(p) + ": " + *why);
  if (fs::exists(p, ec) && ::access(p.c_str(), W_OK) != 0)
    throw OutputDirError(option + " " + quoted(p) + ": cannot replace it (" + std::strerror(errno) + ")");
  fs::create_directories(p.parent_path());
  return p;
}

}  // namespace chatsim
