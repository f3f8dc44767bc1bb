// A reliability suite: a kind of input, a corpus of broken ones and a fuzz loop over mutations,
// with the count of what happened to each input.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace rsaa::reliability {

// What feeding one input did.
enum class Outcome {
  kRejectedClearly,  // an error that names the input, as the project promises
  kAccepted,         // a valid result (e.g. a mutation that is still a valid table)
  kFailed,           // crash-free but wrong: unclear message, invalid result, wrong exception
};

struct SuiteResult {
  std::string what;
  std::uint64_t inputs = 0, rejected = 0, accepted = 0, failed = 0;
  std::vector<std::string> failures;  // the first few, for the report
  void add(Outcome outcome, const std::string& label, const std::string& detail);
};

struct Options {
  std::uint64_t iterations = 200;
  std::uint64_t seed = 1;
  std::string rsaa_binary;  // for the command-line suite; empty: skipped
};

// A fresh directory under the system temp dir, removed with everything in it.
class ScratchDir {
 public:
  ScratchDir();
  ~ScratchDir();
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const std::string& path() const { return path_; }
  std::string file(const std::string& name) const { return path_ + "/" + name; }
  std::string write(const std::string& name, const std::string& bytes) const;  // returns the path

 private:
  std::string path_;
};

// One run of a program as a hostile input's judge sees it: within a time and address-space
// budget (docs/reliability.md: 60 s, 6 GiB), stdout and stderr together.
struct RunResult {
  int exit_code = -1;   // -1 unless the program exited
  int signal = 0;       // the signal that ended it, 0 if none
  bool timed_out = false;
  double seconds = 0.0;
  std::string output;
};
constexpr double kInputSeconds = 60.0;
constexpr std::uint64_t kInputAddressSpace = std::uint64_t{6} << 30;
// max_processes > 0: RLIMIT_NPROC, so that threads fail to start; root ignores that limit, so
// a root caller's child runs as nobody (65534) then.
// `environment`: changes to the inherited environment, "NAME=VALUE" to set, "NAME" to unset.
// file_size_limit > 0: RLIMIT_FSIZE (ulimit -f), writes beyond it fail as on a full disk.
RunResult run_limited(const std::vector<std::string>& argv, double seconds = kInputSeconds,
                      std::uint64_t address_space = kInputAddressSpace, std::uint64_t max_processes = 0,
                      const std::vector<std::string>& environment = {}, std::uint64_t file_size_limit = 0);

SuiteResult table_corpus(const Options& options);
SuiteResult table_fuzz(const Options& options);
// Defined only in builds with the runtime.
SuiteResult scene_corpus(const Options& options);
SuiteResult scene_fuzz(const Options& options);
SuiteResult image_corpus(const Options& options);
SuiteResult command_line_corpus(const Options& options);
// Issue 15's classes of hostile input and environment, fed to the rsaa binary, one suite each.
std::vector<SuiteResult> hostile_suites(const Options& options);

}  // namespace rsaa::reliability
