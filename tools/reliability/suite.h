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

SuiteResult table_corpus(const Options& options);
SuiteResult table_fuzz(const Options& options);
// Defined only in builds with the runtime.
SuiteResult scene_corpus(const Options& options);
SuiteResult scene_fuzz(const Options& options);
SuiteResult image_corpus(const Options& options);
SuiteResult command_line_corpus(const Options& options);

}  // namespace rsaa::reliability
