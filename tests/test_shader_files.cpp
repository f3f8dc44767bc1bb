// The shader files an engine includes (shaders/rsaa_prepass.glsl, rsaa_post.glsl, rsaa_post.hlsl):
// usable through a standard include mechanism (GL_GOOGLE_include_directive, glslangValidator -I)
// and as one expanded text; the HLSL post-process compiles for every table and option and,
// compiled to SPIR-V (glslangValidator -D) and back to GLSL (spirv-cross), gives the image of the
// GLSL post-process on a real frame: same algorithm, Direct3D's conventions handled right.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

#include <glm/gtc/type_ptr.hpp>

#include "core/rsaa/conventions.h"
#include "core/rsaa/sample_pattern.h"
#include "runtime/fullscreen.h"
#include "runtime/gl_objects.h"
#include "runtime/render.h"
#include "runtime/rsaa_pass.h"
#include "runtime/scene.h"
#include "runtime/scene_renderer.h"
#include "runtime/shader_library.h"
#include "tests/gl_test.h"
#include "tests/test_util.h"

namespace rsaa {
namespace {

const std::string kShaders = std::string(RSAA_SOURCE_DIR) + "/shaders";
const std::string kTables = std::string(RSAA_SOURCE_DIR) + "/tables";

struct Configuration {
  RsaaSettings settings;
  int samples;
  bool multisample;
};

std::vector<Configuration> configurations() {
  RsaaSettings depth_auth2, sadp_auth1, plane;
  depth_auth2.similarity = "depth", depth_auth2.auth = 2, depth_auth2.code_bits = 16;
  sadp_auth1.similarity = "sadp", sadp_auth1.auth = 1, sadp_auth1.code_bits = 32;
  return {{plane, 8, false}, {depth_auth2, 4, true}, {sadp_auth1, 16, false}};
}

// Compiles `text` as a `stage` shader with glslangValidator; returns its output when it fails.
std::string glslang_errors(const std::string& stage, const std::string& text, const std::string& flags = "") {
  test::TempDir dir;
  test::write_text(dir.file("t." + stage), text);
  const auto r = test::run_command("glslangValidator " + flags + " " + dir.file("t." + stage));
  return r.exit_code == 0 ? "" : r.output + "\n--- source:\n" + text;
}

const char* kIncludeHeader = "#version 450\n#extension GL_GOOGLE_include_directive : require\n";

TEST(ShaderFiles, ThePrePassAndPostProcessCompileThroughAnIncludeDirective) {
  // (-l: glslangValidator resolves includes when it links, not when it only validates)
  const std::string includes = "-l -I" + kShaders + " -I" + kTables;
  for (const Configuration& c : configurations()) {
    const std::string defines = rsaa_shader_defines(c.settings, c.samples, c.multisample);
    EXPECT_EQ(glslang_errors("vert", kIncludeHeader + defines + "#define RSAA_INCLUDE_FS 0\n"
                                     "#include \"rsaa_prepass.glsl\"\n"
                                     "layout(location = 0) in vec3 p;\n"
                                     "void main() { gl_Position = rsaa_jitter(vec4(p, 1.0)); }\n",
                             includes),
              "");
    EXPECT_EQ(glslang_errors("frag", kIncludeHeader + defines + "#include \"rsaa_prepass.glsl\"\n"
                                     "in vec3 v;\nlayout(location = 0) out uvec4 o;\n"
                                     "void main() { o = rsaa_prepass_code(v, rsaa_face_normal(v), 1u); }\n",
                             includes),
              "");
    const std::string post_main = "layout(location = 0) out vec4 o;\n"
                                  "void main() { uint m; o = rsaa_resolve(ivec2(gl_FragCoord.xy), m); }\n";
    EXPECT_EQ(glslang_errors("frag", kIncludeHeader + defines + "#include \"rsaa_post.glsl\"\n" + post_main, includes), "");
    // Offsets from a table include instead of the table texture.
    const std::string table = c.samples == 4 ? "d3d4x" : c.samples == 8 ? "d3d8x" : "d3d16x";
    EXPECT_EQ(glslang_errors("frag", kIncludeHeader + defines + "#define RSAA_TABLE_ARRAY\n#include \"" + table +
                                         ".glsl\"\n#include \"rsaa_post.glsl\"\n" + post_main,
                             includes),
              "");
    // The same as one expanded text, nothing to include.
    EXPECT_EQ(glslang_errors("frag", "#version 450\n" + defines + rsaa_shader_file("rsaa_post.glsl") + post_main), "");
  }
}

TEST(ShaderFiles, AWrongTableForTheSampleCountIsACompileError) {
  RsaaSettings settings;
  const std::string errors =
      glslang_errors("frag", kIncludeHeader + rsaa_shader_defines(settings, 8, false) +
                                 "#define RSAA_TABLE_ARRAY\n#include \"d3d4x.glsl\"\n#include \"rsaa_post.glsl\"\n"
                                 "void main() {}\n",
                     "-l -I" + kShaders + " -I" + kTables);
  EXPECT_NE(errors.find("another sample count"), std::string::npos) << errors;
}

// Compiles the HLSL post-process for `table` (a file of tables/) to SPIR-V (`spirv_file`); false
// and the log when glslang refuses it.
bool compile_hlsl_post(const test::TempDir& dir, const std::string& table, const std::string& defines,
                       const std::string& spirv_file, std::string& log) {
  test::write_text(dir.file("post.hlsl"), "#include \"" + table + ".hlsl\"\n#include \"rsaa_post.hlsl\"\n");
  const auto r = test::run_command("glslangValidator -D -V -S frag -e RsaaPostPS -I" + kTables + " -I" + kShaders +
                                   " " + defines + " -o " + spirv_file + " " + dir.file("post.hlsl"));
  log = r.output;
  return r.exit_code == 0;
}

TEST(HlslPostProcess, CompilesForEveryTableAndOption) {
  test::TempDir dir;
  for (const auto& entry : std::filesystem::directory_iterator(kTables)) {
    if (entry.path().extension() != ".hlsl") continue;
    const std::string table = entry.path().stem().string();
    const std::string text = test::read_text(entry.path().string());
    const std::size_t at = text.find("RSAA_TABLE_SAMPLE_COUNT ");
    ASSERT_NE(at, std::string::npos) << table;
    const int samples = std::stoi(text.substr(at + 24));
    const std::string count = "-DRSAA_SAMPLE_COUNT=" + std::to_string(samples);
    std::string log;
    if (samples > 8) {
      // Seconds per compile for a 65,536-entry table: once. (The HLSL is checked; the SPIR-V
      // glslang writes for it is not valid: the constant array exceeds an instruction's 65,535
      // words, a limit of SPIR-V, not of Direct3D's compilers.)
      EXPECT_TRUE(compile_hlsl_post(dir, table, count + " -DRSAA_AUTH=1 -DRSAA_SIMILARITY_SADP_PLANE",
                                    dir.file("post.spv"), log))
          << table << "\n" << log;
      continue;
    }
    for (const char* similarity : {"", "-DRSAA_SIMILARITY_DEPTH", "-DRSAA_SIMILARITY_SADP_PLANE"})
      for (int auth : {0, 1})
        for (int bits : {8, 32}) {
          // The options beyond the paper with one combination each (compile time is the cost).
          const char* extensions = bits == 32 ? " -DRSAA_SPLIT_CAP=3.0 -DRSAA_MULTI_SURFACE_NEIGHBOURS" : "";
          const std::string defines = count + " -DRSAA_AUTH=" + std::to_string(auth) +
                                      " -DRSAA_CODE_BITS=" + std::to_string(bits) + " " + similarity + extensions;
          EXPECT_TRUE(compile_hlsl_post(dir, table, defines, dir.file("post.spv"), log))
              << table << " " << defines << "\n" << log;
        }
  }
  std::string log;
  // Registers overridden one at a time.
  EXPECT_TRUE(compile_hlsl_post(dir, "d3d8x", "-DRSAA_SAMPLE_COUNT=8 -DRSAA_REGISTER_CONSTANTS=b1 -DRSAA_REGISTER_COLOUR=t8",
                                dir.file("post.spv"), log))
      << log;
  EXPECT_FALSE(compile_hlsl_post(dir, "d3d4x", "-DRSAA_SAMPLE_COUNT=8", dir.file("post.spv"), log)) << "a table of 4 for 8 samples";
  EXPECT_NE(log.find("another sample count"), std::string::npos) << log;
}

// `actual` equals `expected` (within 1e-3, `actual` upside down when `flipped`), and `expected`
// resampled many pixels of the 1x colour `noaa` (so that the comparison says something).
void expect_same_resampled_image(GLuint expected_texture, GLuint actual_texture, GLuint noaa_texture, int width,
                                 int height, bool flipped) {
  const Image expected = read_back_image(expected_texture, width, height);
  const Image actual = read_back_image(actual_texture, width, height);
  const Image noaa = read_back_image(noaa_texture, width, height);
  int resampled = 0, differing = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const Rgb a = expected.at(x, y), b = actual.at(x, flipped ? height - 1 - y : y), c = noaa.at(x, y);
      resampled += a.r != c.r || a.g != c.g || a.b != c.b;
      differing += std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)}) > 1e-3f;
    }
  EXPECT_GT(resampled, 300);
  EXPECT_EQ(differing, 0) << "of " << resampled << " resampled pixels";
}

