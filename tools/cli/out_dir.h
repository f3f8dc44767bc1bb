// An output directory for a set of files that belong together.
#pragma once

#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/util/atomic_file.h"

namespace rsaa::cli {

// An output directory claimed by claim_out_dir. The directories the claim created go with it
// while they are still empty: a command refused before writing (an unknown scene found only once
// it loads) leaves no empty directory behind.
class ClaimedOutDir {
 public:
  ClaimedOutDir(const std::string& dir, const std::string& purpose);
  ~ClaimedOutDir();
  ClaimedOutDir(const ClaimedOutDir&) = delete;
  ClaimedOutDir& operator=(const ClaimedOutDir&) = delete;

 private:
  std::vector<std::filesystem::path> created_;  // the deepest first
  std::unique_ptr<DirectoryLock> lock_;
};

// The output directory, created if missing, and held exclusively until the files are in place:
// a second run of `purpose` into it is refused at once instead of mixing its files with ours.
std::unique_ptr<ClaimedOutDir> claim_out_dir(const std::string& dir, const std::string& purpose);

// The files a command writes as one set (a report with its plots and tables): the output
// directory is claimed (claim_out_dir) for the whole run, the files are written into a staging
// directory inside it, and commit() puts them into the output directory together
// (write_files_atomically). A command that fails midway (a full disk, a refused input) leaves
// the previous set as it was, never new files beside old ones; the staging directory goes with
// the object (a dead run's with the next run into that directory).
class StagedOutputs {
 public:
  StagedOutputs(const std::string& out_dir, const std::string& purpose);
  ~StagedOutputs();
  StagedOutputs(const StagedOutputs&) = delete;
  StagedOutputs& operator=(const StagedOutputs&) = delete;

  // Where the command writes its files (a directory inside the output directory).
  std::string dir() const;
  // Every file written into dir() since the last commit, into the output directory as one set;
  // returns their names. With `set_name`, the set replaces the previous one of that name whole:
  // a hidden list (.rsaa-set-NAME) names the files each commit wrote, and those of the previous
  // set that this one does not write are removed (a report of other scenes left their plots, a
  // redraw left a measured run's crops, beside it). Files the list does not name are kept.
  std::vector<std::string> commit(const std::string& set_name = "");

  static constexpr std::uint64_t kMaxStagedFileBytes = std::uint64_t{1} << 30;

 private:
  std::filesystem::path out_dir_, staging_;
  std::unique_ptr<ClaimedOutDir> lock_;
};

// "wrote DIR/a, b, c" on stderr: the files a command committed.
void print_written(const std::string& out_dir, const std::vector<std::string>& names);

}  // namespace rsaa::cli
