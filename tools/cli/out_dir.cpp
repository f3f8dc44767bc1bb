#include "tools/cli/out_dir.h"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

namespace rsaa::cli {
namespace {

constexpr const char* kStagingPrefix = ".rsaa-staging-";

// Staging directories of runs that died (kill -9, a crash) before removing theirs.
void remove_dead_staging(const std::filesystem::path& out_dir) {
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(out_dir, error)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(kStagingPrefix, 0) != 0 || !entry.is_directory(error)) continue;
    const long pid = std::strtol(name.c_str() + std::char_traits<char>::length(kStagingPrefix), nullptr, 10);
    if (pid > 0 && kill(pid_t(pid), 0) != 0 && errno == ESRCH) std::filesystem::remove_all(entry.path(), error);
  }
}

}  // namespace

StagedOutputs::StagedOutputs(const std::string& out_dir) : out_dir_(out_dir) {
  std::error_code made;
  std::filesystem::create_directories(out_dir_, made);
  if (made || !std::filesystem::is_directory(out_dir_))
    throw std::invalid_argument("--out-dir: cannot create '" + out_dir + "'" + (made ? " (" + made.message() + ")" : ""));
  remove_dead_staging(out_dir_);
  staging_ = out_dir_ / (kStagingPrefix + std::to_string(getpid()));
  std::error_code error;
  std::filesystem::remove_all(staging_, error);
  if (!std::filesystem::create_directory(staging_, error))
    throw std::runtime_error("--out-dir: cannot create the staging directory '" + staging_.string() + "'" +
                             (error ? " (" + error.message() + ")" : ""));
}

StagedOutputs::~StagedOutputs() {
  std::error_code error;
  std::filesystem::remove_all(staging_, error);
}

std::string StagedOutputs::dir() const { return staging_.string(); }

std::vector<std::string> StagedOutputs::commit() {
  std::vector<std::pair<std::string, std::string>> files;
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(staging_)) {
    if (!entry.is_regular_file()) continue;
    const std::string name = entry.path().filename().string();
    if (name.rfind('.', 0) == 0) continue;  // a writer's own temporary
    files.emplace_back((out_dir_ / name).string(), read_whole_file(entry.path().string(), kMaxStagedFileBytes));
    names.push_back(name);
  }
  write_files_atomically(files);
  std::sort(names.begin(), names.end());
  return names;
}

void print_written(const std::string& out_dir, const std::vector<std::string>& names) {
  std::string list;
  for (const std::string& name : names) list += (list.empty() ? "" : ", ") + name;
  std::fprintf(stderr, "wrote %s/%s\n", out_dir.c_str(), list.c_str());
}

}  // namespace rsaa::cli
