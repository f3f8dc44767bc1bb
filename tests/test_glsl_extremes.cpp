// The shared GLSL (shaders/rsaa_common.glsl) at the extremes, run on the GL driver itself through
// a compute shader, against closed forms.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "runtime/gl_context.h"
#include "tests/gl_test.h"
#include "runtime/gl_objects.h"
#include "runtime/shader_library.h"

namespace rsaa {
namespace {

struct ProbeCase {
  float p1[4], n1[4], p2[4], n2[4];  // p1.w: a value to encode as a similarity code
};

struct ProbeResult {
  float sadp, depth_difference, decoded, plane_gap;
  std::uint32_t code, code_of_zero, code_max;
  float decoded_max;  // rsaa_decode_similarity(RSAA_PROBE_CODE): another surface than geometry says
};

// Evaluates the shared functions for each case with the given code bits.
std::vector<ProbeResult> probe(const std::vector<ProbeCase>& cases, int code_bits,
                               const std::string& defines = "") {
  const std::string source = gl::shader_source("rsaa_common.glsl") + R"(
#ifndef RSAA_PROBE_CODE
#define RSAA_PROBE_CODE RSAA_CODE_MAX
#endif
layout(local_size_x = 1) in;
struct Case { vec4 p1; vec4 n1; vec4 p2; vec4 n2; };
struct Result { vec4 values; uvec4 codes; };
layout(std430, binding = 0) readonly buffer Cases { Case cases[]; };
layout(std430, binding = 1) writeonly buffer Results { Result results[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  Case c = cases[i];
  uint code = rsaa_encode_similarity(c.p1.w);
  results[i].values = vec4(rsaa_sadp(c.p1.xyz - c.p2.xyz, c.n1.xyz, c.n2.xyz),
                           rsaa_depth_difference(c.p1.xyz, c.p2.xyz),
                           rsaa_decode_similarity(code, true),
                           rsaa_plane_gap(c.p1.xyz, c.n1.xyz, c.p2.xyz, c.n2.xyz));
  results[i].codes = uvec4(code, rsaa_encode_similarity(0.0), RSAA_CODE_MAX,
                           floatBitsToUint(rsaa_decode_similarity(RSAA_PROBE_CODE, true)));
})";
  const gl::Program program = gl::make_program(
      {{GL_COMPUTE_SHADER, source}}, "#define RSAA_CODE_BITS " + std::to_string(code_bits) + "\n" + defines,
      "GLSL probe");
  GLuint buffers[2];
  glCreateBuffers(2, buffers);
  const gl::Buffer in(buffers[0]), out(buffers[1]);
  glNamedBufferStorage(in.get(), GLsizeiptr(cases.size() * sizeof(ProbeCase)), cases.data(), 0);
  glNamedBufferStorage(out.get(), GLsizeiptr(cases.size() * sizeof(ProbeResult)), nullptr,
                       GL_MAP_READ_BIT);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.get());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, out.get());
  glUseProgram(program.get());
  glDispatchCompute(GLuint(cases.size()), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<ProbeResult> results(cases.size());
  glGetNamedBufferSubData(out.get(), 0, GLsizeiptr(results.size() * sizeof(ProbeResult)), results.data());
  gl::check("GLSL probe");
  return results;
}

ProbeCase make_case(std::array<float, 3> p1, std::array<float, 3> n1, std::array<float, 3> p2,
                    std::array<float, 3> n2, float value = 0.0f) {
  return {{p1[0], p1[1], p1[2], value}, {n1[0], n1[1], n1[2], 0}, {p2[0], p2[1], p2[2], 0}, {n2[0], n2[1], n2[2], 0}};
}

class GlslExtremes : public test::GlTest {};

const float kNan = std::numeric_limits<float>::quiet_NaN();
const std::array<float, 3> kZ = {0, 0, 1}, kX = {1, 0, 0};

TEST_F(GlslExtremes, SadpClosedForms) {
  const float s = std::sqrt(0.5f);
  const auto r = probe(
      {
          make_case({0, 0, -1}, kZ, {0, 0, -1}, kZ),                 // 0 coincident: 0
          make_case({0, 0, -1}, kZ, {1, 0, -1}, kZ),                 // 1 same plane: 0
          make_case({0, 0, -1}, kZ, {0, 0, -2}, kZ),                 // 2 along both normals: 2
          make_case({0, 0, -1}, kZ, {1, 0, -1}, kX),                 // 3 corner: 0 + 1
          make_case({0, 0, -1}, {s, 0, s}, {1, 0, -1}, kZ),          // 4 45 degrees: sqrt(1/2)
          make_case({0, 0, -1e-10f}, kZ, {0, 0, -2e-10f}, kZ),       // 5 tiny |r|: 2
          make_case({0, 0, 0}, kZ, {0, 0, 1e-13f}, kZ),              // 6 below 1e-12: same point
          make_case({0, 0, -1e30f}, kZ, {3e30f, 0, 1e30f}, kZ),       // 7 huge |r|: 2 * 2/sqrt(13)
          make_case({1e6f, 0, -1}, kZ, {1e6f + 0.5f, 0, -1}, kZ),    // 8 far from the origin: 0
          make_case({0, 0, -1}, {0, 0, 0}, {0, 0, -2}, kZ),          // 9 zero normal: one term, 1
          make_case({0, 0, -1}, {0, 0, 2}, {0, 0, -2}, kZ),          // 10 unnormalised: 2 + 1
          make_case({0, 0, -1}, {kNan, 0, 0}, {0, 0, -2}, kZ),        // 11 NaN normal: NaN
          make_case({0, 0, -1}, {0, 1e-7f, 1}, {1, 0, -1}, kZ),      // 12 grazing: ~0
      },
      8);
  EXPECT_EQ(r[0].sadp, 0.0f);
  EXPECT_EQ(r[1].sadp, 0.0f);
  EXPECT_NEAR(r[2].sadp, 2.0f, 1e-6f);
  EXPECT_NEAR(r[3].sadp, 1.0f, 1e-6f);
  EXPECT_NEAR(r[4].sadp, s, 1e-6f);
  EXPECT_NEAR(r[5].sadp, 2.0f, 1e-5f);
  EXPECT_EQ(r[6].sadp, 0.0f);
  EXPECT_NEAR(r[7].sadp, 4.0f / std::sqrt(13.0f), 1e-5f);
  EXPECT_EQ(r[8].sadp, 0.0f);
  EXPECT_NEAR(r[9].sadp, 1.0f, 1e-6f);
  EXPECT_NEAR(r[10].sadp, 3.0f, 1e-6f);
  EXPECT_TRUE(std::isnan(r[11].sadp));
  EXPECT_NEAR(r[12].sadp, 0.0f, 1e-6f);
  for (std::size_t i = 0; i < r.size(); ++i)
    if (i != 11) {
      EXPECT_TRUE(std::isfinite(r[i].sadp)) << i;
    }
}

TEST_F(GlslExtremes, DepthDifferenceNearAndFar) {
  const auto r = probe({make_case({0, 0, -0.001f}, kZ, {0, 0, -0.00101f}, kZ),  // near: 1 %
                        make_case({0, 0, -1e6f}, kZ, {0, 0, -1.01e6f}, kZ),   // far: 1 %
                        make_case({0, 0, 0}, kZ, {0, 0, 0}, kZ),              // both at 0: 0
                        make_case({0, 0, 0}, kZ, {0, 0, -1}, kZ)},            // one at 0: huge
                       8);
  EXPECT_NEAR(r[0].depth_difference, 1.0f, 1e-3f);
  EXPECT_NEAR(r[1].depth_difference, 1.0f, 1e-3f);
  EXPECT_EQ(r[2].depth_difference, 0.0f);
  EXPECT_TRUE(std::isfinite(r[3].depth_difference));
  EXPECT_GT(r[3].depth_difference, 1e20f);
}

TEST_F(GlslExtremes, CodesRoundTripAndSaturate) {
  const float values[] = {0.0f, 0.4f, 1.0f, 1.98f, 2.0f, 1e9f, 1e30f, kNan, -1.0f};
  for (int bits : {8, 16, 32}) {
    std::vector<ProbeCase> cases;
    for (float v : values) cases.push_back(make_case({0, 0, -1}, kZ, {0, 0, -1}, kZ, v));
    const auto r = probe(cases, bits);
    const double scale = bits == 32 ? std::ldexp(1.0, 30) : std::ldexp(1.0, bits - 1);
    const std::uint64_t max = bits == 32 ? 0xffffffffull : (1ull << bits) - 1;
    EXPECT_EQ(r[0].code_of_zero, 1u) << bits;                 // 0 is "same surface", not empty
    const double step = std::max(1.0 / scale, 1e-7);           // float precision bounds 32 bits
    EXPECT_NEAR(r[1].decoded, 0.4, step) << bits;               // quantised down to 1/scale
    EXPECT_LE(r[1].decoded, 0.4f) << bits;
    EXPECT_NEAR(r[2].decoded, 1.0, step) << bits;
    // Geometric values saturate one below the largest code, which is kept for another surface
    // (a background centre, another material) and decodes as 4 at every width, above any
    // saturated geometry.
    EXPECT_EQ(r[0].code_max, max) << bits;
    EXPECT_EQ(r[0].decoded_max, 4.0f) << bits;
    for (int k : {5, 6}) EXPECT_EQ(r[k].code, max - 1) << bits << " saturates below the largest code";
    EXPECT_EQ(r[7].code, 1u) << "NaN encodes as similar";
    EXPECT_EQ(r[8].code, 1u) << "negative clamps to 0";
    if (bits == 8) {
      EXPECT_EQ(r[4].code, max - 1) << "8 bits saturate at 253/128 = 1.98";
      EXPECT_NEAR(r[4].decoded, 253.0 / 128.0, 1e-6);
    }
    // Whatever a similarity measure gives (SADP and sadp-plane lie in [0, 2]) stays below
    // another surface's code.
    for (int k : {0, 1, 2, 3, 4}) EXPECT_LT(r[k].decoded, r[k].decoded_max) << bits << " value " << values[k];
    for (const auto& x : r) EXPECT_TRUE(std::isfinite(x.decoded));
    // With material edges the code below the largest is another material that the outside pixel
    // does not show: it decodes as the largest does, and geometry saturates below both.
    const auto m = probe(cases, bits, "#define RSAA_MATERIAL_EDGES\n#define RSAA_PROBE_CODE (RSAA_CODE_MAX - 1u)\n");
    EXPECT_EQ(m[0].decoded_max, 4.0f) << bits;
    for (int k : {5, 6}) EXPECT_EQ(m[k].code, max - 2) << bits << " saturates below both material codes";
    for (int k : {0, 1, 2}) EXPECT_EQ(m[k].code, r[k].code) << bits << " value " << values[k];
    for (int k : {0, 1, 2, 3, 4}) EXPECT_LT(m[k].decoded, m[k].decoded_max) << bits << " value " << values[k];
  }
}

}  // namespace
}  // namespace rsaa

