// Files in and out, bounded and all-or-nothing.
// Out: write a temporary file beside the target, then rename it over the target; several files
// that belong together are committed as one unit. In: only regular files, within a size budget
// checked before anything is allocated (a FIFO, /dev/zero or a huge file is refused at once).
#pragma once

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace rsaa {

// A refusal because an input is over a budget or of the wrong kind (FIFO, device): callers
// that tolerate broken optional inputs (a model's texture) still refuse these.
class LimitError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Default read budget: larger than any file the project reads as a whole.
constexpr std::uint64_t kDefaultReadBudgetBytes = std::uint64_t{256} << 20;

// Throws std::runtime_error naming the path when the directory is missing or unwritable.
void write_file_atomically(const std::string& path, const std::string& contents);

// Several files that belong together: all temporaries are written first, then renamed. When a
// rename fails midway, the targets already replaced get their previous contents back (kept as
// hard links until the commit is done), so the set is never mixed. A run killed among its renames
// (kill -9) leaves a commit journal beside the first file: the next write into that directory
// (or remove_stale_temporaries) finishes the renames it lists, then removes the dead run's
// temporaries.
void write_files_atomically(const std::vector<std::pair<std::string, std::string>>& files);

// The same with the rename made injectable, for tests of a failing rename.
using RenameFn = std::function<bool(const std::string& from, const std::string& to, std::string& error)>;
void write_files_atomically(const std::vector<std::pair<std::string, std::string>>& files,
                            const RenameFn& rename);

// Throws std::runtime_error naming `target` when it exists and is not a regular file (a
// directory, a symbolic link, a device, a FIFO): outputs replace only regular files.
void check_replaceable(const std::string& target);

// A fresh temporary name beside `target` for this process: DIR/.STEM.rsaa-tmp-PID-N.EXT (the
// extension is kept so that format-by-extension writers still work; STEM is shortened to keep
// the name within 255 bytes).
std::string temporary_path_beside(const std::string& target);
// Finishes the commits of dead runs in DIR (their journals), then removes the regular files named
// as temporaries are (DIR/.STEM.rsaa-tmp-PID-N.EXT) whose PID is no longer running; returns how
// many temporaries it removed.
std::size_t remove_stale_temporaries(const std::string& dir);

// Checks that `path` is a regular file of at most `max_bytes` without blocking on it (FIFOs and
// devices are refused, not opened for reading); returns its size. `what` names the kind of
// file in messages ("image", "texture", ...). Throws std::runtime_error naming the path, the
// size and the limit (LimitError for those two, std::runtime_error when it cannot be opened).
std::uint64_t check_regular_file(const std::string& path, std::uint64_t max_bytes,
                                 const std::string& what = "file");

// Whole file as a string, under the same checks; throws std::runtime_error naming the path.
// A file written as one of a set is better read with read_committed_file.
std::string read_whole_file(const std::string& path,
                            std::uint64_t max_bytes = kDefaultReadBudgetBytes,
                            const std::string& what = "file");

// `path` as the commit into its directory intends: when a commit journal there (of a run killed
// among its renames, or of one renaming now) lists `path` and its temporary is still there, the
// temporary is read (it is what `path` becomes); otherwise `path`. Reading every file of a set
// this way gives one set even while a writer is, or died, between its renames. Writes nothing.
std::string read_committed_file(const std::string& path,
                                std::uint64_t max_bytes = kDefaultReadBudgetBytes,
                                const std::string& what = "file");

// An exclusive advisory lock (flock) on a directory, held while the object lives. A second
// holder is refused at once with an error naming the directory and `purpose`.
class DirectoryLock {
 public:
  DirectoryLock(const std::string& dir, const std::string& purpose);
  ~DirectoryLock();
  DirectoryLock(const DirectoryLock&) = delete;
  DirectoryLock& operator=(const DirectoryLock&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace rsaa
