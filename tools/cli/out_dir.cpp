#include "tools/cli/out_dir.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace rsaa::cli {
namespace {

constexpr const char* kStagingPrefix = ".rsaa-staging-";
constexpr const char* kSetListPrefix = ".rsaa-set-";

}  // namespace

ClaimedOutDir::ClaimedOutDir(const std::string& dir, const std::string& purpose) {
  std::error_code error;
  std::filesystem::path missing = std::filesystem::path(dir).lexically_normal();
  if (missing.filename().empty()) missing = missing.parent_path();  // "out/" is "out"
  for (; !missing.empty() && !std::filesystem::exists(std::filesystem::symlink_status(missing, error));
       missing = missing.parent_path())
    created_.push_back(missing);
  std::filesystem::create_directories(dir, error);
  if (error || !std::filesystem::is_directory(dir))
    throw std::invalid_argument("--out-dir: cannot create '" + dir + "'" + (error ? " (" + error.message() + ")" : ""));
  lock_ = std::make_unique<DirectoryLock>(dir, purpose);
}

ClaimedOutDir::~ClaimedOutDir() {
  // Removed while still locked, so that no other run has claimed them; one that is not empty
  // (this run's files, or another's) stays, and so do its parents.
  std::error_code error;
  for (const std::filesystem::path& dir : created_)
    if (!std::filesystem::remove(dir, error)) break;
}

std::unique_ptr<ClaimedOutDir> claim_out_dir(const std::string& dir, const std::string& purpose) {
  return std::make_unique<ClaimedOutDir>(dir, purpose);
}

StagedOutputs::StagedOutputs(const std::string& out_dir, const std::string& purpose)
    : out_dir_(out_dir), lock_(claim_out_dir(out_dir, purpose)) {
  // The directory is ours until the end (a second run into it is refused at once): any staging
  // directory already there is a dead run's (killed, crashed).
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(out_dir_, error))
    if (entry.path().filename().string().rfind(kStagingPrefix, 0) == 0 && entry.is_directory(error))
      std::filesystem::remove_all(entry.path(), error);
  staging_ = out_dir_ / (kStagingPrefix + std::to_string(getpid()));
  if (!std::filesystem::create_directory(staging_, error))
    throw std::runtime_error("--out-dir: cannot create the staging directory '" + staging_.string() + "'" +
                             (error ? " (" + error.message() + ")" : ""));
}

StagedOutputs::~StagedOutputs() {
  std::error_code error;
  std::filesystem::remove_all(staging_, error);
}

std::string StagedOutputs::dir() const { return staging_.string(); }

std::vector<std::string> StagedOutputs::commit(const std::string& set_name) {
  std::vector<std::pair<std::string, std::string>> files;
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(staging_)) {
    if (!entry.is_regular_file()) continue;
    const std::string name = entry.path().filename().string();
    if (name.rfind('.', 0) == 0) continue;  // a writer's own temporary
    // The set list holds a name a line: a name with a control character could name another file.
    if (std::any_of(name.begin(), name.end(), [](char c) { return std::iscntrl(static_cast<unsigned char>(c)); }))
      throw std::runtime_error("--out-dir: a report file name holds a control character: '" + name + "'");
    files.emplace_back((out_dir_ / name).string(), read_whole_file(entry.path().string(), kMaxStagedFileBytes));
    names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  std::vector<std::string> previous;
  if (!set_name.empty()) {
    const std::filesystem::path list = out_dir_ / (kSetListPrefix + set_name);
    std::error_code error;
    if (std::filesystem::is_regular_file(list, error)) {
      std::istringstream lines(read_whole_file(list.string(), kMaxStagedFileBytes));
      // Plain names of this directory only: a hand-edited list names nothing elsewhere.
      for (std::string name; std::getline(lines, name);)
        if (!name.empty() && name[0] != '.' && name.find('/') == std::string::npos) previous.push_back(name);
    }
    std::string text;
    for (const std::string& name : names) text += name + "\n";
    files.emplace_back(list.string(), text);  // committed with the set
  }
  write_files_atomically(files);
  // Committed: the staging directory is empty again for the next set.
  for (const std::string& name : names) std::filesystem::remove(staging_ / name);
  for (const std::string& name : previous) {
    std::error_code error;
    const std::filesystem::path stale = out_dir_ / name;
    if (!std::binary_search(names.begin(), names.end(), name) && std::filesystem::is_regular_file(stale, error))
      std::filesystem::remove(stale, error);
  }
  return names;
}

void print_written(const std::string& out_dir, const std::vector<std::string>& names) {
  std::string list;
  for (const std::string& name : names) list += (list.empty() ? "" : ", ") + name;
  std::fprintf(stderr, "wrote %s/%s\n", out_dir.c_str(), list.c_str());
}

}  // namespace rsaa::cli
