// The drop-in pass's contract with an engine (runtime/rsaa_pass.h): a missing or wrong frame
// texture is an error naming the field, a callback that draws with another program is an
// error, and the engine's GL state is as it was after both calls.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>

#include <gtest/gtest.h>

#include "runtime/fullscreen.h"
#include "runtime/gl_context.h"
#include "tests/gl_test.h"
#include "runtime/render.h"
#include "runtime/rsaa_pass.h"
#include "runtime/scene.h"
#include "runtime/scene_renderer.h"
#include "runtime/shader_library.h"

namespace rsaa {

// The pass's internals a test reaches (RsaaPass's friend).
struct RsaaPassTesting {
  static void set_edge_list_capacity(RsaaPass& pass, std::int64_t pixels) { pass.make_lists(pixels); }
  // The multisample pre-pass's record passes as on a driver without multisample image loads.
  static void read_records_as_textures(RsaaPass& pass) { pass.make_record_programs(false); }
  // The pixels (x + y * width) the last pre-pass's record passes put in the compute post-process's
  // edge list, sorted; nullopt when that pre-pass listed none (the post-process lists them).
  static std::optional<std::vector<std::uint32_t>> prepass_edge_list(const RsaaPass& pass, int width) {
    if (!pass.edges_listed_) return std::nullopt;
    std::vector<std::uint32_t> pixels = pass.edge_list_pixels();
    for (std::uint32_t& p : pixels) p = (p & 0xffffu) + (p >> 16) * std::uint32_t(width);
    std::sort(pixels.begin(), pixels.end());
    return pixels;
  }
};

namespace {

constexpr int kWidth = 64, kHeight = 48;

class RsaaPassApi : public test::GlTest {};

// The message of the std::invalid_argument `f` throws ("" if it throws none).
template <typename F>
std::string invalid_argument_of(F f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST_F(RsaaPassApi, AMissingOrWrongFrameTextureIsAnErrorNamingTheField) {
  const RsaaTargets targets(kWidth, kHeight);
  RsaaPass pass(RsaaSettings{}, kWidth, kHeight);
  const RsaaFrame good = targets.frame(glm::mat4(1.0f));
  const auto draw_nothing = [](GLuint, glm::vec2) {};

  RsaaFrame missing_normal = good;
  missing_normal.centre_normal = 0;
  EXPECT_NE(invalid_argument_of([&] { pass.render_subsamples(missing_normal, draw_nothing); })
                .find("RsaaFrame::centre_normal: 0 is not a texture"),
            std::string::npos);

  RsaaFrame colour_as_depth = good;
  colour_as_depth.centre_depth = good.colour;
  const std::string wrong_format =
      invalid_argument_of([&] { pass.resolve(colour_as_depth, good.colour); });
  EXPECT_NE(wrong_format.find("RsaaFrame::centre_depth"), std::string::npos) << wrong_format;
  EXPECT_NE(wrong_format.find("GL_RGBA16F"), std::string::npos) << wrong_format;
  EXPECT_NE(wrong_format.find("GL_DEPTH_COMPONENT32F"), std::string::npos) << wrong_format;

  const gl::Texture small = gl::make_texture_2d(GL_RGBA16F, kWidth / 2, kHeight);
  EXPECT_NE(invalid_argument_of([&] { pass.resolve(good, small.get()); }).find("resolve output"),
            std::string::npos);
  // Material edges need the primitive target with its material channel, and only with them.
  RsaaSettings material_settings;
  material_settings.material_edges = true;
  RsaaPass material_pass(material_settings, kWidth, kHeight);
  const std::string no_material = invalid_argument_of([&] { material_pass.render_subsamples(good, draw_nothing); });
  EXPECT_NE(no_material.find("RsaaFrame::centre_primitive (material_edges: primitive, material)"), std::string::npos)
      << no_material;
  EXPECT_NE(no_material.find("GL_RG32UI"), std::string::npos) << no_material;
  const RsaaTargets material_targets(kWidth, kHeight, true);
  const std::string unexpected_material =
      invalid_argument_of([&] { pass.resolve(material_targets.frame(glm::mat4(1.0f)), good.colour); });
  EXPECT_NE(unexpected_material.find("RsaaFrame::centre_primitive"), std::string::npos) << unexpected_material;
  EXPECT_NE(unexpected_material.find("GL_R32UI"), std::string::npos) << unexpected_material;

  RsaaFrame other_size = good;
  other_size.width = kWidth + 1;
  EXPECT_NE(invalid_argument_of([&] { pass.render_subsamples(other_size, draw_nothing); })
                .find("RsaaFrame is 65x48, the RsaaPass was made for 64x48"),
            std::string::npos);
  gl::check("after the refused calls");
}

TEST_F(RsaaPassApi, ACallbackDrawingWithAnotherProgramIsAnError) {
  const RsaaTargets targets(kWidth, kHeight);
  RsaaPass pass(RsaaSettings{}, kWidth, kHeight);
  SceneRenderer renderer;
  const GLuint engine_program = renderer.shade_program();
  try {
    pass.render_subsamples(targets.frame(glm::mat4(1.0f)),
                           [&](GLuint, glm::vec2) { glUseProgram(engine_program); });
    FAIL() << "no error";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("not the pre-pass program"), std::string::npos) << e.what();
  }
}


gl::Program engine_prepass_program(const RsaaPass& pass) { return test::engine_prepass_program(pass.prepass_glsl()); }

// The masks of the default scene, pre-pass drawn by the pass's program or by an engine program.
struct MaskRun {
  std::vector<std::uint32_t> own_program, engine_program;
  std::uint32_t all_similar;
};
MaskRun masks_both_ways(const std::string& scene_name, RsaaSettings settings, int width, int height) {
  const test::SceneFrame scene(scene_name, width, height, settings.material_edges);
  settings.output_mask = true;
  RsaaPass pass(settings, width, height);
  const RsaaFrame frame = scene.frame();
  const gl::Texture output = gl::make_texture_2d(GL_RGBA16F, width, height);
  const gl::Texture masks = gl::make_texture_2d(GL_R32UI, width, height);
  MaskRun run;
  run.all_similar = (1u << pass.pattern().size()) - 1u;
  scene.render_subsamples(pass);
  pass.resolve(frame, output.get(), masks.get());
  run.own_program = read_back_uints(masks.get(), width, height);
  const gl::Program engine = engine_prepass_program(pass);
  pass.render_subsamples_with_own_shaders(frame, [&] {
    glUseProgram(engine.get());
    SceneRenderer::draw_in_current_viewport(scene.gpu, scene.view, glm::vec2(0.0f), engine.get());
  });
  pass.resolve(frame, output.get(), masks.get());
  run.engine_program = read_back_uints(masks.get(), width, height);
  return run;
}

TEST_F(RsaaPassApi, AnEnginesOwnShadersGiveThePassProgramsMasks) {
  RsaaSettings multisample;
  multisample.pattern = "gl4x";
  multisample.prepass = "msaa";
  RsaaSettings material;  // the engine's own shaders pass the draw's material
  material.material_edges = true;
  // Records with materials: the include packs the material into the engine's record.
  RsaaSettings multisample_material = multisample, records_material = material;
  multisample_material.material_edges = true;
  records_material.prepass = "records";
  RsaaSettings jittered;  // the defaults ("auto") take records for d3d8x on a 4-sample driver
  jittered.prepass = "jittered";
  RsaaSettings cells;  // one 4x draw at twice the height: the engine's draw into the pass's viewport
  cells.table = std::make_shared<OffsetTable>(
      read_offset_table(std::string(RSAA_SOURCE_DIR) + "/tables/custom-gl4x-tall.json"));
  cells.pattern = "";
  for (const auto& [scene, settings] : {std::pair{"builtin:default", RsaaSettings{}},
                                        std::pair{"builtin:edges", RsaaSettings{}},
                                        std::pair{"builtin:default", jittered},
                                        std::pair{"builtin:edges", jittered},
                                        std::pair{"builtin:default", multisample},
                                        std::pair{"builtin:default", cells},
                                        std::pair{"builtin:coplanar", material},
                                        std::pair{"builtin:coplanar", multisample_material},
                                        std::pair{"builtin:coplanar", records_material}}) {
    const MaskRun run = masks_both_ways(scene, settings, 160, 120);
    int edges = 0, differing = 0;
    for (std::size_t i = 0; i < run.own_program.size(); ++i) {
      edges += run.own_program[i] != run.all_similar;
      differing += run.own_program[i] != run.engine_program[i];
    }
    EXPECT_GT(edges, 200) << scene;
    // The face normal from derivatives differs from the geometry stage's in the last bits; only
    // subsamples whose similarity sits on the threshold may change side.
    EXPECT_LE(differing, edges / 100) << scene << ": " << differing << " of " << edges << " edge pixels differ";
  }
}

TEST_F(RsaaPassApi, AnEngineProgramWithoutTheBlockOrThatRebindsAUnitIsAnError) {
  const RsaaTargets targets(kWidth, kHeight);
  RsaaPass pass(RsaaSettings{}, kWidth, kHeight);
  const RsaaFrame frame = targets.frame(glm::mat4(1.0f));
  SceneRenderer renderer;
  const auto logic_error_of = [&](const std::function<void()>& draw) -> std::string {
    try {
      pass.render_subsamples_with_own_shaders(frame, draw);
    } catch (const std::logic_error& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(logic_error_of([&] { glUseProgram(renderer.shade_program()); }).find("has no RsaaUniforms block"),
            std::string::npos);
  const gl::Program engine = engine_prepass_program(pass);
  const gl::Texture material = gl::make_texture_2d(GL_RGBA8, 4, 4);
  EXPECT_NE(logic_error_of([&] {
              glUseProgram(engine.get());
              glBindTextureUnit(14, material.get());
            }).find("rebound texture unit 14"),
            std::string::npos);
  GLuint linear = 0;
  glCreateSamplers(1, &linear);
  EXPECT_NE(logic_error_of([&] {
              glUseProgram(engine.get());
              glBindSampler(15, linear);
            }).find("bound sampler object " + std::to_string(linear) + " to texture unit 15"),
            std::string::npos);
  glDeleteSamplers(1, &linear);
  EXPECT_EQ(logic_error_of([&] { glUseProgram(engine.get()); }), "");
  gl::check("after the refused draws");
}

// An engine may delete its current program (it stays alive until another is made current): the
// pass's draws end it, and its calls leave no GL error trying to restore it.
TEST_F(RsaaPassApi, AProgramDeletedWhileCurrentIsNotRestored) {
  const test::SceneFrame scene("builtin:edges", kWidth, kHeight);
  RsaaPass pass(RsaaSettings{}, kWidth, kHeight);
  {
    const gl::Program doomed = engine_prepass_program(pass);
    glUseProgram(doomed.get());
  }  // deleted while current
  while (glGetError() != GL_NO_ERROR) {
  }
  scene.render_subsamples(pass);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR)) << "after the pre-pass";
  const gl::Texture output = gl::make_texture_2d(GL_RGBA16F, kWidth, kHeight);
  pass.resolve(scene.frame(), output.get());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR)) << "after the post-process";
  GLint current = -1;
  glGetIntegerv(GL_CURRENT_PROGRAM, &current);
  EXPECT_EQ(current, 0);
}

