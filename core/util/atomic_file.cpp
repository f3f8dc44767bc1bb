#include "core/util/atomic_file.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <set>
#include <stdexcept>
#include <system_error>

namespace rsaa {

namespace fs = std::filesystem;

namespace {

std::string errno_text() { return std::strerror(errno); }

// Closes a descriptor on every path out of a scope.
struct Fd {
  int fd;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

// O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer forever.
int open_regular(const std::string& path, std::uint64_t max_bytes, const std::string& what,
                 std::uint64_t& size) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw std::runtime_error(path + ": cannot open " + what + " (" + errno_text() + ")");
  Fd guard{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0)
    throw std::runtime_error(path + ": cannot stat " + what + " (" + errno_text() + ")");
  if (!S_ISREG(st.st_mode))
    throw LimitError(path + ": " + what + " is " + kind_of(st.st_mode) +
                             "; only regular files are read");
  size = static_cast<std::uint64_t>(st.st_size);
  if (size > max_bytes)
    throw LimitError(path + ": " + what + " is " + std::to_string(size) +
                             " bytes; the limit is " + std::to_string(max_bytes) + " bytes");
  guard.fd = -1;
  return fd;
}

void write_temporary(const std::string& path, const std::string& temporary,
                     const std::string& contents) {
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) throw std::runtime_error(path + ": cannot write (" + errno_text() + ")");
  Fd guard{fd};
  std::size_t done = 0;
  while (done < contents.size()) {
    const ssize_t n = ::write(fd, contents.data() + done, contents.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const std::string error = errno_text();
      ::unlink(temporary.c_str());
      throw std::runtime_error(path + ": write failed (" + error + ")");
    }
    done += static_cast<std::size_t>(n);
  }
}

bool system_rename(const std::string& from, const std::string& to, std::string& error) {
  if (::rename(from.c_str(), to.c_str()) == 0) return true;
  error = errno_text();
  return false;
}

std::string directory_of(const std::string& path) {
  const fs::path parent = fs::path(path).parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

// What marks rsaa's temporaries: distinctive, since a dead PID in the name gets the file removed
// (".tmp-" alone also matched users' own files, such as ".backup.tmp-2024-01.tar").
constexpr const char* kTemporaryMarker = ".rsaa-tmp-";

// The PID in a temporary's name (DIR/.STEM.rsaa-tmp-PID-N.EXT, exactly that form), or 0.
pid_t pid_of_temporary(const std::string& name) {
  const std::string marker = kTemporaryMarker;
  const std::size_t at = name.rfind(marker);
  if (name.empty() || name[0] != '.' || at == std::string::npos) return 0;
  const auto digits_from = [&](std::size_t i) {
    std::size_t end = i;
    while (end < name.size() && std::isdigit(static_cast<unsigned char>(name[end]))) ++end;
    return end;
  };
  const std::size_t pid_begin = at + marker.size(), pid_end = digits_from(pid_begin);
  if (pid_end == pid_begin || pid_end - pid_begin > 9 || pid_end >= name.size() || name[pid_end] != '-') return 0;
  const std::size_t count_end = digits_from(pid_end + 1);
  if (count_end == pid_end + 1 || (count_end < name.size() && name[count_end] != '.')) return 0;
  return static_cast<pid_t>(std::stol(name.substr(pid_begin, pid_end - pid_begin)));
}

// Only a PID that no longer exists marks a dead run; a live one may be mid-commit.
bool is_dead(pid_t pid) { return pid > 0 && pid != ::getpid() && ::kill(pid, 0) != 0 && errno == ESRCH; }

// The commit journal: written (atomically) once every temporary is in place and before the first
// rename, removed after the last. A run killed between the two leaves it; the next run in that
// directory finishes the renames (roll forward), so a set is never left mixed. Each record is
// "<length>:<temporary><length>:<target>" with absolute paths (any byte may be in a name).
constexpr const char* kJournalStem = ".rsaa-commit";

std::string journal_path(const std::string& dir) {
  // DIR/.rsaa-commit.rsaa-tmp-PID-N.journal: named by its run's PID like every temporary.
  return temporary_path_beside((fs::path(dir) / (std::string(kJournalStem).substr(1) + ".journal")).string());
}

std::string journal_text(const std::vector<std::string>& temporaries,
                         const std::vector<std::pair<std::string, std::string>>& files) {
  std::string text;
  const auto field = [&](const std::string& path) {
    const std::string absolute = fs::absolute(path).string();
    text += std::to_string(absolute.size()) + ":" + absolute;
  };
  for (std::size_t i = 0; i < files.size(); ++i) field(temporaries[i]), field(files[i].first);
  return text;
}

// The (temporary, target) pairs a journal lists; false when it cannot be read or parsed.
bool read_journal(const std::string& journal, std::vector<std::pair<std::string, std::string>>& renames) {
  std::string text;
  try {
    text = read_whole_file(journal, std::uint64_t{1} << 20, "commit journal");
  } catch (const std::exception&) {
    return false;
  }
  std::vector<std::string> fields;
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t colon = text.find(':', at);
    if (colon == std::string::npos || colon == at || colon - at > 6) return false;
    const std::size_t length = std::stoul(text.substr(at, colon - at));
    if (colon + 1 + length > text.size()) return false;
    fields.push_back(text.substr(colon + 1, length));
    at = colon + 1 + length;
  }
  if (fields.size() % 2 != 0) return false;
  renames.clear();
  for (std::size_t i = 0; i < fields.size(); i += 2) renames.emplace_back(fields[i], fields[i + 1]);
  return true;
}

bool is_journal_name(const std::string& name) {
  const std::string ext = ".journal";
  return name.rfind(kJournalStem, 0) == 0 && name.size() > ext.size() &&
         name.compare(name.size() - ext.size(), ext.size(), ext) == 0;
}

// Whether a journal's (temporary, target) pair is one its run can have written: the target in the
// journal's own directory, the temporary beside it and named as that run's temporaries are
// (temporary_path_beside(), the journal's PID). A journal is a file anyone who can write the
// directory can make: followed blindly, it renamed any file the user could reach over any other.
bool is_own_rename(const fs::path& journal, const std::string& temporary, const std::string& target) {
  // Directories compared as the file system resolves them (a run may have reached the directory
  // through a symbolic link, the next one not).
  std::error_code ec;
  const auto resolved = [&ec](const fs::path& p) { return fs::weakly_canonical(fs::absolute(p, ec), ec); };
  const fs::path dir = resolved(journal.parent_path());
  const fs::path from = fs::path(temporary), to = fs::path(target);
  if (!from.is_absolute() || !to.is_absolute() || resolved(from.parent_path()) != dir ||
      resolved(to.parent_path()) != dir || ec)
    return false;
  const std::string name = from.filename().string(), target_name = to.filename().string();
  if (target_name.empty() || target_name == "." || target_name == ".." || is_journal_name(target_name)) return false;
  const pid_t pid = pid_of_temporary(name);
  return pid != 0 && pid == pid_of_temporary(journal.filename().string()) &&
         pid_of_temporary(target_name) == 0;
}

// Finishes the renames a dead run's journal lists (the temporaries still there); false when the
// journal cannot be read or parsed, or lists a rename its run cannot have meant (it is then left,
// untouched, for a person to look at).
bool roll_forward(const std::string& journal) {
  std::vector<std::pair<std::string, std::string>> renames;
  if (!read_journal(journal, renames)) return false;
  for (const auto& [temporary, target] : renames)
    if (!is_own_rename(journal, temporary, target)) return false;
  for (const auto& [temporary, target] : renames) {
    struct stat st {};
    if (::lstat(temporary.c_str(), &st) == 0 && S_ISREG(st.st_mode)) ::rename(temporary.c_str(), target.c_str());
  }
  return true;
}


}  // namespace

