#include "runtime/shader_library.h"

#include <set>
#include <sstream>
#include <stdexcept>

namespace rsaa::gl {
namespace {

const std::string& source_of(const std::string& name) {
  const auto& sources = embedded_shader_sources();
  const auto it = sources.find(name);
  if (it == sources.end()) throw std::runtime_error("no embedded shader source '" + name + "'");
  return it->second;
}

void expand(const std::string& name, std::set<std::string>& included, std::string& out) {
  if (!included.insert(name).second) return;
  std::istringstream in(source_of(name));
  std::string line;
  while (std::getline(in, line)) {
    const std::size_t at = line.find("#include \"");
    if (at != std::string::npos && line.find_first_not_of(" \t") == at) {
      const std::size_t start = at + 10;
      expand(line.substr(start, line.find('"', start) - start), included, out);
    } else {
      out += line + "\n";
    }
  }
}

}  // namespace

std::string shader_source(const std::string& name) {
  std::set<std::string> included;
  std::string out;
  expand(name, included, out);
  return out;
}

std::string table_glsl(const std::string& pattern) {
  const auto& sources = embedded_shader_sources();
  const auto it = sources.find("tables/" + pattern + ".glsl");
  if (it == sources.end())
    throw std::runtime_error("no baked offset table for pattern '" + pattern +
                             "' in this build (tables/" + pattern + ".glsl)");
  return it->second;
}

OffsetTable builtin_offset_table(const std::string& pattern) {
  const auto& sources = embedded_shader_sources();
  const auto it = sources.find("tables/" + pattern + ".json");
  if (it == sources.end())
    throw std::runtime_error("no baked offset table for pattern '" + pattern +
                             "' in this build (tables/" + pattern + ".json)");
  return parse_offset_table(it->second, "tables/" + pattern + ".json");
}

}  // namespace rsaa::gl
