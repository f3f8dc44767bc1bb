#include "tools/cli/progress.h"

#include <unistd.h>

#include <cstdio>

namespace rsaa::cli {

ProgressPrinter::ProgressPrinter(bool quiet) : quiet_(quiet), terminal_(::isatty(2) != 0) {}

void ProgressPrinter::stage(const std::string& name) {
  if (quiet_) return;
  stage_ = name;
  last_decile_ = -1;
  std::fprintf(stderr, "%s...\n", name.c_str());
}

void ProgressPrinter::step(std::uint64_t done, std::uint64_t total) {
  if (quiet_ || total == 0) return;
  const double fraction = double(done) / double(total);
  if (terminal_) {
    std::fprintf(stderr, "\r  %5.1f%%  %llu / %llu%s", 100.0 * fraction,
                 static_cast<unsigned long long>(done), static_cast<unsigned long long>(total),
                 done == total ? "\n" : "");
  } else {
    const int decile = int(fraction * 10.0);
    if (decile == last_decile_) return;
    last_decile_ = decile;
    std::fprintf(stderr, "  %3d%%  %llu / %llu\n", decile * 10,
                 static_cast<unsigned long long>(done), static_cast<unsigned long long>(total));
  }
  std::fflush(stderr);
}

}  // namespace rsaa::cli