void check_replaceable(const std::string& target) {
  struct stat st {};
  if (::lstat(target.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
    throw std::runtime_error(target + ": exists and is " + kind_of(st.st_mode) + "; not replaced");
}

std::string temporary_path_beside(const std::string& target) {
  static std::atomic<unsigned> counter{0};
  const fs::path t(target);
  const std::string suffix = kTemporaryMarker + std::to_string(::getpid()) + "-" + std::to_string(counter++) +
                             t.extension().string();
  // The stem is shortened so that the name fits in NAME_MAX (255 bytes) where the target's does:
  // a 250-byte name is valid, the same with the suffix is not.
  constexpr std::size_t kNameMax = 255;
  const std::string stem = t.stem().string().substr(0, kNameMax - std::min(kNameMax, 1 + suffix.size()));
  return (t.parent_path() / ("." + stem + suffix)).string();
}

std::size_t remove_stale_temporaries(const std::string& dir) {
  std::size_t removed = 0;
  std::error_code ec;
  // First the commits dead runs left half done: finished, so that their temporaries are targets.
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (!is_journal_name(name) || !is_dead(pid_of_temporary(name))) continue;
    std::error_code ignored;
    if (fs::is_regular_file(it->symlink_status(ignored)) && roll_forward(it->path().string()))
      fs::remove(it->path(), ignored);
  }
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.rfind(kJournalStem, 0) == 0 || !is_dead(pid_of_temporary(name))) continue;
    std::error_code ignored;
    if (fs::is_regular_file(it->symlink_status(ignored)) && fs::remove(it->path(), ignored))
      ++removed;
  }
  return removed;
}