// The default scene resolved by RsaaPass with `settings` (the image the shader files must give).
struct ResolvedScene {
  ResolvedScene(const RsaaSettings& settings, int width, int height, const std::string& scene_name = "builtin:default")
      : scene(scene_name, width, height, settings.material_edges),
        pass(settings, width, height),
        frame(scene.frame()),
        output(gl::make_texture_2d(GL_RGBA16F, width, height)) {
    scene.render_subsamples(pass);
    pass.resolve(frame, output.get());
  }
  test::SceneFrame scene;
  RsaaPass pass;
  RsaaFrame frame;
  gl::Texture output;
};

// A buffer holding `bytes` of `data` (a uniform block).
gl::Buffer buffer_of(const void* data, std::size_t bytes) {
  GLuint b = 0;
  glCreateBuffers(1, &b);
  glNamedBufferStorage(b, GLsizeiptr(bytes), data, 0);
  return gl::Buffer(b);
}

// `program` drawn over a width x height RGBA16F target with `textures` bound from unit 0.
gl::Texture draw_post_process(GLuint program, const std::vector<GLuint>& textures, int width, int height,
                              const char* what) {
  glBindTextures(0, GLsizei(textures.size()), textures.data());
  gl::Texture output = gl::make_texture_2d(GL_RGBA16F, width, height);
  const gl::Framebuffer target = gl::make_framebuffer({{output.get()}});
  glBindFramebuffer(GL_FRAMEBUFFER, target.get());
  glViewport(0, 0, width, height);
  glDisable(GL_DEPTH_TEST);
  glUseProgram(program);
  draw_fullscreen_triangle();
  gl::check(what);
  return output;
}

