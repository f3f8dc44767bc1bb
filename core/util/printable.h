// Text from files and command lines made safe to print on a terminal or into a // comment.
#pragma once

#include <cstdio>
#include <string>

namespace rsaa {

// `text` with every control character (below 0x20, and 0x7f) written as \xNN: a newline in a
// path would start a line of code in a generated shader's comment, and an escape sequence in a
// table's recorded command or a model's texture name would clear or fake lines of a terminal.
inline std::string printable(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (const unsigned char c : text) {
    if (c >= 0x20 && c != 0x7f) {
      out += char(c);
    } else {
      char buffer[8];
      std::snprintf(buffer, sizeof buffer, "\\x%02x", c);
      out += buffer;
    }
  }
  return out;
}

}  // namespace rsaa
