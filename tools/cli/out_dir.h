// An output directory for a set of files that belong together.
#pragma once

#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>

#include "core/util/atomic_file.h"

namespace rsaa::cli {

// The output directory, created if missing, and held exclusively until the files are in place:
// a second run of `purpose` into it is refused at once instead of mixing its files with ours.
inline std::unique_ptr<DirectoryLock> claim_out_dir(const std::string& dir, const std::string& purpose) {
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error || !std::filesystem::is_directory(dir))
    throw std::invalid_argument("--out-dir: cannot create '" + dir + "'" +
                                (error ? " (" + error.message() + ")" : ""));
  return std::make_unique<DirectoryLock>(dir, purpose);
}

}  // namespace rsaa::cli