// A copy of a texture upside down (rows from the top, as Direct3D stores an image).
gl::Texture upside_down(GLuint texture, GLenum format, int width, int height, GLenum filter = GL_NEAREST) {
  gl::Texture copy = gl::make_texture_2d(format, width, height, filter);
  const bool depth = format == GL_DEPTH_COMPONENT32F;
  const gl::Framebuffer from = depth ? gl::make_framebuffer({}, {texture}) : gl::make_framebuffer({{texture}});
  const gl::Framebuffer to = depth ? gl::make_framebuffer({}, {copy.get()}) : gl::make_framebuffer({{copy.get()}});
  glBlitNamedFramebuffer(from.get(), to.get(), 0, 0, width, height, 0, height, width, 0,
                         depth ? GL_DEPTH_BUFFER_BIT : GL_COLOR_BUFFER_BIT, GL_NEAREST);
  gl::check("upside-down copy");
  return copy;
}

// The HLSL post-process, compiled to SPIR-V and translated to GLSL by spirv-cross, run on the
// frame the GLSL post-process resolved, as Direct3D sees it (every input upside down: rows from
// the top; depth in [0, 1] through its inverse projection): the same image, upside down.
// Without and with post-pass authentication (which reads depth, normals and neighbour steps);
// parameter 2: without authentication, with the options beyond the paper (split cap, the
// multi-surface resolve, which reads neighbour steps, normals, depth and colours, the split check).
class HlslPostProcessOnGl : public test::GlTest, public ::testing::WithParamInterface<int> {};