void write_files_atomically(const std::vector<std::pair<std::string, std::string>>& files,
                            const RenameFn& rename) {
  if (files.empty()) return;
  std::set<std::string> dirs;
  for (const auto& file : files) dirs.insert(directory_of(file.first));
  // One directory: its journal lists renames within that directory only (is_own_rename()).
  std::set<fs::path> resolved_dirs;
  for (const std::string& dir : dirs) resolved_dirs.insert(fs::absolute(dir).lexically_normal());
  if (resolved_dirs.size() > 1)
    throw std::logic_error("write_files_atomically: the files of one set must share a directory (" + *dirs.begin() +
                           ", " + *dirs.rbegin() + ")");
  for (const std::string& dir : dirs) remove_stale_temporaries(dir);

  // A target must be a regular file or absent: anything else could not be restored.
  for (const auto& file : files) check_replaceable(file.first);

  std::vector<std::string> temporaries, backups(files.size());
  const auto remove_all = [](const std::vector<std::string>& paths) {
    for (const std::string& p : paths)
      if (!p.empty()) ::unlink(p.c_str());
  };
  try {
    for (const auto& file : files) {
      temporaries.push_back(temporary_path_beside(file.first));
      write_temporary(file.first, temporaries.back(), file.second);
    }
    // Hard links keep the previous contents while the targets are replaced.
    for (std::size_t i = 0; i < files.size(); ++i) {
      if (::access(files[i].first.c_str(), F_OK) != 0) continue;
      backups[i] = temporary_path_beside(files[i].first);
      if (::link(files[i].first.c_str(), backups[i].c_str()) != 0) {
        const std::string error = errno_text();
        backups[i].clear();
        throw std::runtime_error(files[i].first + ": cannot keep the previous file while "
                                 "replacing it (" + error + "); nothing was changed");
      }
    }
  } catch (...) {
    remove_all(temporaries);
    remove_all(backups);
    throw;
  }
  // The journal that lets the next run finish these renames should this one die among them.
  const std::string journal = journal_path(directory_of(files.front().first));
  try {
    const std::string journal_temporary = temporary_path_beside(journal);
    write_temporary(journal, journal_temporary, journal_text(temporaries, files));
    std::string error;
    if (!system_rename(journal_temporary, journal, error)) {
      ::unlink(journal_temporary.c_str());
      throw std::runtime_error(journal + ": cannot write the commit journal (" + error + "); nothing was changed");
    }
  } catch (...) {
    remove_all(temporaries);
    remove_all(backups);
    throw;
  }

  for (std::size_t i = 0; i < files.size(); ++i) {
    std::string error;
    if (rename(temporaries[i], files[i].first, error)) continue;
    // Undo the targets already replaced, newest first, so that the set stays as it was.
    std::string undo_error;
    for (std::size_t k = i; k-- > 0;) {
      std::string e;
      if (!backups[k].empty() ? !system_rename(backups[k], files[k].first, e)
                              : ::unlink(files[k].first.c_str()) != 0)
        undo_error += " " + files[k].first;
      if (!backups[k].empty() && e.empty()) backups[k].clear();
    }
    remove_all(std::vector<std::string>(temporaries.begin() + i, temporaries.end()));
    remove_all(backups);
    ::unlink(journal.c_str());
    throw std::runtime_error(files[i].first + ": cannot replace (" + error + "); " +
                             (undo_error.empty() ? "the previous files are left as they were"
                                                 : "could not restore:" + undo_error));
  }
  ::unlink(journal.c_str());
  remove_all(backups);
}

