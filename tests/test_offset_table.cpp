// Offset-table JSON: round trip, and a clear TableError for each kind of broken file.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/rsaa/offset_table.h"
#include "tests/test_util.h"

namespace rsaa {
namespace {

OffsetTable small_table() {
  OffsetTable t = fallback_table(builtin_pattern("d3d4x"));
  t.sources[3] = OffsetSource::OneLine;
  t.sources[5] = OffsetSource::TwoLine;
  t.cases_per_mask[3] = 424242;
  t.offsets[3] = {0.123456, -0.654321};
  t.training = {{"command", "rsaa train --pattern d3d4x"}, {"seed", 1}};
  return t;
}

// Replaces the first occurrence of `from` in the JSON text of the small table.
std::string edited(const std::string& from, const std::string& to) {
  std::string text = offset_table_json(small_table());
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

void expect_rejected(const std::string& text, const std::string& message_part) {
  try {
    parse_offset_table(text, "broken.json");
    ADD_FAILURE() << "accepted a table that should fail with: " << message_part;
  } catch (const TableError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("broken.json: ", 0), 0u) << what;
    EXPECT_NE(what.find(message_part), std::string::npos) << what;
  }
}

TEST(OffsetTableJson, RoundTripsExactly) {
  const OffsetTable t = small_table();
  const std::string text = offset_table_json(t);
  const OffsetTable back = parse_offset_table(text, "mem");
  EXPECT_EQ(back.pattern.name, "d3d4x");
  EXPECT_EQ(back.offsets[3], t.offsets[3]);
  EXPECT_EQ(back.sources[5], OffsetSource::TwoLine);
  EXPECT_EQ(back.cases_per_mask[3], 424242u);
  EXPECT_EQ(back.training, t.training);
  EXPECT_EQ(offset_table_json(back), text);  // same bytes
}

TEST(OffsetTableJson, RejectsBrokenFiles) {
  const std::string good = offset_table_json(small_table());
  expect_rejected(good.substr(0, good.size() / 2), "not valid JSON");
  expect_rejected("", "not valid JSON");
  expect_rejected("[1, 2]", "expected a JSON object");
  expect_rejected(edited("\"format\": \"rsaa-offset-table\",", ""), "format: missing field");
  expect_rejected(edited("\"version\": 1", "\"version\": 2"), "version");
  expect_rejected(edited("\"pattern\": \"d3d4x\"", "\"pattern\": \"d3d5x\""), "unknown pattern");
  expect_rejected(edited("\"y_axis\": \"down\"", "\"y_axis\": \"up\""), "y_axis");
  expect_rejected(edited("[0.123456, -0.654321],", ""), "offsets: has 15 entries; expected 16");
  expect_rejected(edited("0.123456", "NaN"), "not valid JSON");
  expect_rejected(edited("0.123456", "1e999"), "number overflow");
  expect_rejected(edited("0.123456", "1.5"), "offsets[3]: expected finite numbers within [-1, 1]");
  expect_rejected(edited("0.123456", "\"x\""), "offsets[3]: expected a pair of numbers");
  expect_rejected(edited("\"one-line\"", "\"three-line\""), "source[3]");
  EXPECT_NO_THROW(parse_offset_table(edited("\"one-line\"", "\"scene\""), "scene.json"));
  expect_rejected(edited("424242", "-1"), "cases_per_mask[3]");
  expect_rejected(edited("424242", "0.5"), "cases_per_mask[3]");
  expect_rejected(edited("[-0.125, -0.375]", "[-0.125, -0.4]"), "does not match the built-in");
  expect_rejected(edited("[-0.125, -0.375], ", ""), "pattern d3d4x has 4 samples");
  expect_rejected(edited("\"training\": {", "\"training\": 3, \"x\": {"), "training: expected an object");
}

TEST(OffsetTableJson, CustomPatternsCarryTheirSamples) {
  OffsetTable t = fallback_table(pattern_from_positions("custom-two", {{0.25, 0.0}, {-0.25, 0.1}}));
  const OffsetTable back = parse_offset_table(offset_table_json(t), "mem");
  EXPECT_EQ(back.pattern.positions[1], (Vec2{-0.25, 0.1}));
  EXPECT_EQ(back.offsets.size(), 4u);
}

TEST(OffsetTableFiles, MissingFileAndUnwritableDirectoryAreClearErrors) {
  EXPECT_THROW(read_offset_table("/nonexistent/t.json"), TableError);
  try {
    write_offset_table_files(small_table(), "/nonexistent-dir");
    ADD_FAILURE();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-dir/d3d4x.json"), std::string::npos);
  }
  test::TempDir dir;
  const auto paths = write_offset_table_files(small_table(), dir.path());
  EXPECT_EQ(paths.size(), 3u);
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()),
                          std::filesystem::directory_iterator()),
            3);  // no temporaries left behind
  EXPECT_EQ(read_offset_table(paths[0]).offsets[3], small_table().offsets[3]);
}

}  // namespace
}  // namespace rsaa