TEST_P(HlslPostProcessOnGl, GivesTheGlslPostProcessImage) {
  constexpr int kWidth = 160, kHeight = 120;
  RsaaSettings settings;
  settings.auth = GetParam() >= 2 ? 0 : GetParam();
  // 0, 1: the paper's resolve; 2: the extensions (split cap, multi-surface resolve, split and
  // fetch checks); 3: with material edges too, on a scene of coplanar materials.
  std::string extensions;
  settings.split_cap = 0.0f;
  settings.multi_surface = "fetch";
  settings.split_check = "off";
  settings.fetch_check = "off";
  if (GetParam() >= 2) {
    settings.split_cap = 2.5f;
    settings.multi_surface = "neighbours";
    settings.split_check = "neighbours";
    settings.fetch_check = "neighbours";
    extensions = " -DRSAA_SPLIT_CAP=2.5 -DRSAA_MULTI_SURFACE_NEIGHBOURS -DRSAA_SPLIT_CHECK_NEIGHBOURS"
                 " -DRSAA_FETCH_CHECK_NEIGHBOURS";
  }
  if (GetParam() == 3) {  // with post-pass authentication, which compares materials too
    settings.material_edges = true;
    settings.auth = 1;
    extensions += " -DRSAA_MATERIAL_EDGES";
  }
  const ResolvedScene resolved(settings, kWidth, kHeight, GetParam() == 3 ? "builtin:coplanar" : "builtin:default");
  const View& view = resolved.scene.view;
  const RsaaFrame& frame = resolved.frame;

  test::TempDir dir;
  std::string log;
  const std::string spirv = dir.file("post.spv");
  ASSERT_TRUE(compile_hlsl_post(dir, "d3d8x",
                                "-DRSAA_SAMPLE_COUNT=8 -DRSAA_CODE_BITS=8 -DRSAA_SIMILARITY_SADP_PLANE -DRSAA_AUTH=" +
                                    std::to_string(settings.auth) + extensions,
                                spirv, log))
      << log;
  const auto cross = test::run_command("spirv-cross --version 450 --no-es " + spirv);
  ASSERT_EQ(cross.exit_code, 0) << cross.output;
  std::string fragment = cross.output;
  fragment.erase(0, fragment.find('\n') + 1);  // its #version: make_program writes one
  const gl::Program program = gl::make_program({{GL_VERTEX_SHADER, gl::shader_source("fullscreen.vert")},
                                                {GL_FRAGMENT_SHADER, fragment}},
                                               "", "HLSL post-process via spirv-cross");
  // spirv-cross names a sampler after the texture and sampler it combines: bind by texture name.
  const GLuint p = program.get();
  GLint uniforms = 0;
  glGetProgramInterfaceiv(p, GL_UNIFORM, GL_ACTIVE_RESOURCES, &uniforms);
  const std::vector<GlName> codes = resolved.pass.code_textures();
  ASSERT_EQ(codes.size(), 2u);
  for (GLint u = 0; u < uniforms; ++u) {
    char name[256];
    glGetProgramResourceName(p, GL_UNIFORM, GLuint(u), sizeof name, nullptr, name);
    const std::string n = name;
    const GLint location = glGetProgramResourceLocation(p, GL_UNIFORM, name);
    if (n.find("rsaa_codes") != std::string::npos) {
      const GLint units[2] = {4, 5};
      glProgramUniform1iv(p, location, 2, units);
    } else if (n.find("rsaa_colour") != std::string::npos) {
      glProgramUniform1i(p, location, 0);
    } else if (n.find("rsaa_centre_normal") != std::string::npos) {
      glProgramUniform1i(p, location, 1);
    } else if (n.find("rsaa_centre_depth") != std::string::npos) {
      glProgramUniform1i(p, location, 2);
    } else if (n.find("rsaa_centre_primitive") != std::string::npos) {
      glProgramUniform1i(p, location, 6);
    }
  }
  // The constant buffer: the inverse projection taking Direct3D's depth (z = 2 d - 1), the
  // viewport, the threshold.
  glm::mat4 d3d_depth(1.0f);
  d3d_depth[2][2] = 2.0f, d3d_depth[3][2] = -1.0f;
  struct {
    float inverse_projection[16];
    float viewport[2];
    float threshold;
    float padding;
  } constants{};
  const glm::mat4 inverse = view.inverse_projection() * d3d_depth;
  std::copy_n(glm::value_ptr(inverse), 16, constants.inverse_projection);
  constants.viewport[0] = kWidth, constants.viewport[1] = kHeight;
  constants.threshold = settings.threshold;
  const gl::Buffer buffer = buffer_of(&constants, sizeof constants);
  glBindBufferBase(GL_UNIFORM_BUFFER, 0, buffer.get());
  const gl::Texture colour = upside_down(frame.colour, GL_RGBA16F, kWidth, kHeight, GL_LINEAR);
  const gl::Texture normal = upside_down(frame.centre_normal, GL_RG16UI, kWidth, kHeight);
  const gl::Texture depth = upside_down(frame.centre_depth, GL_DEPTH_COMPONENT32F, kWidth, kHeight);
  const gl::Texture codes0 = upside_down(codes[0], GL_RGBA8UI, kWidth, kHeight);
  const gl::Texture codes1 = upside_down(codes[1], GL_RGBA8UI, kWidth, kHeight);
  const gl::Texture primitive = upside_down(frame.centre_primitive, settings.material_edges ? GL_RG32UI : GL_R32UI,
                                            kWidth, kHeight);
  const gl::Texture hlsl_output = draw_post_process(
      p, {colour.get(), normal.get(), depth.get(), 0, codes0.get(), codes1.get(), primitive.get()}, kWidth, kHeight,
      "the HLSL post-process");

  expect_same_resampled_image(resolved.output.get(), hlsl_output.get(), frame.colour, kWidth, kHeight, true);
}

