// The GLSL and HLSL tables compile inside a shader that indexes them, and carry the JSON's
// numbers: GLSL with y flipped (OpenGL window space), HLSL as is (pixel space).
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>

#include "core/rsaa/conventions.h"
#include "core/rsaa/offset_table.h"
#include "tests/test_util.h"
#include "trainer/train.h"

namespace rsaa {
namespace {

// The (x, y) pairs of every `vec2(x, y)` / `float2(x, y)` after the declaration of `array`.
std::vector<Vec2> array_literals(const std::string& text, const std::string& array) {
  const std::size_t start = text.find(array + "[");
  EXPECT_NE(start, std::string::npos) << array;
  const std::size_t end = text.find(';', start);
  const std::string body = text.substr(start, end - start);
  static const std::regex pair(R"((?:vec2|float2)\(([-+0-9.eE]+), ([-+0-9.eE]+)\))");
  std::vector<Vec2> out;
  for (auto it = std::sregex_iterator(body.begin(), body.end(), pair); it != std::sregex_iterator();
       ++it)
    out.push_back({std::stod((*it)[1]), std::stod((*it)[2])});
  return out;
}

void expect_glsl_compiles(const std::string& table_glsl) {
  test::TempDir dir;
  test::write_text(dir.file("t.frag"),
                   "#version 450\n" + table_glsl +
                       "layout(location = 0) flat in uint mask;\n"
                       "layout(location = 0) out vec4 colour;\n"
                       "void main() { colour = vec4(rsaa_offsets[mask % RSAA_TABLE_MASK_COUNT], "
                       "rsaa_sample_positions[RSAA_TABLE_SAMPLE_COUNT - 1]); }\n");
  const auto r = test::run_command("glslangValidator -S frag " + dir.file("t.frag"));
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

void expect_hlsl_compiles(const std::string& table_hlsl) {
  test::TempDir dir;
  test::write_text(dir.file("t.hlsl"),
                   table_hlsl +
                       "float4 main(uint mask : MASK) : SV_Target {\n"
                       "  return float4(rsaa_offsets[mask % RSAA_TABLE_MASK_COUNT],\n"
                       "                rsaa_sample_positions[RSAA_TABLE_SAMPLE_COUNT - 1]);\n}\n");
  const auto r = test::run_command("glslangValidator -D -V -S frag -e main -o " +
                                   dir.file("t.spv") + " " + dir.file("t.hlsl"));
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

void expect_agreement(const OffsetTable& json, const std::string& glsl, const std::string& hlsl) {
  const auto glsl_offsets = array_literals(glsl, "rsaa_offsets");
  const auto hlsl_offsets = array_literals(hlsl, "rsaa_offsets");
  ASSERT_EQ(glsl_offsets.size(), json.offsets.size());
  ASSERT_EQ(hlsl_offsets.size(), json.offsets.size());
  for (std::size_t m = 0; m < json.offsets.size(); ++m) {
    const Vec2 gl = gl_to_pixel(glsl_offsets[m]);
    ASSERT_NEAR(gl.x, json.offsets[m].x, 1e-8) << "GLSL mask " << m;
    ASSERT_NEAR(gl.y, json.offsets[m].y, 1e-8) << "GLSL mask " << m;
    ASSERT_NEAR(hlsl_offsets[m].x, json.offsets[m].x, 1e-8) << "HLSL mask " << m;
    ASSERT_NEAR(hlsl_offsets[m].y, json.offsets[m].y, 1e-8) << "HLSL mask " << m;
  }
  const auto glsl_samples = array_literals(glsl, "rsaa_sample_positions");
  ASSERT_EQ(glsl_samples.size(), std::size_t(json.pattern.size()));
  for (int i = 0; i < json.pattern.size(); ++i)
    EXPECT_EQ(gl_to_pixel(glsl_samples[i]), json.pattern.positions[i]);
  EXPECT_NE(glsl.find("+y UP"), std::string::npos);
  EXPECT_NE(hlsl.find("+y DOWN"), std::string::npos);
}

TEST(ShaderTables, FreshlyTrainedTableCompilesAndAgrees) {
  TrainOptions o;
  o.pattern = builtin_pattern("d3d8x");
  o.cases = 20000;
  const OffsetTable t = train_offset_table(o).table;
  const std::string glsl = offset_table_glsl(t), hlsl = offset_table_hlsl(t);
  expect_glsl_compiles(glsl);
  expect_hlsl_compiles(hlsl);
  expect_agreement(t, glsl, hlsl);
}

TEST(ShaderTables, BrokenShaderIsRejected) {
  // The compile check itself can fail: a table text with an error does not pass.
  test::TempDir dir;
  test::write_text(dir.file("t.frag"), "#version 450\nconst vec2 x[2] = vec2[2](vec2(1, 2));\n"
                                       "void main() {}\n");
  EXPECT_NE(test::run_command("glslangValidator -S frag " + dir.file("t.frag")).exit_code, 0);
}

class CheckedInTables : public ::testing::TestWithParam<std::string> {};

TEST_P(CheckedInTables, CompileAndAgreeWithTheirJson) {
  const std::string base = std::string(RSAA_SOURCE_DIR) + "/tables/" + GetParam();
  ASSERT_TRUE(std::filesystem::exists(base + ".json")) << base << ".json is missing";
  const OffsetTable t = read_offset_table(base + ".json");
  const std::string glsl = test::read_text(base + ".glsl"), hlsl = test::read_text(base + ".hlsl");
  expect_agreement(t, glsl, hlsl);
  // The checked-in files are exactly what the writer makes of the JSON.
  EXPECT_TRUE(glsl == offset_table_glsl(t)) << base << ".glsl is stale";
  EXPECT_TRUE(hlsl == offset_table_hlsl(t)) << base << ".hlsl is stale";
  expect_glsl_compiles(glsl);
  expect_hlsl_compiles(hlsl);
}

INSTANTIATE_TEST_SUITE_P(Tables, CheckedInTables, ::testing::Values("d3d4x", "d3d8x", "d3d16x", "custom-gl4x-union", "custom-gl4x-wide",
                                                                "custom-gl4x-tall", "custom-gl4x-quad"));

}  // namespace
}  // namespace rsaa
