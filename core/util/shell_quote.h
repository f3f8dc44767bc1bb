// A word of a recorded command line, as a POSIX shell reads it back.
#pragma once

#include <string>

namespace rsaa {

// `word` unchanged when it holds only characters no shell treats specially, else in single
// quotes (each single quote written as '\''): a path with a space or a quote in a recorded
// command ("rsaa train --generic my tables/x.json") still runs as it was given.
inline std::string shell_quoted(const std::string& word) {
  const bool plain = !word.empty() && word.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                                             "0123456789_./:,+-=@%") == std::string::npos;
  if (plain) return word;
  std::string quoted = "'";
  for (const char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

}  // namespace rsaa