INSTANTIATE_TEST_SUITE_P(Auth, HlslPostProcessOnGl, ::testing::Values(0, 1, 2, 3));

TEST(GeneratedShaders, RsaaShadersWritesSelfContainedFilesThatCompile) {
  test::TempDir dir;
  const auto r = test::run_rsaa("shaders --out-dir " + dir.file("out") + " --auth 1");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string post = test::read_text(dir.file("out/rsaa_post.frag"));
  const std::string prepass = test::read_text(dir.file("out/rsaa_prepass.glsl"));
  EXPECT_EQ(post.find("#include"), std::string::npos);
  EXPECT_EQ(prepass.find("#include"), std::string::npos);
  EXPECT_EQ(glslang_errors("frag", post), "");
  EXPECT_EQ(glslang_errors("vert", "#version 450\n#define RSAA_INCLUDE_FS 0\n" + prepass +
                                       "void main() { gl_Position = rsaa_jitter(vec4(1.0)); }\n"),
            "");
  EXPECT_EQ(glslang_errors("frag", "#version 450\n" + prepass +
                                       "layout(location = 0) out uvec4 o;\n"
                                       "void main() { o = rsaa_prepass_code(vec3(1.0), vec3(0.0, 0.0, 1.0), 0u); }\n"),
            "");
  const auto hlsl = test::run_command("glslangValidator -D -V -S frag -e RsaaPostPS -o " + dir.file("p.spv") + " " +
                                      dir.file("out/rsaa_post.hlsl"));
  EXPECT_EQ(hlsl.exit_code, 0) << hlsl.output;
}

