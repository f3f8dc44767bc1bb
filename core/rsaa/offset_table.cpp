#include "core/rsaa/offset_table.h"

#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <thread>

#include "core/util/atomic_file.h"
#include "core/util/json_unique.h"
#include "core/util/printable.h"
#include "core/rsaa/conventions.h"
#include "core/rsaa/fallback.h"

namespace rsaa {
namespace {

using nlohmann::json;

// The line of the shader files that carries the set id (also the JSON's "set_id").
constexpr const char* kSetIdPrefix = "// Table set id: ";
constexpr const char* kSetIdSuffix = " (one write: the same id in ";

constexpr const char* kMaskBitText = "bit i set = subsample i is similar to the pixel centre";

std::string number_text(double v) { return json(v).dump(); }

std::string bound_text(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", v);
  return buffer;
}

// A float literal both GLSL and HLSL accept (always with a '.' or an exponent).
std::string shader_float(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.9g", v);
  std::string s = buffer;
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}

std::string upper(std::string s) {
  for (char& c : s) c = std::isalnum(static_cast<unsigned char>(c)) ? std::toupper(c) : '_';
  return s;
}

// The command line goes into a // comment of the shader files: control characters (a newline
// would start a line of code) are written as \xNN.
std::string generated_by(const OffsetTable& table) {
  const auto it = table.training.find("command");
  if (it == table.training.end() || !it->is_string()) return "(unknown)";
  return printable(it->get<std::string>());
}

// --- reading -------------------------------------------------------------------------------

class Reader {
 public:
  explicit Reader(std::string origin) : origin_(std::move(origin)) {}

  [[noreturn]] void fail(const std::string& where, const std::string& what) const {
    throw TableError(origin_ + ": " + where + ": " + what);
  }

  const json& field(const json& object, const char* name) const {
    const auto it = object.find(name);
    if (it == object.end()) fail(name, "missing field");
    return *it;
  }

  std::string string_field(const json& object, const char* name) const {
    const json& v = field(object, name);
    if (!v.is_string()) fail(name, "expected a string");
    return v.get<std::string>();
  }

  const json& array_field(const json& object, const char* name, std::size_t expected) const {
    const json& v = field(object, name);
    if (!v.is_array()) fail(name, "expected an array");
    if (v.size() != expected)
      fail(name, "has " + std::to_string(v.size()) + " entries; expected " +
                     std::to_string(expected));
    return v;
  }

  Vec2 pair(const json& v, const std::string& where, double bound) const {
    if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number())
      fail(where, "expected a pair of numbers [x, y]");
    const Vec2 p{v[0].get<double>(), v[1].get<double>()};
    if (!is_finite(p) || std::abs(p.x) > bound || std::abs(p.y) > bound)
      fail(where, "expected finite numbers within [-" + bound_text(bound) + ", " +
                      bound_text(bound) + "], got [" + number_text(p.x) + ", " +
                      number_text(p.y) + "]");
    return p;
  }

 private:
  std::string origin_;
};

// Bounds of the free-form "training" object (the command and options that made the table, two
// levels deep as written): it is copied into eval-table --json, whose indented output grew with
// the square of a hand-edited nesting (100,000 levels took 8 GB and crashed).
constexpr int kMaxTrainingLevels = 16;
constexpr std::size_t kMaxTrainingValues = 4096;

// Whether `value` nests at most `levels` deep (a number or string is one level, an object or
// array one more than its deepest member), counting its values into `count`. Stops at the first
// value too deep or too many, so the recursion and the walk are bounded too.
bool nests_within(const json& value, int levels, std::size_t& count) {
  if (levels < 1 || ++count > kMaxTrainingValues) return false;
  if (value.is_structured())
    for (const json& member : value)
      if (!nests_within(member, levels - 1, count)) return false;
  return true;
}

OffsetSource parse_source(const Reader& reader, const json& v, const std::string& where) {
  if (v.is_string()) {
    const std::string s = v.get<std::string>();
    for (int k = 0; k < kOffsetSourceCount; ++k)
      if (s == to_string(OffsetSource(k))) return OffsetSource(k);
  }
  reader.fail(where, "expected \"one-line\", \"two-line\", \"fallback\" or \"scene\"");
}

}  // namespace

