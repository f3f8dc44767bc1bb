// Offset-table files: a corpus of broken tables and mutations of a valid one. The reader must
// answer each with a valid table or a TableError naming the file.
#include <sstream>

#include "core/util/atomic_file.h"
#include "core/rsaa/offset_table.h"
#include "tools/reliability/mutate.h"
#include "tools/reliability/suite.h"

namespace rsaa::reliability {

void SuiteResult::add(Outcome outcome, const std::string& label, const std::string& detail) {
  ++inputs;
  switch (outcome) {
    case Outcome::kRejectedClearly: ++rejected; break;
    case Outcome::kAccepted: ++accepted; break;
    case Outcome::kFailed:
      ++failed;
      if (failures.size() < 5) failures.push_back(label + ": " + detail);
      break;
  }
}

namespace {

std::string valid_table_text() {
  return read_whole_file(std::string(RSAA_SOURCE_DIR) + "/tables/d3d8x.json");
}

Outcome feed_table(const std::string& text, const std::string& origin, std::string& detail) {
  try {
    const OffsetTable t = parse_offset_table(text, origin);
    for (const Vec2& d : t.offsets)
      if (!is_finite(d) || std::abs(d.x) > 1.0 || std::abs(d.y) > 1.0) {
        detail = "accepted an offset outside [-1, 1]";
        return Outcome::kFailed;
      }
    return Outcome::kAccepted;
  } catch (const TableError& e) {
    detail = e.what();
    return detail.rfind(origin + ": ", 0) == 0 ? Outcome::kRejectedClearly : Outcome::kFailed;
  } catch (const std::exception& e) {
    detail = std::string("unexpected exception: ") + e.what();
    return Outcome::kFailed;
  }
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

}  // namespace

SuiteResult table_corpus(const Options&) {
  const std::string good = valid_table_text();
  std::vector<std::pair<std::string, std::string>> corpus = {
      {"empty", ""},
      {"whitespace", " \n\t "},
      {"not JSON", "rsaa offset table"},
      {"a JSON array", "[1, 2, 3]"},
      {"non-UTF-8 pattern", replaced(good, "\"d3d8x\"", "\"d3d\xff\xfe\"")},
      {"wrong type: version", replaced(good, "\"version\": 1", "\"version\": \"1\"")},
      {"wrong type: samples", replaced(good, "\"samples\": [", "\"samples\": 7, \"x\": [")},
      {"wrong type: offsets", replaced(good, "\"offsets\": [", "\"offsets\": {\"a\": 1}, \"x\": [")},
      {"wrong type: source", replaced(good, "\"source\": [", "\"source\": \"one-line\", \"x\": [")},
      {"NaN offset", replaced(good, "\"offsets\": [\n    [", "\"offsets\": [\n    [NaN, ")},
      {"infinite offset", replaced(good, "\"offsets\": [\n    [", "\"offsets\": [\n    [1e999, ")},
      {"offset 1.5", replaced(good, "\"offsets\": [\n    [", "\"offsets\": [\n    [1.5, 0], [")},
      {"huge case count", replaced(good, "\"cases_per_mask\": [\n    ", "\"cases_per_mask\": [\n    1e30, ")},
      {"unknown pattern", replaced(good, "\"d3d8x\"", "\"d3d9x\"")},
      {"wrong pattern size", replaced(good, "[0.0625, -0.1875], ", "")},
      {"y axis up", replaced(good, "\"y_axis\": \"down\"", "\"y_axis\": \"up\"")},
      {"version 2", replaced(good, "\"version\": 1", "\"version\": 2")},
      {"missing training", replaced(good, "\"training\":", "\"trainin\":")},
      {"deep nesting", std::string(100000, '[') + std::string(100000, ']')},
      {"huge offsets array", replaced(good, "\"offsets\": [\n", "\"offsets\": [\n" + [] {
         std::string many;
         for (int i = 0; i < 200000; ++i) many += "[0, 0], ";
         return many;
       }())},
  };
  for (std::size_t cut : {1, 10, 100, 1000, 5000, 11000}) corpus.push_back({"truncated at " + std::to_string(cut), good.substr(0, cut)});
  SuiteResult r{"table JSON: corpus of broken files", 0, 0, 0, 0, {}};
  for (const auto& [label, text] : corpus) {
    std::string detail;
    Outcome o = feed_table(text, label + ".json", detail);
    if (o == Outcome::kAccepted) o = Outcome::kFailed, detail = "a broken table was accepted";
    r.add(o, label, detail);
  }
  return r;
}

SuiteResult table_fuzz(const Options& options) {
  const std::string good = valid_table_text();
  SuiteResult r{"table JSON: mutations of tables/d3d8x.json", 0, 0, 0, 0, {}};
  for (std::uint64_t i = 0; i < options.iterations; ++i) {
    std::string detail;
    const std::string origin = "mutation-" + std::to_string(i) + ".json";
    const Outcome o = feed_table(mutate(good, options.seed, i), origin, detail);
    r.add(o, origin, detail);
  }
  return r;
}

}  // namespace rsaa::reliability