// An image size outside the driver's limits (a minimised window's 0 x 0 among them) is refused
// naming the size and the limit; it was a GL error from inside ("GL error 0x0501 in
// make_texture_2d").
TEST_F(RsaaPassApi, ImageSizesOutsideTheDriversLimitsAreRefused) {
  GLint max_texture = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_texture);
  const struct {
    int width, height;
  } sizes[] = {{0, 0}, {-1, 5}, {5, -1}, {max_texture + 1, 1}, {1, max_texture + 1}};
  for (const auto& size : sizes) {
    const std::string named = std::to_string(size.width) + "x" + std::to_string(size.height) + " image";
    EXPECT_NE(invalid_argument_of([&] { RsaaPass(RsaaSettings{}, size.width, size.height); }).find("RsaaPass: a " + named),
              std::string::npos);
    EXPECT_NE(invalid_argument_of([&] { RsaaTargets(size.width, size.height); }).find("RsaaTargets: a " + named),
              std::string::npos);
  }
  gl::check("after the refused sizes");
}

TEST_F(RsaaPassApi, ResourceSlotsOutsideTheDriversLimitsAreRefused) {
  RsaaSettings settings;
  settings.prepass_first_unit = 1000;
  EXPECT_NE(invalid_argument_of([&] { RsaaPass(settings, kWidth, kHeight); }).find("prepass_first_unit 1000"),
            std::string::npos);
  settings = RsaaSettings{};
  settings.uniform_binding = -1;
  EXPECT_NE(invalid_argument_of([&] { RsaaPass(settings, kWidth, kHeight); }).find("uniform_binding -1"),
            std::string::npos);
}

TEST_F(RsaaPassApi, TheEngineGlStateIsRestored) {
  const test::SceneFrame scene("builtin:default", kWidth, kHeight);
  const SceneRenderer& renderer = scene.renderer;

  // An engine's state, all of it different from what the pass draws with.
  const gl::Texture engine_texture = gl::make_texture_2d(GL_RGBA8, 4, 4);
  // With stencil bits: GL reports the stencil reference clamped to the framebuffer's.
  const gl::Texture engine_depth_stencil = gl::make_texture_2d(GL_DEPTH24_STENCIL8, 4, 4);
  const gl::Framebuffer engine_framebuffer =
      gl::make_framebuffer({{engine_texture.get()}}, {engine_depth_stencil.get()});
  glBindFramebuffer(GL_FRAMEBUFFER, engine_framebuffer.get());
  glViewport(1, 2, 3, 4);
  glUseProgram(renderer.shade_program());
  glEnable(GL_BLEND);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, 1, 1);
  glDisable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
  glDepthFunc(GL_GREATER);
  glBindTextureUnit(2, engine_texture.get());
  glBindTextureUnit(13, engine_texture.get());  // the pre-pass's first unit
  gl::Buffer engine_buffer = [] {
    GLuint b = 0;
    glCreateBuffers(1, &b);
    glNamedBufferStorage(b, 256, nullptr, 0);
    return gl::Buffer(b);
  }();
  glBindBufferRange(GL_UNIFORM_BUFFER, 13, engine_buffer.get(), 0, 128);  // the pass's binding
  // The generic uniform buffer binding (glBufferSubData's target), which binding an indexed one sets.
  const gl::Buffer engine_generic_uniforms = [] {
    GLuint b = 0;
    glCreateBuffers(1, &b);
    glNamedBufferStorage(b, 64, nullptr, 0);
    return gl::Buffer(b);
  }();
  glBindBuffer(GL_UNIFORM_BUFFER, engine_generic_uniforms.get());
  glEnable(GL_SAMPLE_SHADING);
  glMinSampleShading(0.25f);
  // ... and the state an engine leaves for its own draws: culling (the full-screen triangle
  // would vanish), line polygons, a nearest-filtering sampler object on the colour's unit (the
  // bilinear fetch would turn nearest), blending and a closed mask on draw buffer 1.
  glEnable(GL_CULL_FACE);
  glCullFace(GL_FRONT);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  GLuint nearest = 0;
  glCreateSamplers(1, &nearest);
  glSamplerParameteri(nearest, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glSamplerParameteri(nearest, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glBindSampler(0, nearest);
  glEnablei(GL_BLEND, 1);
  glColorMaski(1, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  // A depth range and polygon offset that would move the resolve pass's depth-tested triangle.
  glDepthRange(0.0, 0.0);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(0.0f, -1.0e6f);
  // A stencil test that would reject everything (the culled pre-pass draws with its own).
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_NEVER, 7, 0x0Fu);
  glStencilOp(GL_INCR, GL_DECR, GL_INVERT);
  glStencilMask(0x3u);
  // Compute state the default post-process ("compute") binds: an image on its units, a storage
  // buffer range at its binding, an indirect-dispatch buffer.
  glBindImageTexture(0, engine_texture.get(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA8);
  glBindImageTexture(1, engine_texture.get(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
  // The units the listing pass reads the codes and the normal through (2 to 4 with 8 subsamples).
  for (GLuint unit : {2u, 3u, 4u}) glBindImageTexture(unit, engine_texture.get(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
  glBindBufferRange(GL_SHADER_STORAGE_BUFFER, 0, engine_buffer.get(), 64, 128);
  // The record passes' second list (the post-process's edges, listed by the pre-pass).
  glBindBufferRange(GL_SHADER_STORAGE_BUFFER, 1, engine_buffer.get(), 128, 64);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, engine_buffer.get());
  const gl::Buffer engine_generic_buffer = [] {
    GLuint b = 0;
    glCreateBuffers(1, &b);
    glNamedBufferStorage(b, 64, nullptr, 0);
    return gl::Buffer(b);
  }();
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, engine_generic_buffer.get());  // the generic binding alone
  const gl::Texture engine_array = [] {
    GLuint t = 0;
    glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &t);
    glTextureStorage3D(t, 2, GL_RGBA8, 4, 4, 3);
    return gl::Texture(t);
  }();
  glBindImageTexture(1, engine_array.get(), 1, GL_FALSE, 2, GL_WRITE_ONLY, GL_RGBA8);  // level 1, layer 2

  // Another viewport index's rectangle, depth range and scissor test (for gl_ViewportIndex draws):
  // glViewport, glDepthRange and glDisable(GL_SCISSOR_TEST) set every index.
  glViewportIndexedf(1, 5.5f, 6.0f, 7.0f, 8.0f);
  glDepthRangeIndexed(1, 0.25, 0.75);
  glDisablei(GL_SCISSOR_TEST, 1);  // on for index 0 (above)
  RsaaSettings settings;
  settings.prepass_cull = "neighbours";  // the pass's stencil state too
  // The multisample and records pre-passes too: their record passes bind texture units 0-5 (an
  // engine texture on unit 2, its sampler object on unit 0) and more image units.
  RsaaSettings multisample, records;
  multisample.pattern = "gl4x", multisample.prepass = "msaa", records.prepass = "records";
  const RsaaFrame frame = scene.frame();
  const gl::Texture other_output = gl::make_texture_2d(GL_RGBA16F, kWidth, kHeight);
  for (const RsaaSettings& each : {multisample, records}) {
    RsaaPass other(each, kWidth, kHeight);
    scene.render_subsamples(other);
    other.resolve(frame, other_output.get());
  }
  RsaaPass pass(settings, kWidth, kHeight);
  scene.render_subsamples(pass);
  const gl::Texture output = gl::make_texture_2d(GL_RGBA16F, kWidth, kHeight);
  pass.resolve(frame, output.get());

  GLint framebuffer = 0, viewport[4] = {}, program = 0, depth_func = 0, texture = 0;
  GLboolean depth_mask = GL_TRUE;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
  glGetIntegerv(GL_VIEWPORT, viewport);
  glGetIntegerv(GL_CURRENT_PROGRAM, &program);
  glGetIntegerv(GL_DEPTH_FUNC, &depth_func);
  glGetBooleanv(GL_DEPTH_WRITEMASK, &depth_mask);
  glActiveTexture(GL_TEXTURE2);
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture);
  glActiveTexture(GL_TEXTURE0);
  EXPECT_EQ(GLuint(framebuffer), engine_framebuffer.get());
  EXPECT_EQ(viewport[0], 1);
  EXPECT_EQ(viewport[3], 4);
  GLfloat viewport1[4] = {};
  GLdouble depth_range1[2] = {};
  glGetFloati_v(GL_VIEWPORT, 1, viewport1);
  glGetDoublei_v(GL_DEPTH_RANGE, 1, depth_range1);
  EXPECT_EQ(viewport1[0], 5.5f);
  EXPECT_EQ(viewport1[3], 8.0f);
  EXPECT_EQ(depth_range1[0], 0.25);
  EXPECT_EQ(depth_range1[1], 0.75);
  EXPECT_FALSE(glIsEnabledi(GL_SCISSOR_TEST, 1));
  EXPECT_EQ(GLuint(program), renderer.shade_program());
  EXPECT_TRUE(glIsEnabled(GL_BLEND));
  EXPECT_TRUE(glIsEnabled(GL_SCISSOR_TEST));
  EXPECT_FALSE(glIsEnabled(GL_DEPTH_TEST));
  EXPECT_EQ(depth_mask, GL_FALSE);
  EXPECT_EQ(depth_func, GL_GREATER);
  EXPECT_EQ(GLuint(texture), engine_texture.get());
  GLint unit13 = 0, uniform_buffer = 0;
  GLint64 uniform_size = 0;
  GLfloat min_sample_shading = 0.0f;
  glGetIntegeri_v(GL_TEXTURE_BINDING_2D, 13, &unit13);
  glGetIntegeri_v(GL_UNIFORM_BUFFER_BINDING, 13, &uniform_buffer);
  glGetInteger64i_v(GL_UNIFORM_BUFFER_SIZE, 13, &uniform_size);
  glGetFloatv(GL_MIN_SAMPLE_SHADING_VALUE, &min_sample_shading);
  EXPECT_EQ(GLuint(unit13), engine_texture.get());
  EXPECT_EQ(GLuint(uniform_buffer), engine_buffer.get());
  EXPECT_EQ(uniform_size, 128);
  GLint generic_uniforms = 0;
  glGetIntegerv(GL_UNIFORM_BUFFER_BINDING, &generic_uniforms);
  EXPECT_EQ(GLuint(generic_uniforms), engine_generic_uniforms.get());
  EXPECT_TRUE(glIsEnabled(GL_SAMPLE_SHADING));
  EXPECT_EQ(min_sample_shading, 0.25f);
  GLint polygon_mode[2] = {}, sampler = 0;  // GL_POLYGON_MODE reports front and back
  GLboolean mask1[4] = {GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE};
  glGetIntegerv(GL_POLYGON_MODE, polygon_mode);
  glGetIntegeri_v(GL_SAMPLER_BINDING, 0, &sampler);
  glGetBooleani_v(GL_COLOR_WRITEMASK, 1, mask1);
  EXPECT_TRUE(glIsEnabled(GL_CULL_FACE));
  EXPECT_EQ(polygon_mode[0], GL_LINE);
  EXPECT_EQ(GLuint(sampler), nearest);
  EXPECT_TRUE(glIsEnabledi(GL_BLEND, 1));
  EXPECT_FALSE(mask1[0] || mask1[1] || mask1[2] || mask1[3]);
  GLdouble depth_range[2] = {1.0, 1.0};
  glGetDoublev(GL_DEPTH_RANGE, depth_range);
  EXPECT_EQ(depth_range[1], 0.0);
  EXPECT_TRUE(glIsEnabled(GL_POLYGON_OFFSET_FILL));
  GLint stencil_func = 0, stencil_ref = 0, stencil_value_mask = 0, stencil_fail = 0, stencil_writemask = 0;
  glGetIntegerv(GL_STENCIL_FUNC, &stencil_func);
  glGetIntegerv(GL_STENCIL_REF, &stencil_ref);
  glGetIntegerv(GL_STENCIL_VALUE_MASK, &stencil_value_mask);
  glGetIntegerv(GL_STENCIL_FAIL, &stencil_fail);
  glGetIntegerv(GL_STENCIL_WRITEMASK, &stencil_writemask);
  EXPECT_TRUE(glIsEnabled(GL_STENCIL_TEST));
  EXPECT_EQ(stencil_func, GL_NEVER);
  EXPECT_EQ(stencil_ref, 7);
  EXPECT_EQ(stencil_value_mask, 0x0F);
  EXPECT_EQ(stencil_fail, GL_INCR);
  EXPECT_EQ(stencil_writemask, 0x3);
  ASSERT_EQ(settings.post, "compute");
  GLint image0 = 0, image1 = 0, image0_access = 0, image1_format = 0, storage = 0, indirect = 0;
  GLint64 storage_start = 0, storage_size = 0;
  glGetIntegeri_v(GL_IMAGE_BINDING_NAME, 0, &image0);
  glGetIntegeri_v(GL_IMAGE_BINDING_ACCESS, 0, &image0_access);
  glGetIntegeri_v(GL_IMAGE_BINDING_NAME, 1, &image1);
  glGetIntegeri_v(GL_IMAGE_BINDING_FORMAT, 1, &image1_format);
  GLint image1_level = 0, image1_layer = 0, generic_storage = 0;
  GLboolean image1_layered = GL_TRUE;
  glGetIntegeri_v(GL_IMAGE_BINDING_LEVEL, 1, &image1_level);
  glGetIntegeri_v(GL_IMAGE_BINDING_LAYER, 1, &image1_layer);
  glGetBooleani_v(GL_IMAGE_BINDING_LAYERED, 1, &image1_layered);
  glGetIntegerv(GL_SHADER_STORAGE_BUFFER_BINDING, &generic_storage);
  EXPECT_EQ(image1_level, 1);
  EXPECT_EQ(image1_layer, 2);
  EXPECT_EQ(image1_layered, GL_FALSE);
  EXPECT_EQ(GLuint(generic_storage), engine_generic_buffer.get());
  glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, 0, &storage);
  glGetInteger64i_v(GL_SHADER_STORAGE_BUFFER_START, 0, &storage_start);
  glGetInteger64i_v(GL_SHADER_STORAGE_BUFFER_SIZE, 0, &storage_size);
  glGetIntegerv(GL_DISPATCH_INDIRECT_BUFFER_BINDING, &indirect);
  GLint storage1 = 0;
  GLint64 storage1_start = 0;
  glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, 1, &storage1);
  glGetInteger64i_v(GL_SHADER_STORAGE_BUFFER_START, 1, &storage1_start);
  EXPECT_EQ(GLuint(storage1), engine_buffer.get());
  EXPECT_EQ(storage1_start, 128);
  EXPECT_EQ(GLuint(image0), engine_texture.get());
  EXPECT_EQ(image0_access, GL_READ_ONLY);
  EXPECT_EQ(GLuint(image1), engine_array.get());
  EXPECT_EQ(image1_format, GL_RGBA8);
  for (GLuint unit : {2u, 3u, 4u}) {
    GLint name = 0, access = 0, format = 0;
    glGetIntegeri_v(GL_IMAGE_BINDING_NAME, unit, &name);
    glGetIntegeri_v(GL_IMAGE_BINDING_ACCESS, unit, &access);
    glGetIntegeri_v(GL_IMAGE_BINDING_FORMAT, unit, &format);
    EXPECT_EQ(GLuint(name), engine_texture.get()) << "image unit " << unit;
    EXPECT_EQ(access, GL_READ_WRITE) << "image unit " << unit;
    EXPECT_EQ(format, GL_R32UI) << "image unit " << unit;
  }
  EXPECT_EQ(GLuint(storage), engine_buffer.get());
  EXPECT_EQ(storage_start, 64);
  EXPECT_EQ(storage_size, 128);
  EXPECT_EQ(GLuint(indirect), engine_buffer.get());

  // The engine's state did not reach the pass: the same frame without it gives the same image.
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_BLEND);
  glDepthMask(GL_TRUE);
  glDisable(GL_SAMPLE_SHADING);
  glDisable(GL_CULL_FACE);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glBindSampler(0, 0);
  glDeleteSamplers(1, &nearest);
  glColorMaski(1, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthRange(0.0, 1.0);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDisable(GL_STENCIL_TEST);
  const gl::Texture clean_output = gl::make_texture_2d(GL_RGBA16F, kWidth, kHeight);
  scene.render_subsamples(pass);
  pass.resolve(frame, clean_output.get());
  const Image a = read_back_image(output.get(), kWidth, kHeight);
  const Image b = read_back_image(clean_output.get(), kWidth, kHeight);
  int differing = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const Rgb p = a.at(x, y), q = b.at(x, y);
      differing += p.r != q.r || p.g != q.g || p.b != q.b;
    }
  EXPECT_EQ(differing, 0);
  // ... and it resampled: the comparison says something.
  const Image one_x = read_back_image(frame.colour, kWidth, kHeight);
  int resampled = 0;
  for (std::size_t p = 0; p < a.pixels.size(); ++p) resampled += a.pixels[p].r != one_x.pixels[p].r;
  EXPECT_GT(resampled, 20);
  gl::check("state test");
  // The suite's tests share one context: leave GL's defaults for the next (a test run after this
  // one in the same process saw the stencil and depth state above).
  glDepthFunc(GL_LESS);
  glPolygonOffset(0.0f, 0.0f);
  glStencilFunc(GL_ALWAYS, 0, ~0u);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glStencilMask(~0u);
  glDisablei(GL_BLEND, 1);
  glMinSampleShading(0.0f);
  glCullFace(GL_BACK);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glUseProgram(0);
  for (GLuint unit : {0u, 1u, 2u, 3u, 4u}) glBindImageTexture(unit, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R8);
  for (GLuint unit : {2u, 13u}) glBindTextureUnit(unit, 0);
  glBindBufferBase(GL_UNIFORM_BUFFER, 13, 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
}

