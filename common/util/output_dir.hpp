#pragma once
// Where commands write: never over what they did not make.
//
// A folder a command writes as a whole (a rendered result, a scene, a folder of renders) must be
// new, empty, or one chatsim wrote before: such a folder holds a marker file (kOutputMarker)
// naming its kind. Anything else is refused before any work, with the path and the fix. The
// folder is written under a temporary name beside it and swapped in when complete, so it is
// whole or absent, and what it held before is removed only then, and only when it was chatsim's.
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>

namespace chatsim {

// A refused output path; the message names the path, what is wrong and the fix.
class OutputDirError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The file in every folder chatsim writes whole; its content names the folder's kind.
inline constexpr const char* kOutputMarker = ".chatsim-output";

// The kind ("result", "scene", ...) recorded in dir's marker, or nothing when dir has none.
std::optional<std::string> output_kind(const std::filesystem::path& dir);

// Checks, before any work, that `dir` may become an output folder of `kind`: it is absent (and
// its nearest existing parent a writable folder), empty, or chatsim's own of the same kind; with
// `force`, chatsim's own of any kind. `option` names the flag in messages (e.g. "--out").
// Returns the path with symbolic links resolved; throws OutputDirError otherwise.
std::filesystem::path check_output_dir(const std::filesystem::path& dir, const std::string& kind, bool force,
                                       const std::string& option = "--out");

// Throws OutputDirError when the output folder `dir` is `input` or holds it: replacing it would
// remove what the command reads (`input_option` names it in the message, e.g. "--scene").
void refuse_output_over_input(const std::filesystem::path& dir, const std::filesystem::path& input,
                              const std::string& option, const std::string& input_option);

// A folder written whole or not at all. The constructor checks the target (check_output_dir)
// and makes a fresh temporary folder beside it (<target>.part-<host>-<pid>-<n>); write into
// path(); commit() marks it and swaps it in. Not committed (an error, an exception), the
// temporary folder is removed; one a killed process left is removed by the next constructor for
// the same target.
class StagedOutputDir {
 public:
  StagedOutputDir(const std::filesystem::path& dir, std::string kind, bool force, std::string option = "--out");
  ~StagedOutputDir();
  StagedOutputDir(const StagedOutputDir&) = delete;
  StagedOutputDir& operator=(const StagedOutputDir&) = delete;

  const std::filesystem::path& path() const { return staging_; }   // where to write now
  const std::filesystem::path& target() const { return target_; }  // where it ends up
  // Checks the target again (files may have appeared there meanwhile: then the result stays in
  // path() and OutputDirError says so), then moves the folder into place.
  void commit();

 private:
  std::filesystem::path target_, staging_;
  std::string kind_, option_;
  bool force_ = false, done_ = false;
};

// A folder that receives outputs one by one (chat's rounds, a benchmark's work folder): checked
// as check_output_dir, then created with its marker if it is not chatsim's already. Returns the
// resolved path.
std::filesystem::path prepare_output_root(const std::filesystem::path& dir, const std::string& kind, bool force,
                                          const std::string& option);

// A file a command writes (a report, a model, an image): refused when the path is a folder or
// its folder cannot be written; its missing parent folders are created. Returns the path.
std::filesystem::path prepare_output_file(const std::filesystem::path& file, const std::string& option = "--out");

}  // namespace chatsim
