// Offset tables: one resampling offset per similarity mask (docs/conventions.md section 3), and
// their three file forms (JSON, GLSL include, HLSL include).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/rsaa/mask.h"
#include "core/rsaa/sample_pattern.h"
#include "core/util/vec2.h"

namespace rsaa {

// Which rule produced a table entry. Scene: fitted on cases harvested from a scene's renders
// (rsaa train --from-scene); an addition to docs/conventions.md section 3's three values.
enum class OffsetSource { OneLine, TwoLine, Fallback, Scene };
constexpr int kOffsetSourceCount = 4;
const char* to_string(OffsetSource source);  // "one-line", "two-line", "fallback", "scene"

// Read budget of a table file: the 16x table is under 3 MB.
constexpr std::uint64_t kMaxTableFileBytes = std::uint64_t{16} << 20;

// Tables are 2^n entries; beyond 16 samples they stop being practical lookup tables.
constexpr int kMaxTableSamples = 16;

struct OffsetTable {
  SamplePattern pattern;
  std::vector<Vec2> offsets;               // index = mask; pixel space (y down); |dx|,|dy| <= 1
  std::vector<OffsetSource> sources;       // index = mask
  std::vector<std::uint64_t> cases_per_mask;  // training cases that produced each mask
  nlohmann::json training = nlohmann::json::object();  // command and options that made it

  Vec2 offset(Mask mask) const { return offsets.at(mask); }
};

// A table of the right size for `pattern` with every entry set by the fallback rule.
OffsetTable fallback_table(const SamplePattern& pattern);

// Thrown for every problem with a table file; the message names the file and the field.
class TableError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Reads and validates a table (format, version, pattern, samples, entry counts, finite offsets
// within [-1, 1], sources, case counts, and the set id when there is one: it must be the id of
// the contents). `origin` names the file in error messages.
OffsetTable parse_offset_table(const std::string& text, const std::string& origin);
// The same from a file P.json; the P.glsl and P.hlsl beside it, where they exist, must carry
// the JSON's set id (one write), else a TableError names the file that is not of the set. Reads
// through a commit journal (read_committed_file): a set whose writer was killed among its
// renames is read as that commit finishes it.
OffsetTable read_offset_table(const std::string& path);

// The id written in all three files of a table (JSON "set_id", a "// Table set id:" line in the
// GLSL and HLSL): 16 hex digits of a hash of the JSON's contents, so the same table gives the
// same bytes and a file of another write another id.
std::string table_set_id(const OffsetTable& table);

// File texts. Deterministic: the same table gives the same bytes.
std::string offset_table_json(const OffsetTable& table);
// GLSL: OpenGL window space (+y up), so the offsets are (dx, -dy) of the JSON.
std::string offset_table_glsl(const OffsetTable& table);
// HLSL: pixel space (+y down), the JSON's numbers.
std::string offset_table_hlsl(const OffsetTable& table);

// Writes DIR/STEM.json, DIR/STEM.glsl and DIR/STEM.hlsl together (all or none); STEM is the
// pattern name unless given. Refuses (std::invalid_argument) a stem or pattern name that is not
// a valid pattern name and a table the reader would refuse (non-finite or |offset| > 1).
// Returns the paths.
std::vector<std::string> write_offset_table_files(const OffsetTable& table, const std::string& dir,
                                                  const std::string& stem = "");

}  // namespace rsaa