const char* to_string(OffsetSource source) {
  switch (source) {
    case OffsetSource::OneLine: return "one-line";
    case OffsetSource::TwoLine: return "two-line";
    case OffsetSource::Fallback: return "fallback";
    case OffsetSource::Scene: return "scene";
  }
  return "fallback";
}

OffsetTable fallback_table(const SamplePattern& pattern) {
  if (pattern.size() > kMaxTableSamples)
    throw std::invalid_argument("pattern '" + pattern.name + "' has " +
                                std::to_string(pattern.size()) + " samples; tables allow at most " +
                                std::to_string(kMaxTableSamples));
  OffsetTable table;
  table.pattern = pattern;
  const std::size_t n = pattern.mask_count();
  table.offsets.resize(n);
  table.sources.assign(n, OffsetSource::Fallback);
  table.cases_per_mask.assign(n, 0);
  for (std::size_t m = 0; m < n; ++m) table.offsets[m] = fallback_offset(pattern, m);
  return table;
}

namespace {

// The table, and in `set_id` the id the JSON carries ("" when it has none).
OffsetTable parse_table(const std::string& text, const std::string& origin, std::string& set_id) {
  const Reader reader(origin);
  json root;
  try {
    root = parse_json_with_unique_keys(text);
  } catch (const json::exception& e) {
    throw TableError(origin + ": not valid JSON (" + e.what() + ")");
  } catch (const std::invalid_argument& e) {
    throw TableError(origin + ": " + e.what());
  }
  if (!root.is_object()) reader.fail("top level", "expected a JSON object");
  if (reader.string_field(root, "format") != "rsaa-offset-table")
    reader.fail("format", "expected \"rsaa-offset-table\"");
  const json& version = reader.field(root, "version");
  if (!version.is_number_integer() || version.get<long long>() != 1)
    reader.fail("version", "expected 1 (the only version this program reads)");
  if (reader.string_field(root, "y_axis") != "down")
    reader.fail("y_axis", "expected \"down\" (pixel space, docs/conventions.md section 1)");
  reader.string_field(root, "mask_bit");

  const std::string name = reader.string_field(root, "pattern");
  if (!is_known_pattern_name(name))
    reader.fail("pattern", "unknown pattern '" + name +
                               "' (known: d3d4x, d3d8x, d3d16x, gl4x, custom-NAME)");
  const json& samples = reader.field(root, "samples");
  if (!samples.is_array() || samples.empty() ||
      samples.size() > static_cast<std::size_t>(kMaxTableSamples))
    reader.fail("samples", "expected an array of 1 to " + std::to_string(kMaxTableSamples) +
                               " [x, y] positions");
  std::vector<Vec2> positions;
  for (std::size_t i = 0; i < samples.size(); ++i)
    positions.push_back(reader.pair(samples[i], "samples[" + std::to_string(i) + "]", 0.5));

  OffsetTable table;
  try {
    table.pattern = pattern_from_positions(name, positions);
  } catch (const std::invalid_argument& e) {
    reader.fail("samples", e.what());
  }
  if (is_builtin_pattern(name)) {
    const SamplePattern builtin = builtin_pattern(name);
    if (builtin.size() != table.pattern.size())
      reader.fail("samples", "pattern " + name + " has " + std::to_string(builtin.size()) +
                                 " samples, the file lists " +
                                 std::to_string(table.pattern.size()));
    for (int i = 0; i < builtin.size(); ++i)
      if (length(builtin.positions[i] - positions[i]) > 1e-9)
        reader.fail("samples[" + std::to_string(i) + "]",
                    "does not match the built-in pattern " + name);
  }

  const std::size_t n = table.pattern.mask_count();
  const json& offsets = reader.array_field(root, "offsets", n);
  const json& sources = reader.array_field(root, "source", n);
  const json& counts = reader.array_field(root, "cases_per_mask", n);
  table.offsets.resize(n);
  table.sources.resize(n);
  table.cases_per_mask.resize(n);
  for (std::size_t m = 0; m < n; ++m) {
    const std::string index = "[" + std::to_string(m) + "]";
    table.offsets[m] = reader.pair(offsets[m], "offsets" + index, 1.0);
    table.sources[m] = parse_source(reader, sources[m], "source" + index);
    if (!counts[m].is_number_unsigned())
      reader.fail("cases_per_mask" + index, "expected a non-negative integer");
    table.cases_per_mask[m] = counts[m].get<std::uint64_t>();
  }
  const json& training = reader.field(root, "training");
  if (!training.is_object()) reader.fail("training", "expected an object");
  std::size_t training_values = 0;
  if (!nests_within(training, kMaxTrainingLevels, training_values))
    reader.fail("training", "expected an object of at most " + std::to_string(kMaxTrainingValues) +
                                " values nested at most " + std::to_string(kMaxTrainingLevels) +
                                " levels deep (the command and options that made the table)");
  table.training = training;
  // Checked last, so that a broken field is named as such. A JSON without an id (written by
  // hand) is read alone; one with an id must be the table that id was made from.
  set_id.clear();
  if (root.contains("set_id")) {
    set_id = reader.string_field(root, "set_id");
    const std::string expected = table_set_id(table);
    if (set_id != expected)
      reader.fail("set_id", "is " + json(set_id).dump() + " but the contents give \"" + expected +
                                "\": the file was changed after it was written, so its .glsl and "
                                ".hlsl may not match it; write the three again (rsaa train) or "
                                "remove set_id");
  }
  return table;
}

// The id in the header of a shader table file, "" when there is none.
std::string shader_set_id(const std::string& text) {
  const std::size_t at = text.find(kSetIdPrefix);
  if (at == std::string::npos || at > 4096) return "";
  const std::size_t start = at + std::char_traits<char>::length(kSetIdPrefix);
  return text.substr(start, std::min<std::size_t>(16, text.size() - start));
}

// Why the .glsl and .hlsl beside `json_path` are not of the same write as it (id `set_id`);
// "" when they are or are absent.
std::string set_mismatch(const std::string& json_path, const std::string& set_id) {
  const std::string suffix = ".json";
  if (json_path.size() <= suffix.size() || json_path.compare(json_path.size() - suffix.size(), suffix.size(), suffix) != 0)
    return "";
  const std::string base = json_path.substr(0, json_path.size() - suffix.size());
  for (const char* ext : {".glsl", ".hlsl"}) {
    const std::string sibling = base + ext;
    std::error_code ec;
    if (!std::filesystem::exists(std::filesystem::symlink_status(sibling, ec))) continue;
    std::string text;
    try {
      text = read_committed_file(sibling, kMaxTableFileBytes, "table");
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    const std::string id = shader_set_id(text);
    if (id != set_id)
      return sibling + " is not of the same write as " + json_path + " (" +
             (id.empty() ? std::string("it has no set id") : "set id " + id) + ", the JSON's is " + set_id +
             "): the three table files are not one set; write them again (rsaa train)";
  }
  return "";
}

}  // namespace

OffsetTable parse_offset_table(const std::string& text, const std::string& origin) {
  std::string set_id;
  return parse_table(text, origin, set_id);
}

OffsetTable read_offset_table(const std::string& path) {
  // Files are read as the commit in progress or interrupted in their directory intends
  // (read_committed_file); a mix seen while another run is between its journal and its renames
  // is read again a few times before it is refused.
  for (int attempt = 0;; ++attempt) {
    std::string text;
    try {
      text = read_committed_file(path, kMaxTableFileBytes, "table");
    } catch (const std::runtime_error& e) {
      throw TableError(e.what());
    }
    std::string set_id;
    OffsetTable table = parse_table(text, path, set_id);
    if (set_id.empty()) return table;
    const std::string mixed = set_mismatch(path, set_id);
    if (mixed.empty()) return table;
    if (attempt == 4) throw TableError(path + ": " + mixed);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

namespace {

// The JSON text, with the set id line when `set_id` is not empty. Hand-laid so that each entry
// is one line; values go through nlohmann for exact escaping and shortest round-trip numbers.
std::string table_json_text(const OffsetTable& table, const std::string& set_id) {
  std::ostringstream out;
  const auto pair_text = [](Vec2 p) { return "[" + number_text(p.x) + ", " + number_text(p.y) + "]"; };
  out << "{\n";
  out << "  \"format\": \"rsaa-offset-table\",\n";
  out << "  \"version\": 1,\n";
  if (!set_id.empty()) out << "  \"set_id\": \"" << set_id << "\",\n";
  out << "  \"pattern\": " << json(table.pattern.name).dump() << ",\n";
  out << "  \"y_axis\": \"down\",\n";
  out << "  \"samples\": [";
  for (int i = 0; i < table.pattern.size(); ++i)
    out << (i ? ", " : "") << pair_text(table.pattern.positions[i]);
  out << "],\n";
  out << "  \"mask_bit\": " << json(kMaskBitText).dump() << ",\n";
  // The command may hold file names, which are any bytes: invalid UTF-8 is written as U+FFFD
  // rather than failing the write.
  out << "  \"training\": " << table.training.dump(-1, ' ', false, json::error_handler_t::replace) << ",\n";
  const std::size_t n = table.offsets.size();
  out << "  \"offsets\": [\n";
  for (std::size_t m = 0; m < n; ++m)
    out << "    " << pair_text(table.offsets[m]) << (m + 1 < n ? ",\n" : "\n");
  out << "  ],\n";
  out << "  \"source\": [\n";
  for (std::size_t m = 0; m < n; ++m)
    out << (m % 8 == 0 ? "    " : " ") << json(to_string(table.sources[m])).dump()
        << (m + 1 < n ? "," : "") << (m % 8 == 7 || m + 1 == n ? "\n" : "");
  out << "  ],\n";
  out << "  \"cases_per_mask\": [\n";
  for (std::size_t m = 0; m < n; ++m)
    out << (m % 16 == 0 ? "    " : " ") << table.cases_per_mask[m] << (m + 1 < n ? "," : "")
        << (m % 16 == 15 || m + 1 == n ? "\n" : "");
  out << "  ]\n";
  out << "}\n";
  return out.str();
}

}  // namespace

std::string table_set_id(const OffsetTable& table) {
  // FNV-1a, 64 bits, of the JSON text without its id: a function of the contents only, so the
  // same table gives the same id (byte-identical files) and another table another id.
  std::uint64_t hash = 0xcbf29ce484222325ull;
  for (unsigned char c : table_json_text(table, "")) hash = (hash ^ c) * 0x100000001b3ull;
  char buffer[17];
  std::snprintf(buffer, sizeof buffer, "%016llx", static_cast<unsigned long long>(hash));
  return buffer;
}

std::string offset_table_json(const OffsetTable& table) { return table_json_text(table, table_set_id(table)); }

namespace {

// The shared layout of both shader includes; `vec2` and `y_sign` select the language.
std::string shader_table(const OffsetTable& table, bool glsl) {
  const std::string& name = table.pattern.name;
  const std::size_t n = table.offsets.size();
  const int samples = table.pattern.size();
  const std::string vec2 = glsl ? "vec2" : "float2";
  const auto literal = [&](Vec2 p) {
    const Vec2 v = glsl ? pixel_to_gl(p) : p;
    return vec2 + "(" + shader_float(v.x) + ", " + shader_float(v.y) + ")";
  };
  const auto array_open = [&](const std::string& var, std::size_t count) {
    return glsl ? "const " + vec2 + " " + var + "[" + std::to_string(count) + "] = " + vec2 +
                      "[" + std::to_string(count) + "](\n"
                : "static const " + vec2 + " " + var + "[" + std::to_string(count) + "] = {\n";
  };
  const std::string array_close = glsl ? ");\n" : "};\n";
  const std::string guard = "RSAA_TABLE_" + upper(name) + (glsl ? "_GLSL" : "_HLSL");

  std::ostringstream out;
  out << "// rsaa offset table, pattern " << name << ": " << samples << " subsamples, " << n
      << " masks. Generated file, do not edit.\n";
  out << "// Generated by: " << generated_by(table) << "\n";
  out << kSetIdPrefix << table_set_id(table) << kSetIdSuffix << name << ".json, .glsl and .hlsl)\n";
  out << "// Index: the similarity mask, bit i set = subsample i is similar to the pixel centre.\n";
  if (glsl)
    out << "// Y CONVENTION: OpenGL window space, +y UP. Every offset and sample position here is\n"
           "// (x, -y) of the pixel-space (+y down) numbers in "
        << name << ".json.\n";
  else
    out << "// Y CONVENTION: pixel space, +y DOWN (Direct3D screen space): the numbers of " << name
        << ".json.\n";
  out << "// Offsets are in pixels; one bilinear fetch at (pixel centre + offset) resolves a pixel.\n";
  out << "#ifndef " << guard << "\n#define " << guard << "\n";
  out << "#define RSAA_TABLE_SAMPLE_COUNT " << samples << "\n";
  out << "#define RSAA_TABLE_MASK_COUNT " << n << "\n";
  out << array_open("rsaa_sample_positions", samples);
  for (int i = 0; i < samples; ++i)
    out << "  " << literal(table.pattern.positions[i]) << (i + 1 < samples ? ",\n" : "\n");
  out << array_close;
  out << array_open("rsaa_offsets", n);
  for (std::size_t m = 0; m < n; ++m)
    out << (m % 4 == 0 ? "  " : " ") << literal(table.offsets[m]) << (m + 1 < n ? "," : "")
        << (m % 4 == 3 || m + 1 == n ? "\n" : "");
  out << array_close;
  out << "#endif  // " << guard << "\n";
  return out.str();
}

}  // namespace

std::string offset_table_glsl(const OffsetTable& table) { return shader_table(table, true); }
std::string offset_table_hlsl(const OffsetTable& table) { return shader_table(table, false); }

std::vector<std::string> write_offset_table_files(const OffsetTable& table, const std::string& dir,
                                                  const std::string& stem) {
  const std::string name = stem.empty() ? table.pattern.name : stem;
  // The stem is a file name inside `dir` and the pattern name is written into shader code.
  for (const std::string& n : {name, table.pattern.name})
    if (!is_valid_pattern_name(n))
      throw std::invalid_argument("table name '" + n + "' must be 1 to " +
                                  std::to_string(kMaxPatternNameLength) +
                                  " letters, digits, '-' or '_'");
  // What the reader would refuse is never written.
  if (table.offsets.size() != table.pattern.mask_count() ||
      table.sources.size() != table.offsets.size() ||
      table.cases_per_mask.size() != table.offsets.size())
    throw std::invalid_argument("table " + name + ": entry counts do not match the pattern");
  for (std::size_t m = 0; m < table.offsets.size(); ++m) {
    const Vec2 d = table.offsets[m];
    if (!is_finite(d) || std::abs(d.x) > 1.0 || std::abs(d.y) > 1.0)
      throw std::invalid_argument("table " + name + ": offset of mask " + std::to_string(m) +
                                  " is [" + number_text(d.x) + ", " + number_text(d.y) +
                                  "], not finite within [-1, 1]; nothing written");
  }
  const std::string base = (dir.empty() ? std::string(".") : dir) + "/" + name;
  const std::vector<std::pair<std::string, std::string>> files = {
      {base + ".json", offset_table_json(table)},
      {base + ".glsl", offset_table_glsl(table)},
      {base + ".hlsl", offset_table_hlsl(table)},
  };
  write_files_atomically(files);
  std::vector<std::string> paths;
  for (const auto& file : files) paths.push_back(file.first);
  return paths;
}

}  // namespace rsaa
