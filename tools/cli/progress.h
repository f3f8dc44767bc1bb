// Progress on stderr for long runs: a rewritten line on a terminal, a line per 10% otherwise.
#pragma once

#include <cstdint>
#include <string>

namespace rsaa::cli {

class ProgressPrinter {
 public:
  explicit ProgressPrinter(bool quiet = false);
  void stage(const std::string& name);
  void step(std::uint64_t done, std::uint64_t total);

 private:
  bool quiet_;
  bool terminal_;
  std::string stage_;
  int last_decile_ = -1;
};

}  // namespace rsaa::cli