namespace rsaa {
namespace {

// rsaa_classify for 8 similarities and a threshold per case.
std::vector<std::uint32_t> classify(const std::vector<std::array<float, 9>>& cases) {
  const std::string source = gl::shader_source("rsaa_common.glsl") + R"(
#ifndef RSAA_PROBE_CODE
#define RSAA_PROBE_CODE RSAA_CODE_MAX
#endif
layout(local_size_x = 1) in;
layout(std430, binding = 0) readonly buffer Cases { float values[]; };
layout(std430, binding = 1) writeonly buffer Masks { uint masks[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  float s[RSAA_SAMPLE_COUNT];
  for (int k = 0; k < RSAA_SAMPLE_COUNT; ++k) s[k] = values[i * 9u + uint(k)];
  float split;
  masks[i] = rsaa_classify(s, values[i * 9u + 8u], split);
})";
  const gl::Program program =
      gl::make_program({{GL_COMPUTE_SHADER, source}}, "#define RSAA_SAMPLE_COUNT 8\n", "classify probe");
  GLuint buffers[2];
  glCreateBuffers(2, buffers);
  const gl::Buffer in(buffers[0]), out(buffers[1]);
  glNamedBufferStorage(in.get(), GLsizeiptr(cases.size() * sizeof(cases[0])), cases.data(), 0);
  glNamedBufferStorage(out.get(), GLsizeiptr(cases.size() * 4), nullptr, 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.get());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, out.get());
  glUseProgram(program.get());
  glDispatchCompute(GLuint(cases.size()), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<std::uint32_t> masks(cases.size());
  glGetNamedBufferSubData(out.get(), 0, GLsizeiptr(masks.size() * 4), masks.data());
  gl::check("classify probe");
  return masks;
}

TEST_F(GlslExtremes, ClassificationAndItsThresholdLimits) {
  const auto m = classify({
      {0, 0, 0, 0, 0, 0, 0, 0, 0.4f},                             // no edge: all similar
      {0.4f, 0.4f, 0.4f, 0.5f, 1.1f, 1.2f, 1.2f, 1.3f, 0.4f},     // the paper's example
      {0, 0, 0, 0, 0, 0, 0, 1e-6f, 0.0f},                         // threshold 0
      {2, 2, 2, 2, 2, 2, 2, 2, 1e30f},                            // huge threshold: never
      {0.1f, 0.1f, 0.1f, 0.1f, 0.1f, 0.1f, 0.1f, 0.4f, 0.4f},     // maxsim == threshold: no edge
      {2, 2, 2, 2, 2, 2, 2, 2, 0.4f},                             // all different: mask 0
  });
  EXPECT_EQ(m[0], 255u);
  EXPECT_EQ(m[1], 0b00001111u);  // {0.4, 0.4, 0.4, 0.5} similar, as section 2.2 says
  EXPECT_EQ(m[2], 0b01111111u);
  EXPECT_EQ(m[3], 255u);
  EXPECT_EQ(m[4], 255u);
  EXPECT_EQ(m[5], 0u);
}

// Depth codes keep large relative depth differences apart (stored on a log scale), so the
// k-means split stays adaptive: linear codes saturated at 2% (8 and 16 bits).
TEST_F(GlslExtremes, DepthCodesStayDistinctAboveTwoPercent) {
  const std::vector<float> percents = {0.1f, 0.4f, 1.0f, 2.0f, 3.0f, 5.0f, 10.0f, 20.0f, 50.0f, 100.0f, 500.0f};
  for (int bits : {8, 16, 32}) {
    std::vector<ProbeCase> cases;
    for (float v : percents) cases.push_back(make_case({0, 0, -1}, kZ, {0, 0, -1}, kZ, v));
    const auto r = probe(cases, bits, "#define RSAA_SIMILARITY_DEPTH\n");
    for (std::size_t i = 0; i < percents.size(); ++i) {
      if (i > 0) {
        EXPECT_GT(r[i].code, r[i - 1].code) << bits << " bits, " << percents[i] << "%";
      }
      // Decoded within the code's resolution: 1/16 of an octave of (1 + v / 0.05%) at 8 bits.
      EXPECT_NEAR(r[i].decoded, percents[i], 0.05f * (percents[i] + 0.05f)) << bits << " bits";
      // Below the saturation and below another surface (the largest code, rsaa_decode_similarity).
      EXPECT_LT(r[i].code, r[i].code_max - 1) << bits << " bits, " << percents[i] << "%";
      EXPECT_GT(r[i].decoded_max, 1e3f * r[i].decoded) << bits << " bits";
    }
  }
}

// The plane gap: 0 for two points of one plane however obliquely it is seen; for parallel planes
// the gap along the view ray in percent of the depth; 0 (unknown) when both planes are edge-on.
TEST_F(GlslExtremes, PlaneGapClosedForms) {
  const std::array<float, 3> up = {0, 1, 0};
  const std::vector<ProbeCase> cases = {
      make_case({0, -1, -10}, up, {0.3f, -1, -30}, up),  // one floor plane (about 6 degrees): 0
      // Two parallel floors met by one ray, at 10 and 9 units: the second point lies 1 unit
      // beyond the first floor along the ray, 1/9 = 11.1% of its own depth.
      make_case({0, -1, -10}, up, {0, -0.9f, -9}, up),
      make_case({0, 0, -10}, kX, {0, 0, -12}, kX),  // both planes edge-on to the ray: unknown
  };
  const auto r = probe(cases, 8);
  EXPECT_NEAR(r[0].plane_gap, 0.0f, 1e-4f);
  EXPECT_NEAR(r[1].plane_gap, 100.0f / 9.0f, 1e-3f);
  EXPECT_EQ(r[2].plane_gap, 0.0f);
}

}  // namespace
}  // namespace rsaa