// With the multisample pre-pass, and with the jittered draws writing records (what RsaaPass's
// "auto" runs for d3d8x on a 4-sample driver), the files include the record passes (which turn
// the draws' records into the codes the post-process reads, as RsaaPass does) and the HLSL
// post-process (one code layout for every pre-pass); every file compiles, material edges on and
// off.
TEST(GeneratedShaders, ThePrePassesWritingRecordsComeWithTheirRecordPasses) {
  for (const auto& [options, define] : {std::pair{" --pattern gl4x --prepass msaa", "#define RSAA_PREPASS_MSAA\n"},
                                        std::pair{" --pattern d3d8x --prepass records", "#define RSAA_PREPASS_RECORDS\n"}})
  for (const char* material_edges : {"off", "on"}) {
    SCOPED_TRACE(std::string(options) + ", material edges " + material_edges);
    test::TempDir dir;
    const auto r = test::run_rsaa("shaders --out-dir " + dir.file("out") + options + " --material-edges " + material_edges);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(test::read_text(dir.file("out/rsaa_prepass.glsl")).find(define), std::string::npos);
    for (const char* name : {"rsaa_prepass_list.comp", "rsaa_prepass_codes.comp", "rsaa_post_list_size.comp"}) {
      const std::string text = test::read_text(dir.file(std::string("out/") + name));
      EXPECT_NE(text.find(define), std::string::npos) << name;
      EXPECT_NE(text.find("#define RSAA_SUBSAMPLE_WINDOWS vec2[]("), std::string::npos) << name;
      EXPECT_EQ(glslang_errors("comp", text), "") << name << ", material edges " << material_edges;
    }
    EXPECT_EQ(glslang_errors("frag", "#version 450\n" + test::read_text(dir.file("out/rsaa_prepass.glsl")) +
                                         "layout(location = 0) out uvec4 o;\n"
                                         "void main() { o = rsaa_prepass_code(vec3(1.0), vec3(0.0, 0.0, 1.0), 1u" +
                                         (std::string(material_edges) == "on" ? ", 3u" : "") + "); }\n"),
              "");
    // Borrowed colours (the default): the codes pass writes the sources, the GLSL post-process reads them.
    EXPECT_NE(test::read_text(dir.file("out/rsaa_prepass_codes.comp")).find("imageStore(rsaa_source_image"), std::string::npos);
    const std::string post = test::read_text(dir.file("out/rsaa_post.frag"));
    EXPECT_NE(post.find("#define RSAA_MULTI_SURFACE_BORROW"), std::string::npos);
    EXPECT_EQ(glslang_errors("frag", post), "");
    const auto hlsl = test::run_command("glslangValidator -D -V -S frag -e RsaaPostPS -o " + dir.file("p.spv") + " " +
                                        dir.file("out/rsaa_post.hlsl"));
    EXPECT_EQ(hlsl.exit_code, 0) << hlsl.output;
  }
}