void write_files_atomically(const std::vector<std::pair<std::string, std::string>>& files) {
  write_files_atomically(files, system_rename);
}

std::string read_committed_file(const std::string& path, std::uint64_t max_bytes, const std::string& what) {
  const fs::path wanted = fs::absolute(path).lexically_normal();
  std::error_code ec;
  for (fs::directory_iterator it(directory_of(path), ec), end; !ec && it != end; it.increment(ec)) {
    if (!is_journal_name(it->path().filename().string())) continue;
    std::vector<std::pair<std::string, std::string>> renames;
    if (!read_journal(it->path().string(), renames)) continue;
    for (const auto& [temporary, target] : renames) {
      // A writer's temporary is always beside its target: a journal naming another place is
      // not one of ours and is not followed.
      if (fs::path(target).lexically_normal() != wanted ||
          fs::path(temporary).lexically_normal().parent_path() != wanted.parent_path())
        continue;
      // Renamed in the meantime (or never there): the target holds the committed contents.
      try {
        return read_whole_file(temporary, max_bytes, what);
      } catch (const LimitError&) {
        throw;
      } catch (const std::runtime_error&) {
      }
    }
  }
  return read_whole_file(path, max_bytes, what);
}

void write_file_atomically(const std::string& path, const std::string& contents) {
  write_files_atomically({{path, contents}});
}

std::uint64_t check_regular_file(const std::string& path, std::uint64_t max_bytes,
                                 const std::string& what) {
  std::uint64_t size = 0;
  ::close(open_regular(path, max_bytes, what, size));
  return size;
}

std::string read_whole_file(const std::string& path, std::uint64_t max_bytes,
                            const std::string& what) {
  std::uint64_t size = 0;
  const Fd fd{open_regular(path, max_bytes, what, size)};
  std::string text(static_cast<std::size_t>(size), '\0');
  std::size_t done = 0;
  // Read one byte past the size seen: a file that grows while being read is refused.
  char extra;
  for (;;) {
    char* into = done < text.size() ? &text[done] : &extra;
    const std::size_t want = done < text.size() ? text.size() - done : 1;
    const ssize_t n = ::read(fd.fd, into, want);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw std::runtime_error(path + ": read failed (" + errno_text() + ")");
    if (n == 0) break;
    if (done >= text.size())
      throw LimitError(path + ": " + what + " grew while being read");
    done += static_cast<std::size_t>(n);
  }
  text.resize(done);
  return text;
}

DirectoryLock::DirectoryLock(const std::string& dir, const std::string& purpose) {
  fd_ = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd_ < 0) throw std::runtime_error(dir + ": cannot open the directory (" + errno_text() + ")");
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const bool busy = errno == EWOULDBLOCK;
    const std::string error = errno_text();
    ::close(fd_);
    fd_ = -1;
    throw std::runtime_error(dir + ": " +
                             (busy ? "another process holds this directory for " + purpose +
                                         "; wait for it to finish or choose another directory"
                                   : "cannot lock the directory (" + error + ")"));
  }
}

DirectoryLock::~DirectoryLock() {
  if (fd_ >= 0) ::close(fd_);  // closing releases the flock
}

}  // namespace rsaa
