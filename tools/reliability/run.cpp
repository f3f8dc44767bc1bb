// Running a child under the per-input budget, and scratch directories.
#include <fcntl.h>
#include <grp.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <thread>

#include "core/util/atomic_file.h"
#include "tools/reliability/suite.h"

namespace rsaa::reliability {

namespace fs = std::filesystem;

ScratchDir::ScratchDir() {
  std::string pattern = (fs::temp_directory_path() / "rsaa-reliability-XXXXXX").string();
  if (!::mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
  path_ = pattern;
  // Traversable (not listable) by others: a child run as nobody reaches its own subdirectory.
  fs::permissions(path_, fs::perms::others_exec | fs::perms::group_exec, fs::perm_options::add);
}

ScratchDir::~ScratchDir() {
  std::error_code ignored;
  fs::remove_all(path_, ignored);
}

std::string ScratchDir::write(const std::string& name, const std::string& bytes) const {
  const std::string p = file(name);
  std::ofstream(p, std::ios::binary) << bytes;
  return p;
}

RunResult run_limited(const std::vector<std::string>& argv, double seconds, std::uint64_t address_space,
                      std::uint64_t max_processes, const std::vector<std::string>& environment,
                      std::uint64_t file_size_limit) {
  const ScratchDir scratch;
  const std::string log = scratch.file("output");
  // Everything the child needs is made before fork: another thread may hold the malloc lock.
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const auto name_of = [](const std::string& entry) { return entry.substr(0, entry.find('=')); };
  std::vector<std::string> variables;
  for (char** e = environ; *e; ++e) {
    bool changed = false;
    for (const std::string& change : environment) changed = changed || name_of(change) == name_of(*e);
    if (!changed) variables.push_back(*e);
  }
  for (const std::string& change : environment)
    if (change.find('=') != std::string::npos) variables.push_back(change);
  std::vector<char*> envp;
  for (const std::string& v : variables) envp.push_back(const_cast<char*>(v.c_str()));
  envp.push_back(nullptr);
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    const int null = ::open("/dev/null", O_RDONLY);
    if (fd < 0 || null < 0) ::_exit(127);
    ::dup2(null, 0), ::dup2(fd, 1), ::dup2(fd, 2);
    const rlimit limit{address_space, address_space};
    ::setrlimit(RLIMIT_AS, &limit);
    if (file_size_limit > 0) {
      const rlimit file_size{file_size_limit, file_size_limit};
      ::setrlimit(RLIMIT_FSIZE, &file_size);
    }
    if (max_processes > 0) {
      const rlimit processes{max_processes, max_processes};
      ::setrlimit(RLIMIT_NPROC, &processes);
      if (::getuid() == 0 && (::setgroups(0, nullptr) != 0 || ::setgid(65534) != 0 || ::setuid(65534) != 0))
        ::_exit(126);
    }
    ::execve(args[0], args.data(), envp.data());
    ::_exit(127);
  }
  RunResult r;
  int status = 0;
  for (;;) {
    if (::waitpid(pid, &status, WNOHANG) == pid) break;
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (r.seconds > seconds) {
      r.timed_out = true;
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!r.timed_out && WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
  if (!r.timed_out && WIFSIGNALED(status)) r.signal = WTERMSIG(status);
  try {
    r.output = read_whole_file(log, std::uint64_t{16} << 20, "output");
  } catch (const std::exception&) {
  }
  return r;
}

}  // namespace rsaa::reliability
