// Offset-table JSON: round trip, and a clear TableError for each kind of broken file.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/rsaa/offset_table.h"
#include "core/util/printable.h"
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

// The JSON text without its set id line: a table as written by hand, whose fields are then
// checked one by one (with the id, any edit is refused as not matching it).
std::string without_set_id(std::string text) {
  const std::size_t at = text.find("  \"set_id\"");
  EXPECT_NE(at, std::string::npos);
  return text.erase(at, text.find('\n', at) + 1 - at);
}

// Replaces the first occurrence of `from` in the JSON text of the small table (no set id).
std::string edited(const std::string& from, const std::string& to) {
  std::string text = without_set_id(offset_table_json(small_table()));
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
  // A repeated key is refused wherever it stands (nlohmann would keep the last one silently);
  // one key in two objects is fine.
  expect_rejected(edited("\"format\": \"rsaa-offset-table\",", "\"pattern\": \"gl4x\", \"format\": \"rsaa-offset-table\","),
                  "the key \"pattern\" appears twice in one object");
  expect_rejected(edited("\"training\": {", "\"training\": {\"a\": 1, \"a\": 2, "), "the key \"a\" appears twice");
  EXPECT_NO_THROW(parse_offset_table(edited("\"training\": {", "\"training\": {\"x\": {\"a\": 1}, \"y\": {\"a\": 2}, "),
                                     "twice.json"));
  // Nested 100,000 deep (eval-table --json echoed it in quadratic space) or very many values.
  const std::size_t depth = 100000;
  expect_rejected(edited("\"training\": {", "\"training\": {\"x\": " + std::string(depth, '[') +
                                                 std::string(depth, ']') + ", "),
                  "training: expected an object of at most 4096 values nested at most 16 levels");
  std::string many = "[0";
  for (int i = 0; i < 5000; ++i) many += ",0";
  expect_rejected(edited("\"training\": {", "\"training\": {\"x\": " + many + "], "), "training: expected");
  // Nested 16 levels in all is still read.
  EXPECT_NO_THROW(parse_offset_table(
      edited("\"training\": {", "\"training\": {\"x\": " + std::string(14, '[') + "1" + std::string(14, ']') + ", "),
      "deep.json"));
}

// The set id: the same in the three files, a function of the contents, checked by the reader.
TEST(OffsetTableJson, TheSetIdIsTheContentsAndAnEditIsRefused) {
  const OffsetTable t = small_table();
  const std::string id = table_set_id(t);
  ASSERT_EQ(id.size(), 16u);
  EXPECT_NE(offset_table_json(t).find("\"set_id\": \"" + id + "\""), std::string::npos);
  EXPECT_NE(offset_table_glsl(t).find("// Table set id: " + id), std::string::npos);
  EXPECT_NE(offset_table_hlsl(t).find("// Table set id: " + id), std::string::npos);
  OffsetTable other = t;
  other.offsets[3].x = 0.125;
  EXPECT_NE(table_set_id(other), id);
  // An edit of a table that carries its id: refused, naming the field.
  std::string text = offset_table_json(t);
  text.replace(text.find("0.123456"), 8, "0.125");
  expect_rejected(text, "set_id: is \"" + id + "\" but the contents give");
  // The same edit without the id: a hand-written table, read alone.
  EXPECT_NO_THROW(parse_offset_table(without_set_id(text), "hand.json"));
}

// A set mixed by hand (a .glsl of another write beside the JSON) is refused naming the file;
// one without its shader files is read alone.
TEST(OffsetTableFiles, AMixedSetIsRefusedNamingTheFileOfAnotherWrite) {
  test::TempDir dir;
  OffsetTable other = small_table();
  other.offsets[3].x = 0.125;
  write_offset_table_files(small_table(), dir.path());
  test::write_text(dir.file("d3d4x.hlsl"), offset_table_hlsl(other));
  try {
    read_offset_table(dir.file("d3d4x.json"));
    ADD_FAILURE() << "a mixed set was read";
  } catch (const TableError& e) {
    EXPECT_NE(std::string(e.what()).find(dir.file("d3d4x.hlsl") + " is not of the same write as"), std::string::npos) << e.what();
  }
  std::filesystem::remove(dir.file("d3d4x.hlsl"));
  std::filesystem::remove(dir.file("d3d4x.glsl"));
  EXPECT_EQ(read_offset_table(dir.file("d3d4x.json")).offsets[3], small_table().offsets[3]);
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

// Text from files printed or written into comments: C0 and C1 controls escaped, UTF-8 kept, a
// newline kept only where asked (an error's compile log), nothing escaped twice.
TEST(Printable, EscapesControlsAndKeepsUtf8) {
  EXPECT_EQ(printable("plain text: a/b c.json"), "plain text: a/b c.json");
  EXPECT_EQ(printable("a\nb\tc\x1b[2J\x7f"), "a\\x0ab\\x09c\\x1b[2J\\x7f");
  EXPECT_EQ(printable("a\nb\tc\r", true), "a\nb\tc\\x0d");
  EXPECT_EQ(printable("caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x99\x82"), "caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x99\x82");
  EXPECT_EQ(printable("\xc2\x9b" "1m"), "\\xc2\\x9b1m");      // U+009B, CSI
  EXPECT_EQ(printable("\x9b" "1m"), "\\x9b1m");                // a lone C1 byte
  EXPECT_EQ(printable("\xc3"), "\\xc3");                        // a cut sequence
  EXPECT_EQ(printable("\xc2\xa0"), "\xc2\xa0");                // U+00A0 stays
  const std::string once = printable("x\x1b\x9b\n");
  EXPECT_EQ(printable(once), once);
}

}  // namespace
}  // namespace rsaa
