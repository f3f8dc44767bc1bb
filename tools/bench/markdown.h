// Text put into a cell of a Markdown table: a '|' in a scene's file name would start a cell of
// its own and shift every column after it.
#pragma once

#include <string>

#include "core/util/printable.h"

namespace rsaa::bench {

inline std::string markdown_cell(const std::string& text) {
  std::string out;
  for (const char c : printable(text)) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

}  // namespace rsaa::bench