// State an engine turns on for its own draws that decides which samples a fragment writes (the
// multisample pre-pass: GL_MULTISAMPLE off, a sample mask, a coverage value) or how a code combines
// with the one in the target (a logic op, the jittered pre-pass's integer codes) does not reach
// the pass: the masks are those of a clean state, and the engine's state is as it was.
TEST_F(RsaaPassApi, TheEnginesSampleAndLogicOpStateDoesNotReachThePrePass) {
  const test::SceneFrame scene("builtin:default", kWidth, kHeight);
  RsaaSettings multisample;
  multisample.pattern = "gl4x", multisample.prepass = "msaa";
  for (RsaaSettings settings : {RsaaSettings{}, multisample}) {
    settings.output_mask = true;
    RsaaPass pass(settings, kWidth, kHeight);
    const auto masks = [&] {
      scene.render_subsamples(pass);
      const gl::Texture output = gl::make_texture_2d(GL_RGBA16F, kWidth, kHeight);
      const gl::Texture mask = gl::make_texture_2d(GL_R32UI, kWidth, kHeight);
      pass.resolve(scene.frame(), output.get(), mask.get());
      return read_back_uints(mask.get(), kWidth, kHeight);
    };
    const std::vector<std::uint32_t> clean = masks();
    const struct {
      GLenum cap;
      bool on;
    } states[] = {{GL_MULTISAMPLE, false}, {GL_SAMPLE_MASK, true}, {GL_SAMPLE_COVERAGE, true}, {GL_COLOR_LOGIC_OP, true}};
    glSampleMaski(0, 0x1u);
    glSampleCoverage(0.25f, GL_FALSE);
    glLogicOp(GL_XOR);
    for (const auto& state : states) {
      state.on ? glEnable(state.cap) : glDisable(state.cap);
      const std::vector<std::uint32_t> engine = masks();
      EXPECT_EQ(bool(glIsEnabled(state.cap)), state.on) << "capability 0x" << std::hex << state.cap;
      state.on ? glDisable(state.cap) : glEnable(state.cap);
      int differing = 0;
      for (std::size_t p = 0; p < clean.size(); ++p) differing += clean[p] != engine[p];
      EXPECT_EQ(differing, 0) << settings.prepass << " pre-pass, capability 0x" << std::hex << state.cap
                              << (state.on ? " on" : " off");
    }
    glSampleMaski(0, ~0u);
    glSampleCoverage(1.0f, GL_FALSE);
    glLogicOp(GL_COPY);
  }
  gl::check("sample and logic op state");
}

