#include "core/atomic_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>

namespace rsaa {

namespace {

std::string temporary_path(const std::string& path) {
  return path + ".tmp-" + std::to_string(::getpid());
}

void write_temporary(const std::string& path, const std::string& contents) {
  const std::string temporary = temporary_path(path);
  std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
  if (!out) throw std::runtime_error(path + ": cannot write (" + std::strerror(errno) + ")");
  out.write(contents.data(), static_cast<std::streamsize>(contents.size()));
  out.flush();
  if (!out) {
    out.close();
    std::remove(temporary.c_str());
    throw std::runtime_error(path + ": write failed (" + std::strerror(errno) + ")");
  }
}

}  // namespace

void write_files_atomically(const std::vector<std::pair<std::string, std::string>>& files) {
  std::size_t written = 0;
  try {
    for (; written < files.size(); ++written)
      write_temporary(files[written].first, files[written].second);
  } catch (...) {
    for (std::size_t i = 0; i < written; ++i) std::remove(temporary_path(files[i].first).c_str());
    throw;
  }
  for (std::size_t i = 0; i < files.size(); ++i) {
    std::error_code error;
    std::filesystem::rename(temporary_path(files[i].first), files[i].first, error);
    if (error) {
      for (std::size_t k = i; k < files.size(); ++k)
        std::remove(temporary_path(files[k].first).c_str());
      throw std::runtime_error(files[i].first + ": cannot replace (" + error.message() + ")");
    }
  }
}

void write_file_atomically(const std::string& path, const std::string& contents) {
  write_files_atomically({{path, contents}});
}

std::string read_whole_file(const std::string& path) {
  if (std::filesystem::is_directory(path)) throw std::runtime_error(path + ": is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open (" + std::strerror(errno) + ")");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw std::runtime_error(path + ": read failed");
  return buffer.str();
}

}  // namespace rsaa