// The options beyond the paper reach all three files (and the paper's files have none of them).
TEST(GeneratedShaders, TheOptionsBeyondThePaperReachEveryFile) {
  test::TempDir dir;
  const auto r = test::run_rsaa("shaders --out-dir " + dir.file("out") +
                                " --split-cap 2.5 --multi-surface neighbours --split-check neighbours"
                                " --fetch-check neighbours --material-edges on");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* file : {"out/rsaa_prepass.glsl", "out/rsaa_post.frag", "out/rsaa_post.hlsl"}) {
    const std::string text = test::read_text(dir.file(file));
    EXPECT_NE(text.find("#define RSAA_SPLIT_CAP 2.5\n"), std::string::npos) << file;
    EXPECT_NE(text.find("#define RSAA_MULTI_SURFACE_NEIGHBOURS\n"), std::string::npos) << file;
    EXPECT_NE(text.find("#define RSAA_SPLIT_CHECK_NEIGHBOURS\n"), std::string::npos) << file;
    EXPECT_NE(text.find("#define RSAA_FETCH_CHECK_NEIGHBOURS\n"), std::string::npos) << file;
    EXPECT_NE(text.find("#define RSAA_MATERIAL_EDGES\n"), std::string::npos) << file;
    EXPECT_NE(text.find("--split-cap 2.5 --multi-surface neighbours --split-check neighbours --fetch-check neighbours"
                        " --material-edges on"),
              std::string::npos)
        << file;
  }
  // With material edges the pre-pass takes the draw's material.
  EXPECT_EQ(glslang_errors("frag", "#version 450\n" + test::read_text(dir.file("out/rsaa_prepass.glsl")) +
                                       "layout(location = 0) out uvec4 o;\n"
                                       "void main() { o = rsaa_prepass_code(vec3(1.0), vec3(0.0, 0.0, 1.0), 0u, 3u); }\n"),
            "");
  EXPECT_EQ(glslang_errors("frag", test::read_text(dir.file("out/rsaa_post.frag"))), "");
  const auto hlsl = test::run_command("glslangValidator -D -V -S frag -e RsaaPostPS -o " + dir.file("p.spv") + " " +
                                      dir.file("out/rsaa_post.hlsl"));
  EXPECT_EQ(hlsl.exit_code, 0) << hlsl.output;
  const auto paper =
      test::run_rsaa("shaders --out-dir " + dir.file("paper") + " --similarity sadp --split-cap 0 --multi-surface fetch --split-check off --fetch-check off");
  ASSERT_EQ(paper.exit_code, 0) << paper.output;
  for (const char* file : {"paper/rsaa_prepass.glsl", "paper/rsaa_post.frag", "paper/rsaa_post.hlsl"}) {
    const std::string text = test::read_text(dir.file(file));
    EXPECT_EQ(text.find("#define RSAA_SPLIT_CAP"), std::string::npos) << file;
    EXPECT_EQ(text.find("#define RSAA_MULTI_SURFACE_NEIGHBOURS"), std::string::npos) << file;
    EXPECT_EQ(text.find("#define RSAA_SPLIT_CHECK_NEIGHBOURS"), std::string::npos) << file;
    EXPECT_EQ(text.find("#define RSAA_FETCH_CHECK_NEIGHBOURS"), std::string::npos) << file;
    EXPECT_EQ(text.find("#define RSAA_MATERIAL_EDGES"), std::string::npos) << file;
  }
}

// The header's command line makes the same files again, options of more digits than %g keeps
// included (it printed 0.123457 for 0.123456789, whose float then differed).
TEST(GeneratedShaders, TheHeadersCommandLineMakesTheSameFiles) {
  test::TempDir dir;
  const auto first = test::run_rsaa("shaders --out-dir " + dir.file("first") +
                                    " --borrow-weight 0.123456789 --split-cap 1.23456789");
  ASSERT_EQ(first.exit_code, 0) << first.output;
  const std::string post = test::read_text(dir.file("first/rsaa_post.frag"));
  const std::string marker = "// Generated by: rsaa ";
  const size_t begin = post.find(marker);
  ASSERT_NE(begin, std::string::npos);
  const size_t end = post.find('\n', begin);
  const std::string args = post.substr(begin + marker.size(), end - begin - marker.size());
  EXPECT_EQ(args.find("0.123457 "), std::string::npos) << args;
  const auto again = test::run_rsaa(args + " --out-dir " + dir.file("again"));
  ASSERT_EQ(again.exit_code, 0) << again.output;
  for (const char* file : {"rsaa_prepass.glsl", "rsaa_post.frag", "rsaa_post.hlsl"})
    EXPECT_EQ(test::read_text(dir.file(std::string("again/") + file)),
              test::read_text(dir.file(std::string("first/") + file)))
        << file;
}