// The pass reads the frame through its own sampler objects: the frame textures' own sampling
// parameters and an engine's sampler objects do not change the image or the masks. Without them
// a GL_REPEAT colour (GL's default) blended the opposite image border into edge pixels, and a
// texture incomplete under its parameters read as zero: a glTexImage2D colour with the default
// mipmap minification filter (black edge pixels), integer G-buffer textures filtered linearly, an
// engine's linear sampler object on the pre-pass's units (most masks wrong).
TEST_F(RsaaPassApi, TheFramesSamplingParametersAndAnEnginesSamplersDoNotReachThePass) {
  constexpr int width = 160, height = 120;
  const test::SceneFrame scene("builtin:default", width, height);
  RsaaSettings settings;
  settings.output_mask = true;
  RsaaPass pass(settings, width, height);
  struct Result {
    Image image;
    std::vector<std::uint32_t> masks;
  };
  const auto run = [&](const RsaaFrame& frame) {
    scene.render_subsamples(pass);
    const gl::Texture output = gl::make_texture_2d(GL_RGBA16F, width, height);
    const gl::Texture mask = gl::make_texture_2d(GL_R32UI, width, height);
    pass.resolve(frame, output.get(), mask.get());
    return Result{read_back_image(output.get(), width, height), read_back_uints(mask.get(), width, height)};
  };
  const auto expect_same = [&](const Result& a, const Result& b, const char* what) {
    int differing_colour = 0, differing_mask = 0;
    for (std::size_t p = 0; p < a.masks.size(); ++p) {
      const Rgb x = a.image.pixels[p], y = b.image.pixels[p];
      differing_colour += x.r != y.r || x.g != y.g || x.b != y.b;
      differing_mask += a.masks[p] != b.masks[p];
    }
    EXPECT_EQ(differing_colour, 0) << what;
    EXPECT_EQ(differing_mask, 0) << what;
  };
  const RsaaFrame frame = scene.frame();
  const Result clean = run(frame);
  const Image one_x = read_back_image(frame.colour, width, height);
  int resampled = 0;
  for (std::size_t p = 0; p < one_x.pixels.size(); ++p) resampled += clean.image.pixels[p].r != one_x.pixels[p].r;
  EXPECT_GT(resampled, 100);  // the comparisons cover resolved pixels

  // An engine's trilinear, repeating sampler object on every unit the pass reads.
  GLuint engine_sampler = 0;
  glCreateSamplers(1, &engine_sampler);
  glSamplerParameteri(engine_sampler, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glSamplerParameteri(engine_sampler, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  for (GLuint unit = 0; unit < 16; ++unit) glBindSampler(unit, engine_sampler);
  expect_same(clean, run(frame), "an engine's sampler objects");
  for (GLuint unit = 0; unit < 16; ++unit) glBindSampler(unit, 0);
  glDeleteSamplers(1, &engine_sampler);

  // The textures' own parameters: a repeating colour, linearly filtered integer textures (incomplete),
  // a depth comparison.
  for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T}) glTextureParameteri(frame.colour, wrap, GL_REPEAT);
  for (GLuint integer : {frame.centre_normal, frame.centre_primitive}) {
    glTextureParameteri(integer, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(integer, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  }
  glTextureParameteri(frame.centre_depth, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  expect_same(clean, run(frame), "the textures' own parameters");
  // The compute post-process reads the integer targets as images, for which a texture's own
  // filters decide completeness: it sets nearest ones for the pass and puts the engine's back.
  for (GLuint integer : {frame.centre_normal, frame.centre_primitive})
    for (GLenum filter : {GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER}) {
      GLint value = 0;
      glGetTextureParameteriv(integer, filter, &value);
      EXPECT_EQ(value, GL_LINEAR) << "texture " << integer << " filter " << filter;
    }
  for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T}) glTextureParameteri(frame.colour, wrap, GL_CLAMP_TO_EDGE);
  for (GLuint integer : {frame.centre_normal, frame.centre_primitive}) {
    glTextureParameteri(integer, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(integer, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }
  glTextureParameteri(frame.centre_depth, GL_TEXTURE_COMPARE_MODE, GL_NONE);

  // A colour made as glTexImage2D leaves it: level 0 only, the mipmap minification filter
  // (incomplete), only the magnification filter set as the pass asks.
  const gl::Texture incomplete = [&] {
    GLuint t = 0;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glBindTexture(GL_TEXTURE_2D, 0);
    std::vector<float> texels(std::size_t(width) * height * 4);
    glGetTextureImage(frame.colour, 0, GL_RGBA, GL_FLOAT, GLsizei(texels.size() * sizeof(float)), texels.data());
    glTextureSubImage2D(t, 0, 0, 0, width, height, GL_RGBA, GL_FLOAT, texels.data());
    return gl::Texture(t);
  }();
  RsaaFrame incomplete_colour = frame;
  incomplete_colour.colour = incomplete.get();
  expect_same(clean, run(incomplete_colour), "an incomplete colour");
  gl::check("sampling parameters");
}

// Making a pass leaves the engine's framebuffer bindings as they were (reading the driver's
// sample positions, for gl4x or the multisample pre-pass, bound the default framebuffer after),
// and the engine's pixel unpack state does not reach the table the pass uploads (a bound unpack
// buffer failed with GL_INVALID_OPERATION, GL_UNPACK_SKIP_PIXELS shifted the table).
TEST_F(RsaaPassApi, MakingAPassLeavesTheEnginesFramebufferAndUnpackStateAlone) {
  const test::SceneFrame scene("builtin:default", kWidth, kHeight);
  RsaaSettings multisample;
  multisample.pattern = "gl4x", multisample.prepass = "msaa";
  const gl::Texture draw_texture = gl::make_texture_2d(GL_RGBA8, 4, 4), read_texture = gl::make_texture_2d(GL_RGBA8, 4, 4);
  const gl::Framebuffer draw_framebuffer = gl::make_framebuffer({{draw_texture.get()}});
  const gl::Framebuffer read_framebuffer = gl::make_framebuffer({{read_texture.get()}});
  const gl::Buffer unpack_buffer = [] {
    GLuint b = 0;
    glCreateBuffers(1, &b);
    glNamedBufferStorage(b, 64, nullptr, 0);
    return gl::Buffer(b);
  }();
  for (const RsaaSettings& settings : {RsaaSettings{}, multisample}) {
    const auto image = [&](RsaaPass& pass) {
      scene.render_subsamples(pass);
      const gl::Texture output = gl::make_texture_2d(GL_RGBA16F, kWidth, kHeight);
      pass.resolve(scene.frame(), output.get());
      return read_back_image(output.get(), kWidth, kHeight);
    };
    RsaaPass clean_pass(settings, kWidth, kHeight);
    const Image clean = image(clean_pass);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, draw_framebuffer.get());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, read_framebuffer.get());
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, unpack_buffer.get());
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 3);
    std::optional<RsaaPass> pass;
    try {
      pass.emplace(settings, kWidth, kHeight);
    } catch (const gl::GlError& e) {
      ADD_FAILURE() << settings.pattern << ": " << e.what();
    }
    GLint draw = 0, read = 0, unpack = 0, skip_pixels = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read);
    glGetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &unpack);
    glGetIntegerv(GL_UNPACK_SKIP_PIXELS, &skip_pixels);
    EXPECT_EQ(GLuint(draw), draw_framebuffer.get()) << settings.pattern;
    EXPECT_EQ(GLuint(read), read_framebuffer.get()) << settings.pattern;
    EXPECT_EQ(GLuint(unpack), unpack_buffer.get()) << settings.pattern;
    EXPECT_EQ(skip_pixels, 3) << settings.pattern;
    // Without the unpack buffer (a shifted table then gave another image).
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    if (!pass) pass.emplace(settings, kWidth, kHeight);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    const Image engine = image(*pass);
    int differing = 0;
    for (std::size_t p = 0; p < clean.pixels.size(); ++p) {
      const Rgb a = clean.pixels[p], b = engine.pixels[p];
      differing += a.r != b.r || a.g != b.g || a.b != b.b;
    }
    EXPECT_EQ(differing, 0) << settings.pattern;
  }
  gl::check("making passes");
}

// RsaaTargets::clear() clears every pixel of the four targets whatever scissor test and masks the
// engine left (a clear obeys them), and leaves them as they were.
TEST_F(RsaaPassApi, TheTargetsClearIgnoresTheEnginesScissorAndMasks) {
  RsaaTargets targets(8, 8);
  const float background[3] = {0.5f, 0.25f, 0.125f};
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, 1, 1);
  glColorMask(GL_FALSE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_FALSE);
  targets.clear(background, 0.5f);
  EXPECT_TRUE(glIsEnabled(GL_SCISSOR_TEST));
  GLboolean colour_mask[4] = {}, depth_mask = GL_TRUE;
  glGetBooleanv(GL_COLOR_WRITEMASK, colour_mask);
  glGetBooleanv(GL_DEPTH_WRITEMASK, &depth_mask);
  EXPECT_EQ(colour_mask[0], GL_FALSE);
  EXPECT_EQ(depth_mask, GL_FALSE);
  glDisable(GL_SCISSOR_TEST);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
  const RsaaFrame frame = targets.frame(glm::mat4(1.0f));
  const Image colour = read_back_image(frame.colour, 8, 8);
  std::vector<float> depth(64);
  glGetTextureImage(frame.centre_depth, 0, GL_DEPTH_COMPONENT, GL_FLOAT, GLsizei(depth.size() * sizeof(float)), depth.data());
  int wrong = 0;
  for (const Rgb& p : colour.pixels) wrong += p.r != 0.5f || p.g != 0.25f || p.b != 0.125f;
  for (float d : depth) wrong += d != 0.5f;
  EXPECT_EQ(wrong, 0);
  gl::check("clearing the targets");
}

// A GL error the engine left set is reported as the engine's, by the call that finds it, before
// the call does anything: it was reported as the pass's ("GL error 0x0500 in make_framebuffer",
// from inside the resolve, or "in make_texture_2d" making a pass).
TEST_F(RsaaPassApi, AGlErrorTheEngineLeftIsReportedAsItsOwn) {
  const test::SceneFrame scene("builtin:default", kWidth, kHeight);
  const auto message_of = [](const std::function<void()>& call) -> std::string {
    glEnable(GLenum(0xDEAD));  // GL_INVALID_ENUM, the engine's
    try {
      call();
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "";
  };
  const std::string made = message_of([&] { RsaaPass(RsaaSettings{}, kWidth, kHeight); });
  EXPECT_NE(made.find("0x0500 was already set when RsaaPass::RsaaPass was called"), std::string::npos) << made;
  EXPECT_NE(message_of([&] { RsaaTargets(kWidth, kHeight); }).find("when RsaaTargets::RsaaTargets was called"),
            std::string::npos);
  RsaaPass pass(RsaaSettings{}, kWidth, kHeight);
  EXPECT_NE(message_of([&] { scene.render_subsamples(pass); }).find("when RsaaPass::render_subsamples was called"),
            std::string::npos);
  scene.render_subsamples(pass);
  const gl::Texture output = gl::make_texture_2d(GL_RGBA16F, kWidth, kHeight);
  const float marker[4] = {-1.0f, -1.0f, -1.0f, -1.0f};
  glClearTexImage(output.get(), 0, GL_RGBA, GL_FLOAT, marker);
  const std::string resolved = message_of([&] { pass.resolve(scene.frame(), output.get()); });
  EXPECT_NE(resolved.find("when RsaaPass::resolve was called: an earlier GL call of the caller's failed"),
            std::string::npos)
      << resolved;
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  int written = 0;
  for (const Rgb& p : read_back_image(output.get(), kWidth, kHeight).pixels) written += p.r != -1.0f;
  EXPECT_EQ(written, 0);  // the refused call did nothing
  pass.resolve(scene.frame(), output.get());  // the next call works
}

// resolve() with no codes (no pre-pass yet, or one whose callback threw) is an error: the code
// textures were undefined (zeros on llvmpipe: a third of the default scene's pixels resampled);
// so is a frame whose G-buffer is not the last pre-pass's (its codes are another view's).
TEST_F(RsaaPassApi, ResolvingWithoutAFinishedPrePassIsAnError) {
  const test::SceneFrame scene("builtin:default", kWidth, kHeight);
  RsaaPass pass(RsaaSettings{}, kWidth, kHeight);
  const gl::Texture output = gl::make_texture_2d(GL_RGBA16F, kWidth, kHeight);
  const auto logic_error_of = [&] {
    try {
      pass.resolve(scene.frame(), output.get());
    } catch (const std::logic_error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(logic_error_of().find("RsaaPass::resolve before render_subsamples"), std::string::npos);
  scene.render_subsamples(pass);
  EXPECT_EQ(logic_error_of(), "");
  EXPECT_THROW(pass.render_subsamples(scene.frame(), [](GLuint, glm::vec2) { throw std::runtime_error("engine"); }),
               std::runtime_error);
  EXPECT_NE(logic_error_of().find("did not finish"), std::string::npos);
  // Two views pre-passed one after the other, then resolved: the first's codes are gone.
  const test::SceneFrame other_view("builtin:edges", kWidth, kHeight);
  scene.render_subsamples(pass);
  other_view.render_subsamples(pass);
  EXPECT_NE(logic_error_of().find("the codes are another frame's"), std::string::npos);
  gl::check("resolving without codes");
}

// What an engine can get wrong without a GL error is refused: a depth convention other than
// OpenGL's default, a program whose RsaaUniforms block was moved to another binding.
TEST_F(RsaaPassApi, OtherClipControlOrAMovedBlockAreRefused) {
  const test::SceneFrame scene("builtin:edges", kWidth, kHeight);
  RsaaPass pass(RsaaSettings{}, kWidth, kHeight);
  RsaaFrame frame = scene.frame();
  const gl::Texture output = gl::make_texture_2d(GL_RGBA16F, kWidth, kHeight);
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  EXPECT_NE(invalid_argument_of([&] { pass.resolve(frame, output.get()); }).find("glClipControl"), std::string::npos);
  glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
  const gl::Program engine = engine_prepass_program(pass);
  glUniformBlockBinding(engine.get(), glGetUniformBlockIndex(engine.get(), "RsaaUniforms"), 5);
  try {
    pass.render_subsamples_with_own_shaders(frame, [&] { glUseProgram(engine.get()); });
    ADD_FAILURE() << "a moved block was accepted";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("reads RsaaUniforms at binding 5"), std::string::npos) << e.what();
  }
  gl::check("after the refusals");
}

}  // namespace
}  // namespace rsaa

