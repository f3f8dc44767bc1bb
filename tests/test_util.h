// Small helpers shared by the tests: temporary directories and running the rsaa binary.
#pragma once

#include <string>

namespace rsaa::test {

// A fresh empty directory under the system temp dir, removed by the destructor.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::string& path() const { return path_; }
  std::string file(const std::string& name) const { return path_ + "/" + name; }

 private:
  std::string path_;
};

struct CommandResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr together
};

// Runs a shell command line, capturing its output.
CommandResult run_command(const std::string& command_line);
// Runs build/rsaa with the given arguments.
CommandResult run_rsaa(const std::string& arguments);

void write_text(const std::string& path, const std::string& text);
std::string read_text(const std::string& path);

}  // namespace rsaa::test
