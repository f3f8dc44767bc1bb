// Text from files and command lines made safe to print on a terminal or into a // comment.
#pragma once

#include <cstddef>
#include <cstdio>
#include <string>

namespace rsaa {

// `text` with every control character written as \xNN: C0 (below 0x20) and DEL, and the C1
// controls (0x80-0x9f), as UTF-8 (U+0080-U+009F) or as lone bytes that are not part of a UTF-8
// sequence. A newline in a path would start a line of code in a generated shader's comment, and
// an escape sequence in a table's recorded command or a model's texture name would clear or fake
// lines of a terminal. `keep_lines`: newlines and tabs stay (a driver's compile log in an error).
inline std::string printable(const std::string& text, bool keep_lines = false) {
  const auto escape = [](unsigned char c) {
    char buffer[8];
    std::snprintf(buffer, sizeof buffer, "\\x%02x", c);
    return std::string(buffer);
  };
  std::string out;
  out.reserve(text.size());
  const std::size_t n = text.size();
  for (std::size_t i = 0; i < n;) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c < 0x80) {
      out += (c >= 0x20 && c != 0x7f) || (keep_lines && (c == '\n' || c == '\t')) ? std::string(1, char(c)) : escape(c);
      ++i;
      continue;
    }
    // The length of a well-formed UTF-8 sequence starting here, 0 if there is none.
    const std::size_t length = c >= 0xc2 && c <= 0xdf ? 2 : c >= 0xe0 && c <= 0xef ? 3 : c >= 0xf0 && c <= 0xf4 ? 4 : 0;
    bool whole = length != 0 && i + length <= n;
    for (std::size_t k = 1; whole && k < length; ++k) whole = (static_cast<unsigned char>(text[i + k]) & 0xc0) == 0x80;
    const bool c1 = whole && c == 0xc2 && static_cast<unsigned char>(text[i + 1]) < 0xa0;
    if (whole && !c1) {
      out.append(text, i, length);
      i += length;
    } else {
      out += escape(c);  // a lone byte (a C1 control to an 8-bit terminal) or U+0080-U+009F
      ++i;
    }
  }
  return out;
}

}  // namespace rsaa