TEST(GeneratedShaders, BadOptionsOrTablesAreRefusedAndWriteNothing) {
  test::TempDir dir;
  test::write_text(dir.file("broken.json"), "{\"pattern\": ");
  const auto broken = test::run_rsaa("shaders --out-dir " + dir.file("out") + " --table " + dir.file("broken.json"));
  EXPECT_NE(broken.exit_code, 0);
  EXPECT_NE(broken.output.find("broken.json"), std::string::npos) << broken.output;
  EXPECT_NE(test::run_rsaa("shaders --out-dir " + dir.file("out") + " --code-bits 12").exit_code, 0);
  EXPECT_NE(test::run_rsaa("shaders --out-dir " + dir.file("out") + " --pattern d3d9x").exit_code, 0);
  EXPECT_NE(test::run_rsaa("shaders --out-dir " + dir.file("out") + " --split-cap 0.5").exit_code, 0);
  EXPECT_NE(test::run_rsaa("shaders --out-dir " + dir.file("out") + " --multi-surface blur").exit_code, 0);
  EXPECT_FALSE(std::filesystem::exists(dir.file("out/rsaa_post.frag")));
}

class GeneratedShadersOnGl : public test::GlTest {};

// The generated rsaa_post.frag (offsets inlined, RSAA_TABLE_ARRAY) with the uniform block filled
// as rsaa_uniforms.glsl documents it: the image of RsaaPass's post-process (table texture).
TEST_F(GeneratedShadersOnGl, ThePostFragmentWithItsTableInlinedGivesThePassImage) {
  constexpr int kWidth = 160, kHeight = 120;
  for (const bool material_edges : {false, true}) {  // with them, the primitive target at unit 8
    RsaaSettings settings;
    settings.auth = 1;
    settings.material_edges = material_edges;
    // The files' pre-pass (the defaults': jittered), whose codes alone the post-process reads:
    // borrowed colours, the default, resolve as "neighbours" there.
    settings.prepass = "jittered";
    const ResolvedScene resolved(settings, kWidth, kHeight, material_edges ? "builtin:coplanar" : "builtin:default");
    const View& view = resolved.scene.view;
    const RsaaFrame& frame = resolved.frame;

    test::TempDir dir;
    const auto r = test::run_rsaa("shaders --out-dir " + dir.file("out") + " --auth 1" +
                                  (material_edges ? " --material-edges on" : ""));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    std::string fragment = test::read_text(dir.file("out/rsaa_post.frag"));
    fragment.erase(0, fragment.find('\n') + 1);  // its #version: make_program writes one
    const gl::Program program = gl::make_program({{GL_VERTEX_SHADER, gl::shader_source("fullscreen.vert")},
                                                  {GL_FRAGMENT_SHADER, fragment}},
                                                 "", "generated rsaa_post.frag");
    // The block, std140: mat4, viewport, jitter, threshold, subsample, padding, ivec4 per subsample.
    std::vector<std::int32_t> block(24 + 4 * resolved.pass.pattern().size(), 0);
    const glm::mat4 inverse = view.inverse_projection();
    std::memcpy(block.data(), glm::value_ptr(inverse), 64);
    const float viewport[2] = {float(kWidth), float(kHeight)};
    std::memcpy(&block[16], viewport, 8);
    std::memcpy(&block[20], &settings.threshold, 4);
    for (int i = 0; i < resolved.pass.pattern().size(); ++i) {
      const PixelStep step = outside_pixel_towards(resolved.pass.pattern().positions[i]);
      const Vec2 gl_step = pixel_to_gl({double(step.i), double(step.j)});
      block[24 + 4 * i] = int(gl_step.x), block[24 + 4 * i + 1] = int(gl_step.y);
    }
    const gl::Buffer buffer = buffer_of(block.data(), block.size() * 4);
    glBindBufferBase(GL_UNIFORM_BUFFER, GLuint(settings.uniform_binding), buffer.get());
    const std::vector<GlName> codes = resolved.pass.code_textures();
    const gl::Texture output = draw_post_process(
        program.get(), {frame.colour, frame.centre_normal, frame.centre_depth, 0, codes[0], codes[1], 0, 0,
                        material_edges ? frame.centre_primitive : 0},
        kWidth, kHeight, "the generated post-process");

    expect_same_resampled_image(resolved.output.get(), output.get(), frame.colour, kWidth, kHeight, false);
  }
}

}  // namespace
}  // namespace rsaa