namespace rsaa {
namespace {

// The colour's own filters do not matter: the pass reads it through its own bilinear sampler
// (level 0: implicit derivatives differ where neighbouring offsets differ and would select the
// minification filter), so a colour texture filtered nearest gives the same image.
TEST_F(RsaaPassApi, TheColoursFiltersDoNotMatter) {
  const test::SceneFrame scene("builtin:edges", kWidth, kHeight);
  RsaaPass pass(test::paper_resolve(), kWidth, kHeight);
  scene.render_subsamples(pass);
  const RsaaFrame frame = scene.frame();
  const gl::Texture linear_output = gl::make_texture_2d(GL_RGBA16F, kWidth, kHeight);
  pass.resolve(frame, linear_output.get());
  glTextureParameteri(frame.colour, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(frame.colour, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  const gl::Texture nearest_output = gl::make_texture_2d(GL_RGBA16F, kWidth, kHeight);
  pass.resolve(frame, nearest_output.get());
  glTextureParameteri(frame.colour, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(frame.colour, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  const Image a = read_back_image(linear_output.get(), kWidth, kHeight);
  const Image b = read_back_image(nearest_output.get(), kWidth, kHeight);
  const Image one_x = read_back_image(frame.colour, kWidth, kHeight);
  int differing = 0, resampled = 0;
  for (std::size_t p = 0; p < a.pixels.size(); ++p) {
    differing += a.pixels[p].r != b.pixels[p].r || a.pixels[p].g != b.pixels[p].g || a.pixels[p].b != b.pixels[p].b;
    resampled += a.pixels[p].r != one_x.pixels[p].r;
  }
  EXPECT_EQ(differing, 0);
  EXPECT_GT(resampled, 20);
}

// The two-pass post-process (an edge pass, then the resolve where it marked a pixel) and the
// compute one (a list of edge pixels, then the resolve on the list) give the single pass's image
// and masks, bit for bit, for the default options and the paper's resolve with each
// authentication, on scenes with silhouettes, thin parts and many small triangles.
TEST_F(RsaaPassApi, TheEdgePassAndTheEdgeListGiveTheSinglePassImageAndMasks) {
  // The fence also at a size that is no multiple of the passes' work groups or SIMD blocks.
  const struct {
    const char* scene_name;
    int width, height;
  } cases[] = {{"builtin:default", 160, 120}, {"builtin:fence", 160, 120}, {"builtin:interpenetrating", 160, 120},
               {"builtin:fence", 163, 117}};
  for (const auto& c : cases) {
    const char* scene_name = c.scene_name;
    const int width = c.width, height = c.height;
    const test::SceneFrame scene(scene_name, width, height);
    std::vector<RsaaSettings> variants = {RsaaSettings{}};
    for (int auth : {0, 1, 2}) {
      RsaaSettings paper = test::paper_resolve();
      paper.auth = auth;
      variants.push_back(paper);
    }
    RsaaSettings depth_4x = RsaaSettings{};
    depth_4x.pattern = "d3d4x", depth_4x.similarity = "depth";
    variants.push_back(depth_4x);
    // Every code format and count of code textures the listing pass reads as images.
    RsaaSettings wide_codes = RsaaSettings{}, many_samples = RsaaSettings{};
    wide_codes.code_bits = 16;
    many_samples.table = std::make_shared<const OffsetTable>(
        read_offset_table(std::string(RSAA_SOURCE_DIR) + "/tables/d3d16x.json"));
    many_samples.pattern = "", many_samples.code_bits = 32;
    variants.push_back(wide_codes);
    variants.push_back(many_samples);
    for (RsaaSettings settings : variants) {
      int samples = 0;
      std::vector<Image> images;
      std::vector<std::vector<std::uint32_t>> masks;
      // The last: the compute pass without the mask output (its shaders are built without it).
      const std::vector<std::string> posts = {"single", "edges", "compute", "compute, no mask"};
      for (const std::string& post : posts) {
        const bool no_mask = post == "compute, no mask";
        settings.post = no_mask ? "compute" : post;
        settings.output_mask = !no_mask;
        RsaaPass pass(settings, width, height);
        samples = pass.pattern().size();
        scene.render_subsamples(pass);
        const gl::Texture output = gl::make_texture_2d(GL_RGBA16F, width, height);
        const gl::Texture mask = gl::make_texture_2d(GL_R32UI, width, height);
        pass.resolve(scene.frame(), output.get(), no_mask ? 0u : mask.get());
        images.push_back(read_back_image(output.get(), width, height));
        masks.push_back(no_mask ? masks[0] : read_back_uints(mask.get(), width, height));
      }
      const std::uint32_t all_similar = (1u << samples) - 1u;
      for (std::size_t k = 1; k < posts.size(); ++k) {
        int edges = 0, differing_colour = 0, differing_mask = 0;
        for (std::size_t p = 0; p < masks[0].size(); ++p) {
          edges += masks[0][p] != all_similar;
          differing_mask += masks[0][p] != masks[k][p];
          const Rgb a = images[0].pixels[p], b = images[k].pixels[p];
          differing_colour += a.r != b.r || a.g != b.g || a.b != b.b;
        }
        SCOPED_TRACE(std::string(scene_name) + " " + std::to_string(width) + "x" + std::to_string(height) + " " +
                     settings.pattern + " " + settings.similarity + " auth " + std::to_string(settings.auth) + " " +
                     settings.multi_surface + " " + std::to_string(settings.code_bits) + "-bit codes post " + posts[k]);
        EXPECT_GT(edges, 100);  // the comparison covers resolved pixels
        EXPECT_EQ(differing_mask, 0);
        EXPECT_EQ(differing_colour, 0);
      }
    }
  }
}

// Resolving in place (output == frame.colour, the compute post-process) gives the image and
// masks of a separate output, bit for bit: every listed pixel is resolved from the 1x colours
// before any is overwritten. The edge pass and the single pass, which read the colour while they
// write it, refuse it. A colour drawn into another texture (RsaaTargets::use_colour) is checked.
TEST_F(RsaaPassApi, ResolvingInPlaceGivesTheSeparateOutputsImage) {
  constexpr int width = 160, height = 120;
  for (const char* scene_name : {"builtin:default", "builtin:fence"}) {
    test::SceneFrame scene(scene_name, width, height);
    RsaaSettings settings;
    settings.output_mask = true;
    RsaaPass pass(settings, width, height);
    scene.render_subsamples(pass);
    const gl::Texture output = gl::make_texture_2d(GL_RGBA16F, width, height);
    const gl::Texture mask = gl::make_texture_2d(GL_R32UI, width, height);
    const gl::Texture mask_in_place = gl::make_texture_2d(GL_R32UI, width, height);
    pass.resolve(scene.frame(), output.get(), mask.get());
    const Image one_x = read_back_image(scene.frame().colour, width, height);
    pass.resolve(scene.frame(), scene.frame().colour, mask_in_place.get());
    const Image separate = read_back_image(output.get(), width, height);
    const Image in_place = read_back_image(scene.frame().colour, width, height);
    const std::vector<std::uint32_t> a = read_back_uints(mask.get(), width, height);
    const std::vector<std::uint32_t> b = read_back_uints(mask_in_place.get(), width, height);
    int differing = 0, resampled = 0;
    for (std::size_t p = 0; p < separate.pixels.size(); ++p) {
      const Rgb x = separate.pixels[p], y = in_place.pixels[p];
      differing += x.r != y.r || x.g != y.g || x.b != y.b;
      resampled += x.r != one_x.pixels[p].r || x.g != one_x.pixels[p].g || x.b != one_x.pixels[p].b;
    }
    SCOPED_TRACE(scene_name);
    EXPECT_EQ(differing, 0);
    EXPECT_EQ(a, b);
    EXPECT_GT(resampled, 100);  // the comparison covers resolved pixels
  }
  const test::SceneFrame scene("builtin:default", width, height);
  for (const char* post : {"edges", "single"}) {
    RsaaSettings settings;
    settings.post = post;
    RsaaPass pass(settings, width, height);
    scene.render_subsamples(pass);
    EXPECT_THROW(pass.resolve(scene.frame(), scene.frame().colour), std::invalid_argument) << post;
  }
  RsaaTargets targets(width, height);
  const gl::Texture wrong_format = gl::make_texture_2d(GL_RG16F, width, height);
  const gl::Texture wrong_size = gl::make_texture_2d(GL_RGBA16F, width, height + 1);
  EXPECT_THROW(targets.use_colour(wrong_format.get()), std::invalid_argument);
  EXPECT_THROW(targets.use_colour(wrong_size.get()), std::invalid_argument);
  const gl::Texture own = gl::make_texture_2d(GL_RGBA16F, width, height, GL_LINEAR);
  targets.use_colour(own.get());
  EXPECT_EQ(targets.frame(glm::mat4(1.0f)).colour, own.get());
  targets.use_colour(0);
  EXPECT_NE(targets.frame(glm::mat4(1.0f)).colour, own.get());
}

// An output that is not mipmap-complete (level 0 only, the default minification filter, as
// glTexImage2D leaves it) takes the image as any other, in every post-process; one whose base
// level is not 0 (the pass writes level 0) is refused, not silently left unresolved.
TEST_F(RsaaPassApi, AnIncompleteOutputWorksAndABaseLevelIsRefused) {
  constexpr int width = 160, height = 120;
  const test::SceneFrame scene("builtin:default", width, height);
  for (const char* post : {"compute", "edges", "single"}) {
    RsaaSettings settings;
    settings.post = post;
    RsaaPass pass(settings, width, height);
    scene.render_subsamples(pass);
    const gl::Texture complete = gl::make_texture_2d(GL_RGBA16F, width, height);
    const gl::Texture incomplete = [&] {
      GLuint t = 0;
      glGenTextures(1, &t);
      glBindTexture(GL_TEXTURE_2D, t);
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
      glBindTexture(GL_TEXTURE_2D, 0);
      return gl::Texture(t);
    }();
    pass.resolve(scene.frame(), complete.get());
    pass.resolve(scene.frame(), incomplete.get());
    // The compute path makes it complete for its image stores only while it stores.
    GLint min_filter = 0;
    glGetTextureParameteriv(incomplete.get(), GL_TEXTURE_MIN_FILTER, &min_filter);
    EXPECT_EQ(min_filter, GL_NEAREST_MIPMAP_LINEAR) << post;
    const Image a = read_back_image(complete.get(), width, height);
    const Image b = read_back_image(incomplete.get(), width, height);
    int differing = 0;
    for (std::size_t p = 0; p < a.pixels.size(); ++p)
      differing += a.pixels[p].r != b.pixels[p].r || a.pixels[p].g != b.pixels[p].g || a.pixels[p].b != b.pixels[p].b;
    EXPECT_EQ(differing, 0) << post;

    const gl::Texture base_level_1 = [&] {
      GLuint t = 0;
      glCreateTextures(GL_TEXTURE_2D, 1, &t);
      glTextureStorage2D(t, 2, GL_RGBA16F, width, height);
      glTextureParameteri(t, GL_TEXTURE_BASE_LEVEL, 1);
      return gl::Texture(t);
    }();
    try {
      pass.resolve(scene.frame(), base_level_1.get());
      ADD_FAILURE() << post << ": an output with base level 1 was taken";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("GL_TEXTURE_BASE_LEVEL 1"), std::string::npos) << e.what();
    }
  }
  gl::check("incomplete output test");
}

// The edge pass's test (rsaa_pixel_has_edge: the largest and smallest code) against the mask
// (rsaa_pixel_mask: every subsample decoded, then split), per pixel of the same pre-pass. Too few
// marked pixels would change the image (the test above); too many would only cost time, and the
// two are equal but for rounding of the split, which these scenes do not reach. The pre-passes
// that write records list the edge pixels as they make the codes (the compute post-process then
// lists nothing): exactly the pixels the edge test passes.
TEST_F(RsaaPassApi, TheEdgePassMarksExactlyThePixelsWhoseMaskIsNotAllSimilar) {
  constexpr int width = 160, height = 120;
  const std::string probe_main =
      "layout(location = 0) out uvec2 o;\n"
      "void main() {\n"
      "  ivec2 pixel = ivec2(gl_FragCoord.xy);\n"
      "  float similarity[RSAA_SAMPLE_COUNT];\n"
      "  uvec2 centre_normal;\n"
      "  o = uvec2(rsaa_pixel_has_edge(pixel) ? 1u : 0u,\n"
      "            rsaa_pixel_mask(pixel, similarity, centre_normal) != RSAA_ALL_SIMILAR ? 1u : 0u);\n"
      "}\n";
  for (const char* scene_name : {"builtin:default", "builtin:fence", "builtin:grazing"}) {
    const test::SceneFrame scene(scene_name, width, height);
    RsaaSettings depth_4x, wide_codes, background_only, multisample, jittered;
    depth_4x.pattern = "d3d4x", depth_4x.similarity = "depth";
    wide_codes.code_bits = 16;
    background_only.threshold = 1.5f;  // most surface edges stay below: the code-0 rule decides
    multisample.pattern = "gl4x", multisample.prepass = "msaa";
    jittered.prepass = "jittered";
    for (const RsaaSettings& settings : {RsaaSettings{}, depth_4x, wide_codes, background_only, multisample, jittered}) {
      RsaaPass pass(settings, width, height);
      scene.render_subsamples(pass);
      // The pre-passes that write records list the edges themselves (the post-process then reads
      // no codes of edge-free pixels); the jittered one leaves it to the post-process.
      const std::optional<std::vector<std::uint32_t>> listed = RsaaPassTesting::prepass_edge_list(pass, width);
      EXPECT_EQ(listed.has_value(), settings.prepass != "jittered");
      const int samples = pass.pattern().size();
      const gl::Program probe = gl::make_program(
          {{GL_VERTEX_SHADER, gl::shader_source("fullscreen.vert")},
           {GL_FRAGMENT_SHADER, rsaa_shader_file("rsaa_post.glsl") + probe_main}},
          rsaa_shader_defines(settings, samples, false), "edge test probe");
      // The block's head as shaders/rsaa_uniforms.glsl lays it out: only the viewport and the
      // threshold matter to the two functions.
      std::vector<float> block(24 + 4 * samples, 0.0f);
      block[16] = float(width), block[17] = float(height), block[20] = settings.threshold;
      const gl::Buffer uniforms = [&] {
        GLuint id = 0;
        glCreateBuffers(1, &id);
        glNamedBufferData(id, GLsizeiptr(block.size() * sizeof(float)), block.data(), GL_STATIC_DRAW);
        return gl::Buffer(id);
      }();
      glBindBufferBase(GL_UNIFORM_BUFFER, GLuint(settings.uniform_binding), uniforms.get());
      const RsaaFrame frame = scene.frame();
      glBindTextureUnit(1, frame.centre_normal);
      const std::vector<GlName> codes = pass.code_textures();
      for (std::size_t k = 0; k < codes.size(); ++k) glBindTextureUnit(GLuint(4 + k), codes[k]);
      const gl::Texture result = gl::make_texture_2d(GL_RG32UI, width, height);
      const gl::Framebuffer target = gl::make_framebuffer({{result.get()}});
      glBindFramebuffer(GL_FRAMEBUFFER, target.get());
      glViewport(0, 0, width, height);
      glUseProgram(probe.get());
      draw_fullscreen_triangle();
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      std::vector<std::uint32_t> pairs(std::size_t(width) * height * 2);
      glGetTextureImage(result.get(), 0, GL_RG_INTEGER, GL_UNSIGNED_INT, GLsizei(pairs.size() * 4), pairs.data());
      gl::check("edge test probe");
      int edges = 0, missed = 0, extra = 0;
      std::vector<std::uint32_t> edge_pixels;
      for (std::size_t p = 0; p < pairs.size(); p += 2) {
        edges += pairs[p + 1] != 0;
        missed += pairs[p] == 0 && pairs[p + 1] != 0;
        extra += pairs[p] != 0 && pairs[p + 1] == 0;
        if (pairs[p] != 0) edge_pixels.push_back(std::uint32_t(p / 2));
      }
      SCOPED_TRACE(std::string(scene_name) + " " + pass.pattern().name + " " + settings.similarity + " " +
                   std::to_string(settings.code_bits) + "-bit codes, threshold " + std::to_string(settings.threshold));
      EXPECT_GT(edges, 50);
      EXPECT_EQ(missed, 0);
      EXPECT_EQ(extra, 0);
      // Each pixel the edge test passes, once.
      if (listed) {
        EXPECT_EQ(*listed, edge_pixels);
      }
    }
  }
}

// The engine's depth convention (RsaaSettings::depth): one scene drawn with glClipControl
// GL_ZERO_TO_ONE, with and without reverse Z (the projection remapped so), gives the masks of
// OpenGL's default convention up to float ties; a clip control or depth order other than the
// setting's is refused.
TEST_F(RsaaPassApi, ZeroToOneAndReverseZDepthGiveTheDefaultMasks) {
  constexpr int width = 160, height = 120;
  const Scene scene = load_scene("builtin:default");
  const GpuScene gpu(scene);
  const SceneRenderer renderer;
  const View gl_view = make_view(choose_camera(scene, std::nullopt), width, height);
  // Every pre-pass: the records' depths (multisample and "records") follow the convention too.
  for (const char* pre_pass : {"jittered", "records", "msaa"}) {
    SCOPED_TRACE(pre_pass);
    std::vector<std::vector<std::uint32_t>> masks;
    for (const char* depth : {"gl", "zero-to-one", "reverse-z"}) {
      const bool zero_to_one = std::string(depth) != "gl", reverse = std::string(depth) == "reverse-z";
      View view = gl_view;
      if (zero_to_one) {
        glm::mat4 remap(1.0f);  // clip z' = (z + w) / 2, or w - (z + w) / 2 for reverse Z
        remap[2][2] = reverse ? -0.5f : 0.5f;
        remap[3][2] = 0.5f;
        view.projection = remap * gl_view.projection;
        glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
      }
      const GLenum depth_func = reverse ? GL_GREATER : GL_LESS;
      RsaaTargets targets(width, height);
      const glm::vec3 background = gpu.background();
      targets.clear(&background.x, reverse ? 0.0f : 1.0f);
      targets.bind();
      SceneRenderer::draw(gpu, view, {0.0f, 0.0f}, renderer.gbuffer_program(), depth_func);
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      RsaaSettings settings;
      settings.depth = depth;
      settings.output_mask = true;
      settings.prepass = pre_pass;
      if (settings.prepass == "msaa") settings.pattern = "gl4x";
      RsaaPass pass(settings, width, height);
      const RsaaFrame frame = targets.frame(view.inverse_projection());
      pass.render_subsamples(frame, [&](GLuint program, glm::vec2 jitter) {
        SceneRenderer::draw(gpu, view, jitter, program, depth_func);
      });
      const gl::Texture output = gl::make_texture_2d(GL_RGBA16F, width, height);
      const gl::Texture mask = gl::make_texture_2d(GL_R32UI, width, height);
      pass.resolve(frame, output.get(), mask.get());
      masks.push_back(read_back_uints(mask.get(), width, height));
      if (zero_to_one) {
        // The setting must match the GL and the projection.
        RsaaSettings other = settings;
        other.depth = reverse ? "zero-to-one" : "reverse-z";
        RsaaPass wrong_order(other, width, height);
        EXPECT_NE(invalid_argument_of([&] { wrong_order.resolve(frame, output.get()); }).find("RsaaSettings::depth"),
                  std::string::npos);
        other.depth = "gl";
        RsaaPass wrong_clip(other, width, height);
        EXPECT_NE(invalid_argument_of([&] { wrong_clip.resolve(frame, output.get()); }).find("GL_NEGATIVE_ONE_TO_ONE"),
                  std::string::npos);
      }
      glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    }
    const std::uint32_t all_similar = std::string(pre_pass) == "msaa" ? 15u : 255u;
    int edges = 0;
    for (std::uint32_t m : masks[0]) edges += m != all_similar;
    EXPECT_GT(edges, 200);
    for (std::size_t k = 1; k < masks.size(); ++k) {
      int differing = 0;
      for (std::size_t p = 0; p < masks[0].size(); ++p) differing += masks[0][p] != masks[k][p];
      // Float ties only: depth is stored with another precision per convention.
      EXPECT_LE(differing, edges / 100) << "convention " << k;
      std::printf("depth convention %zu: %d of %d edge masks differ from OpenGL's default\n", k, differing, edges);
    }
  }
  gl::check("depth conventions");
}

}  // namespace
}  // namespace rsaa

namespace rsaa {

namespace {

// The texture's level 0 as RGBA floats (a format without alpha reads alpha 1).
std::vector<float> read_back_floats(GLuint texture, int width, int height) {
  std::vector<float> values(std::size_t(width) * height * 4);
  glGetTextureImage(texture, 0, GL_RGBA, GL_FLOAT, GLsizei(values.size() * sizeof(float)), values.data());
  return values;
}

// A copy of `texture` in `format` (a blit converts; linear colours to an sRGB texture encoded).
gl::Texture converted(GLuint texture, GLenum format, int width, int height) {
  gl::Texture copy = gl::make_texture_2d(format, width, height);
  glEnable(GL_FRAMEBUFFER_SRGB);
  GLuint framebuffers[2] = {};
  glCreateFramebuffers(2, framebuffers);
  glNamedFramebufferTexture(framebuffers[0], GL_COLOR_ATTACHMENT0, texture, 0);
  glNamedFramebufferTexture(framebuffers[1], GL_COLOR_ATTACHMENT0, copy.get(), 0);
  glBlitNamedFramebuffer(framebuffers[0], framebuffers[1], 0, 0, width, height, 0, 0, width, height,
                         GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glDeleteFramebuffers(2, framebuffers);
  glDisable(GL_FRAMEBUFFER_SRGB);
  return copy;
}

// An engine's colour target as it is (HDR: RGBA16F, RGBA32F, R11F_G11F_B10F; LDR: RGB10_A2,
// RGBA8, and SRGB8_ALPHA8, decoded as read and encoded as written), resolved into an output of
// the same format, separately or in place, by both ways the pass writes: the RGBA16F frame's
// image, within the format's precision. Other formats are refused, naming the ones taken, and an
// sRGB output of mutable storage by the compute post-process, which writes through a view.
TEST_F(RsaaPassApi, TheEnginesColourFormatResolvesAsRgba16fDoes) {
  constexpr int width = 160, height = 120;
  const test::SceneFrame scene("builtin:default", width, height);
  const RsaaFrame frame = scene.frame();
  const struct {
    GLenum format;
    float tolerance;  // a few steps of the format near 1
  } formats[] = {{GL_RGBA32F, 2e-3f},        {GL_R11F_G11F_B10F, 0.05f}, {GL_RGB10_A2, 3.0f / 1023},
                 {GL_RGBA8, 3.0f / 255}, {GL_SRGB8_ALPHA8, 3.0f / 255}};
  // The two ways the pass writes its output: image stores (compute) and a framebuffer (single;
  // edges writes the same way); and compute in rounds of rows (in place: a copy of the colour
  // into the scratch image and back).
  for (const std::string post : {"compute", "compute in rounds", "single"}) {
    RsaaSettings settings;
    settings.post = post == "single" ? "single" : "compute";
    RsaaPass pass(settings, width, height);
    if (post == "compute in rounds") RsaaPassTesting::set_edge_list_capacity(pass, width * 7 + 3);
    scene.render_subsamples(pass);
    const gl::Texture half_float = gl::make_texture_2d(GL_RGBA16F, width, height);
    pass.resolve(frame, half_float.get());
    for (const auto& f : formats) {
      std::vector<float> separate_image;
      for (const bool in_place : {false, true}) {
        if (in_place && post == "single") continue;
        char format[16];
        std::snprintf(format, sizeof format, "0x%04X", unsigned(f.format));
        SCOPED_TRACE(post + ", format " + format + (in_place ? ", in place" : ""));
        // The engine's frame in this format: the same 1x colours, as its target would hold them.
        const gl::Texture colour = converted(frame.colour, f.format, width, height);
        RsaaFrame engine_frame = frame;
        engine_frame.colour = colour.get();
        const std::vector<float> one_x = read_back_floats(colour.get(), width, height);
        const gl::Texture separate = gl::make_texture_2d(f.format, width, height);
        const GLuint output = in_place ? colour.get() : separate.get();
        pass.resolve(engine_frame, output);
        const std::vector<float> image = read_back_floats(output, width, height);
        const gl::Texture expected_texture = converted(half_float.get(), f.format, width, height);
        const std::vector<float> expected = read_back_floats(expected_texture.get(), width, height);
        float worst = 0.0f;
        int resampled = 0;
        for (std::size_t k = 0; k < image.size(); ++k) {
          worst = std::max(worst, std::abs(image[k] - expected[k]));
          resampled += std::abs(expected[k] - one_x[k]) > 4 * f.tolerance;
        }
        EXPECT_LE(worst, f.tolerance);
        EXPECT_GT(resampled, 100);  // the comparison covers resolved pixels, beyond the tolerance
        EXPECT_FALSE(glIsEnabled(GL_FRAMEBUFFER_SRGB));  // the engine's setting, as it was
        // In place: the separate output's image exactly (the scratch keeps the output's format).
        if (in_place) {
          EXPECT_TRUE(image == separate_image);
        }
        separate_image = image;
      }
    }
  }
  // HDR values beyond half float's range (65504) in an RGBA32F frame, resolved in place in one
  // round and in rounds: the separate output's image, not clamped by a scratch or copy.
  std::vector<float> bright = read_back_floats(frame.colour, width, height);
  for (float& v : bright) v *= 1e5f;
  for (const bool rounds : {false, true}) {
    SCOPED_TRACE(rounds ? "RGBA32F x 1e5, in rounds" : "RGBA32F x 1e5");
    RsaaPass pass(RsaaSettings{}, width, height);
    if (rounds) RsaaPassTesting::set_edge_list_capacity(pass, width * 7 + 3);
    scene.render_subsamples(pass);
    std::vector<float> images[2];
    for (const bool in_place : {false, true}) {
      const gl::Texture colour = gl::make_texture_2d(GL_RGBA32F, width, height);
      glTextureSubImage2D(colour.get(), 0, 0, 0, width, height, GL_RGBA, GL_FLOAT, bright.data());
      RsaaFrame engine_frame = frame;
      engine_frame.colour = colour.get();
      const gl::Texture separate = gl::make_texture_2d(GL_RGBA32F, width, height);
      const GLuint output = in_place ? colour.get() : separate.get();
      pass.resolve(engine_frame, output);
      images[in_place] = read_back_floats(output, width, height);
    }
    EXPECT_TRUE(images[0] == images[1]);
    EXPECT_GT(*std::max_element(images[1].begin(), images[1].end()), 65504.0f * 1.1f);
  }
  RsaaPass pass(RsaaSettings{}, width, height);
  scene.render_subsamples(pass);
  for (const GLenum refused : {GLenum(GL_RG16F), GLenum(GL_SRGB8)}) {
    const gl::Texture colour = gl::make_texture_2d(refused, width, height);
    RsaaFrame engine_frame = frame;
    engine_frame.colour = colour.get();
    const std::string message = invalid_argument_of([&] { pass.resolve(engine_frame, colour.get()); });
    EXPECT_NE(message.find("RsaaFrame::colour"), std::string::npos) << message;
    EXPECT_NE(message.find("GL_R11F_G11F_B10F"), std::string::npos) << message;
    const gl::Texture output = gl::make_texture_2d(refused, width, height);
    EXPECT_NE(invalid_argument_of([&] { pass.resolve(frame, output.get()); }).find("resolve output"),
              std::string::npos);
  }
  // The engine's GL_FRAMEBUFFER_SRGB does not change the image, and is left as it was.
  {
    const gl::Texture colour = converted(frame.colour, GL_SRGB8_ALPHA8, width, height);
    RsaaFrame engine_frame = frame;
    engine_frame.colour = colour.get();
    std::vector<float> images[2];
    for (const bool engine_srgb : {false, true}) {
      const gl::Texture output = gl::make_texture_2d(GL_SRGB8_ALPHA8, width, height);
      engine_srgb ? glEnable(GL_FRAMEBUFFER_SRGB) : glDisable(GL_FRAMEBUFFER_SRGB);
      pass.resolve(engine_frame, output.get());
      EXPECT_EQ(glIsEnabled(GL_FRAMEBUFFER_SRGB), engine_srgb ? GL_TRUE : GL_FALSE);
      images[engine_srgb] = read_back_floats(output.get(), width, height);
    }
    glDisable(GL_FRAMEBUFFER_SRGB);
    EXPECT_TRUE(images[0] == images[1]);
    // RsaaTargets' clear into an sRGB colour: the linear background encoded, whatever the setting.
    RsaaTargets targets(width, height);
    targets.use_colour(colour.get());
    const float background[3] = {0.2f, 0.5f, 0.9f};
    targets.clear(background);
    const std::vector<float> cleared = read_back_floats(colour.get(), width, height);
    glEnable(GL_FRAMEBUFFER_SRGB);
    targets.clear(background);
    glDisable(GL_FRAMEBUFFER_SRGB);
    EXPECT_TRUE(read_back_floats(colour.get(), width, height) == cleared);
    EXPECT_NE(cleared[0], 0.2f);  // encoded (or read back decoded: 0.2 to a step, not exactly)
  }
  GLuint mutable_srgb = 0;
  glGenTextures(1, &mutable_srgb);
  const gl::Texture mutable_output(mutable_srgb);
  glBindTexture(GL_TEXTURE_2D, mutable_srgb);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glBindTexture(GL_TEXTURE_2D, 0);
  EXPECT_NE(invalid_argument_of([&] { pass.resolve(frame, mutable_srgb); }).find("glTexStorage2D"), std::string::npos);
  gl::check("colour formats");
}


// An image whose edge list (every pixel) exceeds the driver's shader storage block is resolved in
// rounds of rows, each listed and resolved in turn: the same image and masks as one round, in
// place or not. A 8192 x 4096 pass was refused on llvmpipe (128 MiB blocks) although the renderer
// takes 8192 pixels per side; the rounds are run here with a small list at a small size.
TEST_F(RsaaPassApi, AnEdgeListSmallerThanTheImageResolvesItInRounds) {
  GLint64 max_block = 0;
  GLint max_texture = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &max_block);
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_texture);
  const int wide = std::min(max_texture, 8192), tall = int(std::min<GLint64>(max_texture, max_block / 4 / wide));
  EXPECT_NO_THROW(RsaaPass(RsaaSettings{}, wide, tall)) << wide << "x" << tall;

  constexpr int width = 163, height = 117;
  const test::SceneFrame scene("builtin:fence", width, height);
  RsaaSettings single;
  single.post = "single", single.output_mask = true;
  RsaaPass reference(single, width, height);
  scene.render_subsamples(reference);
  const gl::Texture reference_output = gl::make_texture_2d(GL_RGBA16F, width, height);
  const gl::Texture reference_mask = gl::make_texture_2d(GL_R32UI, width, height);
  reference.resolve(scene.frame(), reference_output.get(), reference_mask.get());
  const Image expected = read_back_image(reference_output.get(), width, height);
  const std::vector<std::uint32_t> expected_masks = read_back_uints(reference_mask.get(), width, height);
  const Image one_x = read_back_image(scene.frame().colour, width, height);
  int resampled = 0;
  for (std::size_t p = 0; p < one_x.pixels.size(); ++p) resampled += expected.pixels[p].r != one_x.pixels[p].r;
  EXPECT_GT(resampled, 100);

  RsaaSettings settings;
  settings.output_mask = true;
  // Rounds of one row, of seven rows and a last short one, of all but one row; a list smaller
  // than a row holds a row.
  for (const std::int64_t capacity : {std::int64_t(width), std::int64_t(width) * 7 + 3,
                                      std::int64_t(width) * (height - 1), std::int64_t(1)}) {
    for (const bool in_place : {false, true}) {
      SCOPED_TRACE("capacity " + std::to_string(capacity) + (in_place ? ", in place" : ""));
      test::SceneFrame frame_scene("builtin:fence", width, height);
      RsaaPass pass(settings, width, height);
      RsaaPassTesting::set_edge_list_capacity(pass, capacity);
      frame_scene.render_subsamples(pass);
      const gl::Texture separate = gl::make_texture_2d(GL_RGBA16F, width, height);
      const gl::Texture mask = gl::make_texture_2d(GL_R32UI, width, height);
      const GLuint output = in_place ? frame_scene.frame().colour : separate.get();
      pass.resolve(frame_scene.frame(), output, mask.get());
      const Image image = read_back_image(output, width, height);
      int differing = 0;
      for (std::size_t p = 0; p < image.pixels.size(); ++p) {
        const Rgb a = expected.pixels[p], b = image.pixels[p];
        differing += a.r != b.r || a.g != b.g || a.b != b.b;
      }
      EXPECT_EQ(differing, 0);
      EXPECT_EQ(read_back_uints(mask.get(), width, height), expected_masks);
    }
  }
  gl::check("edge list rounds");
}

// A context whose driver gives a deleted object's name to the next object made, as most drivers
// do (Mesa does so only with its force_gl_names_reuse option, read when the context is made).
class RsaaPassApiReusedNames : public test::GlTest {
 protected:
  static void SetUpTestSuite() {
    setenv("force_gl_names_reuse", "true", 1);
    test::GlTest::SetUpTestSuite();
    unsetenv("force_gl_names_reuse");
  }
};

// An engine that deletes its output or colour texture and makes another of the same format and
// size gets the new one resolved, though its name is the old one's: the pass's framebuffers, made
// for the old texture and not bound when it was deleted, still held it (the copy and the fragment
// passes wrote into the deleted output, or copied the deleted colour).
TEST_F(RsaaPassApiReusedNames, ATextureMadeUnderADeletedOnesNameIsTheOneResolved) {
  constexpr int width = 64, height = 48;
  GLuint first = 0, second = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &first);
  glDeleteTextures(1, &first);
  glCreateTextures(GL_TEXTURE_2D, 1, &second);
  glDeleteTextures(1, &second);
  if (first != second) GTEST_SKIP() << "this driver does not reuse names";
  const test::SceneFrame scene("builtin:default", width, height);
  const auto texture_like_output = [&] { return gl::make_texture_2d(GL_RGBA16F, width, height, GL_LINEAR); };
  for (const char* post : {"compute", "edges", "single"}) {
    SCOPED_TRACE(post);
    RsaaSettings settings;
    settings.post = post;
    RsaaPass pass(settings, width, height);
    scene.render_subsamples(pass);
    // The output.
    gl::Texture output = texture_like_output();
    pass.resolve(scene.frame(), output.get());
    const Image expected = read_back_image(output.get(), width, height);
    const GLuint old_name = output.get();
    output.reset();
    output = texture_like_output();
    ASSERT_EQ(output.get(), old_name);
    pass.resolve(scene.frame(), output.get());
    const Image again = read_back_image(output.get(), width, height);
    int differing = 0;
    for (std::size_t p = 0; p < expected.pixels.size(); ++p) {
      const Rgb a = expected.pixels[p], b = again.pixels[p];
      differing += a.r != b.r || a.g != b.g || a.b != b.b;
    }
    EXPECT_EQ(differing, 0) << "a new output under the old one's name";
    // The colour: one frame's, then another texture of one grey under its name.
    gl::Texture colour = texture_like_output();
    const float frame_grey[4] = {0.75f, 0.75f, 0.75f, 1.0f}, grey[4] = {0.25f, 0.25f, 0.25f, 1.0f};
    glClearTexImage(colour.get(), 0, GL_RGBA, GL_FLOAT, frame_grey);
    RsaaFrame frame = scene.frame();
    frame.colour = colour.get();
    pass.resolve(frame, output.get());
    const GLuint old_colour = colour.get();
    colour.reset();
    colour = texture_like_output();
    ASSERT_EQ(colour.get(), old_colour);
    glClearTexImage(colour.get(), 0, GL_RGBA, GL_FLOAT, grey);
    pass.resolve(frame, output.get());
    const Image resolved = read_back_image(output.get(), width, height);
    int not_grey = 0;
    for (const Rgb& p : resolved.pixels) not_grey += p.r != 0.25f || p.g != 0.25f || p.b != 0.25f;
    EXPECT_EQ(not_grey, 0) << "a new colour under the old one's name";
  }
  gl::check("names reused");
}

}  // namespace
}  // namespace rsaa

namespace rsaa {
namespace {

// Every code texture of a pass, as bytes (RGBA8UI: 8-bit codes).
std::vector<std::uint8_t> read_back_codes(const RsaaPass& pass, int width, int height) {
  std::vector<std::uint8_t> all;
  for (const GlName texture : pass.code_textures()) {
    std::vector<std::uint8_t> texels(std::size_t(width) * height * 4);
    glGetTextureImage(texture, 0, GL_RGBA_INTEGER, GL_UNSIGNED_BYTE, GLsizei(texels.size()), texels.data());
    all.insert(all.end(), texels.begin(), texels.end());
  }
  return all;
}

// The record passes give the same codes, byte for byte, whether they read the records as images
// (where the driver loads them) or as textures (the fallback), and in rounds of rows when the
// pixel list cannot hold every pixel; with and without material edges, for the multisample
// pre-pass's one 4x draw and the union pattern's two, and for d3d8x's jittered draws writing
// records into layers ("records").
TEST_F(RsaaPassApi, TheRecordPassesCodesDoNotDependOnHowTheyReadTheRecords) {
  constexpr int width = 163, height = 117;
  const auto union_table = std::make_shared<const OffsetTable>(
      read_offset_table(std::string(RSAA_SOURCE_DIR) + "/tables/custom-gl4x-union.json"));
  for (const bool material_edges : {false, true}) {
    const test::SceneFrame scene("builtin:coplanar", width, height, material_edges);
    for (const char* pre_pass : {"gl4x", "union", "records"}) {
      RsaaSettings settings;
      settings.prepass = "msaa", settings.material_edges = material_edges;
      if (std::string(pre_pass) == "union")
        settings.table = union_table, settings.pattern = "";
      else if (std::string(pre_pass) == "gl4x")
        settings.pattern = "gl4x";
      else
        settings.prepass = "records";
      SCOPED_TRACE(std::string(pre_pass) + (material_edges ? ", material edges" : ""));
      RsaaPass images(settings, width, height);
      ASSERT_EQ(images.multisample_prepass(), settings.prepass == "msaa");
      scene.render_subsamples(images);
      const std::vector<std::uint8_t> expected = read_back_codes(images, width, height);
      std::size_t not_one = 0;
      for (const std::uint8_t code : expected) not_one += code != 1;
      EXPECT_GT(not_one, 1000u);  // codes other than "the centre's triangle": the passes computed them
      RsaaPass textures(settings, width, height);
      RsaaPassTesting::read_records_as_textures(textures);
      scene.render_subsamples(textures);
      EXPECT_EQ(read_back_codes(textures, width, height), expected);
      for (const std::int64_t capacity : {std::int64_t(width) * 5 + 1, std::int64_t(1)}) {
        RsaaPass rounds(settings, width, height);
        RsaaPassTesting::set_edge_list_capacity(rounds, capacity);
        scene.render_subsamples(rounds);
        EXPECT_EQ(read_back_codes(rounds, width, height), expected) << "list of " << capacity << " pixels";
      }
    }
  }
  gl::check("record passes");
}


// An engine's draw may leave the state the pass drew with changed (a scissor, no depth or colour
// writes): the pass sets its own again before every clear and draw of the next subsample, so the
// codes are those of a callback that changed nothing, on every pre-pass (the jittered draws, the
// draws writing records, the multisample draw, the union pattern's two).
TEST_F(RsaaPassApi, ACallbackLeavingScissorAndMasksDoesNotReachTheNextDraw) {
  constexpr int width = 96, height = 72;
  const test::SceneFrame scene("builtin:default", width, height, true);
  const auto union_table = std::make_shared<const OffsetTable>(
      read_offset_table(std::string(RSAA_SOURCE_DIR) + "/tables/custom-gl4x-union.json"));
  for (const char* pre_pass : {"jittered", "records", "gl4x", "union"}) {
    RsaaSettings settings;
    settings.material_edges = true;
    settings.prepass = pre_pass;
    if (std::string(pre_pass) == "gl4x") settings.pattern = "gl4x", settings.prepass = "msaa";
    if (std::string(pre_pass) == "union") settings.table = union_table, settings.pattern = "", settings.prepass = "msaa";
    SCOPED_TRACE(pre_pass);
    RsaaPass pass(settings, width, height);
    scene.render_subsamples(pass);
    const std::vector<std::uint8_t> expected = read_back_codes(pass, width, height);
    // A frame drawn shifted first, so that targets a masked clear left alone would show.
    pass.render_subsamples(scene.frame(), [&](unsigned program, glm::vec2 jitter) {
      SceneRenderer::draw_in_current_viewport(scene.gpu, scene.view, jitter + glm::vec2(0.2f, 0.1f), program);
    });
    pass.render_subsamples(scene.frame(), [&](unsigned program, glm::vec2 jitter) {
      SceneRenderer::draw_in_current_viewport(scene.gpu, scene.view, jitter, program);
      glEnable(GL_SCISSOR_TEST);
      glScissor(0, 0, 1, 1);
      glDepthMask(GL_FALSE);
      glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    });
    glDisable(GL_SCISSOR_TEST);
    glDepthMask(GL_TRUE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    const std::vector<std::uint8_t> codes = read_back_codes(pass, width, height);
    std::size_t differing = 0;
    for (std::size_t i = 0; i < codes.size(); ++i) differing += codes[i] != expected[i];
    EXPECT_EQ(differing, 0u) << "of " << codes.size() << " codes";
  }
  gl::check("callbacks leaving state");
}

}  // namespace
}  // namespace rsaa
