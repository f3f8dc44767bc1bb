// An engine misusing the drop-in pass (runtime/rsaa_pass.h) gets a clear exception naming what,
// never wrong codes drawn silently, and its GL state back: callbacks that draw elsewhere or rebind
// the pass's units, a program built from another pass's text, a frame whose inverse projection
// is no projection's, an in-memory table with impossible positions, swizzled frame textures, a
// moved-from object. Found by an adversarial review of the API.
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <climits>

#include <epoxy/egl.h>
#include <gtest/gtest.h>

#include "core/rsaa/offset_table.h"
#include "runtime/gl_context.h"
#include "runtime/gl_objects.h"
#include "runtime/render.h"
#include "runtime/rsaa_pass.h"
#include "runtime/scene_renderer.h"
#include "runtime/shader_library.h"
#include "tests/gl_test.h"

namespace rsaa {
namespace {

constexpr int kWidth = 64, kHeight = 48;

class RsaaPassMisuse : public test::GlTest {};

using Draw = std::function<void(GLuint program, glm::vec2 jitter)>;

// The masks of a pre-pass drawn by `draw` and resolved.
std::vector<std::uint32_t> masks_of(RsaaPass& pass, const RsaaFrame& frame, const Draw& draw) {
  pass.render_subsamples(frame, draw);
  const gl::Texture output = gl::make_texture_2d(GL_RGBA16F, frame.width, frame.height);
  const gl::Texture mask = gl::make_texture_2d(GL_R32UI, frame.width, frame.height);
  pass.resolve(frame, output.get(), mask.get());
  return read_back_uints(mask.get(), frame.width, frame.height);
}

Draw scene_draw(const test::SceneFrame& scene) {
  return [&scene](GLuint program, glm::vec2 jitter) { SceneRenderer::draw(scene.gpu, scene.view, jitter, program); };
}

RsaaSettings with_masks(RsaaSettings settings) {
  settings.output_mask = true;
  return settings;
}

// GL_POLYGON_MODE reports two values (front, back): saved into one integer, the second landed on
// the saved polygon offset flag, which came back on after every call (GL_FILL's low byte).
// Binding the record units with a zero name unbound every target of the unit: an engine's cube
// map or 3D texture there was lost.
TEST_F(RsaaPassMisuse, PolygonOffsetAndEveryTextureTargetComeBack) {
  const test::SceneFrame scene("builtin:default", kWidth, kHeight);
  GLuint cube = 0, volume = 0;
  glCreateTextures(GL_TEXTURE_CUBE_MAP, 1, &cube);
  glTextureStorage2D(cube, 1, GL_RGBA8, 4, 4);
  glCreateTextures(GL_TEXTURE_3D, 1, &volume);
  glTextureStorage3D(volume, 1, GL_RGBA8, 4, 4, 4);
  RsaaSettings multisample, records;
  multisample.pattern = "gl4x", multisample.prepass = "msaa";
  records.prepass = "records";
  for (const RsaaSettings& settings : {RsaaSettings{}, multisample, records}) {
    SCOPED_TRACE("prepass " + settings.prepass);
    RsaaPass pass(settings, kWidth, kHeight);
    const gl::Texture output = gl::make_texture_2d(GL_RGBA16F, kWidth, kHeight);
    for (const GLenum mode : {GLenum(GL_FILL), GLenum(GL_POINT)})
      for (const bool offset : {false, true}) {
        glPolygonMode(GL_FRONT_AND_BACK, mode);
        offset ? glEnable(GL_POLYGON_OFFSET_FILL) : glDisable(GL_POLYGON_OFFSET_FILL);
        for (GLuint unit = 0; unit < 16; ++unit) {
          glActiveTexture(GL_TEXTURE0 + unit);
          glBindTexture(GL_TEXTURE_CUBE_MAP, cube);
          glBindTexture(GL_TEXTURE_3D, volume);
        }
        glActiveTexture(GL_TEXTURE0);
        scene.render_subsamples(pass);
        EXPECT_EQ(bool(glIsEnabled(GL_POLYGON_OFFSET_FILL)), offset) << "after render_subsamples";
        pass.resolve(scene.frame(), output.get());
        EXPECT_EQ(bool(glIsEnabled(GL_POLYGON_OFFSET_FILL)), offset) << "after resolve";
        GLint modes[2] = {};
        glGetIntegerv(GL_POLYGON_MODE, modes);
        EXPECT_EQ(GLenum(modes[0]), mode);
        for (GLuint unit = 0; unit < 16; ++unit) {
          GLint bound_cube = 0, bound_volume = 0;
          glActiveTexture(GL_TEXTURE0 + unit);
          glGetIntegerv(GL_TEXTURE_BINDING_CUBE_MAP, &bound_cube);
          glGetIntegerv(GL_TEXTURE_BINDING_3D, &bound_volume);
          EXPECT_EQ(GLuint(bound_cube), cube) << "cube map, unit " << unit;
          EXPECT_EQ(GLuint(bound_volume), volume) << "3D texture, unit " << unit;
          glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
          glBindTexture(GL_TEXTURE_3D, 0);
        }
        glActiveTexture(GL_TEXTURE0);
      }
  }
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDeleteTextures(1, &cube);
  glDeleteTextures(1, &volume);
  gl::check("state restored");
}

// SavedState itself: whatever a pass binds on a saved unit (glBindTextures with a zero name
// unbinds every target), the engine's textures of every target come back.
TEST_F(RsaaPassMisuse, SavedStateRestoresEveryTextureTargetOfAUnit) {
  GLuint cube = 0, volume = 0;
  glCreateTextures(GL_TEXTURE_CUBE_MAP, 1, &cube);
  glTextureStorage2D(cube, 1, GL_RGBA8, 4, 4);
  glCreateTextures(GL_TEXTURE_3D, 1, &volume);
  glTextureStorage3D(volume, 1, GL_RGBA8, 4, 4, 4);
  constexpr GLuint kUnit = 5;
  glActiveTexture(GL_TEXTURE0 + kUnit);
  glBindTexture(GL_TEXTURE_CUBE_MAP, cube);
  glBindTexture(GL_TEXTURE_3D, volume);
  glActiveTexture(GL_TEXTURE0);
  {
    const gl::SavedState saved({int(kUnit)});
    const GLuint none = 0;
    glBindTextures(kUnit, 1, &none);
  }
  GLint bound_cube = 0, bound_volume = 0;
  glActiveTexture(GL_TEXTURE0 + kUnit);
  glGetIntegerv(GL_TEXTURE_BINDING_CUBE_MAP, &bound_cube);
  glGetIntegerv(GL_TEXTURE_BINDING_3D, &bound_volume);
  glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
  glBindTexture(GL_TEXTURE_3D, 0);
  glActiveTexture(GL_TEXTURE0);
  EXPECT_EQ(GLuint(bound_cube), cube);
  EXPECT_EQ(GLuint(bound_volume), volume);
  glDeleteTextures(1, &cube);
  glDeleteTextures(1, &volume);
  gl::check("saved texture targets");
}

// A draw callback that binds its own framebuffer (an engine helper binding its G-buffer) or sets
// its own viewport (the window's) drew elsewhere, and the codes were another frame's, silently.
TEST_F(RsaaPassMisuse, ACallbackThatDrawsIntoAnotherFramebufferOrViewportIsRefused) {
  const test::SceneFrame scene("builtin:default", kWidth, kHeight);
  const Draw draw = scene_draw(scene);
  const gl::Texture engine_colour = gl::make_texture_2d(GL_RGBA8, kWidth, kHeight);
  const gl::Framebuffer engine_framebuffer = gl::make_framebuffer({{engine_colour.get()}});
  View window = scene.view;
  window.width *= 2, window.height *= 2;
  RsaaSettings multisample;
  multisample.pattern = "gl4x", multisample.prepass = "msaa";
  for (const RsaaSettings& settings : {RsaaSettings{}, multisample}) {
    SCOPED_TRACE("prepass " + settings.prepass);
    RsaaPass pass(with_masks(settings), kWidth, kHeight);
    EXPECT_THROW(masks_of(pass, scene.frame(),
                          [&](GLuint program, glm::vec2 jitter) {
                            glBindFramebuffer(GL_FRAMEBUFFER, engine_framebuffer.get());
                            draw(program, jitter);
                          }),
                 std::logic_error);
    EXPECT_THROW(masks_of(pass, scene.frame(),
                          [&](GLuint program, glm::vec2 jitter) {
                            SceneRenderer::draw(scene.gpu, window, jitter, program);
                          }),
                 std::logic_error);
    // The pass is usable after the refusal, with the masks of a good draw.
    EXPECT_FALSE(masks_of(pass, scene.frame(), draw).empty());
  }
  gl::check("callback framebuffer");
}

// render_subsamples() with the pass's own program checked the program only: a callback binding
// a material texture to a pre-pass unit changed the masks silently (as the own-shaders path,
// which refused it, now both do).
TEST_F(RsaaPassMisuse, APassProgramCallbackThatRebindsAPrePassUnitIsRefused) {
  const test::SceneFrame scene("builtin:default", kWidth, kHeight);
  const Draw draw = scene_draw(scene);
  RsaaPass pass(with_masks(RsaaSettings{}), kWidth, kHeight);
  const gl::Texture albedo = gl::make_texture_2d(GL_RGBA8, 4, 4);
  const int first = RsaaSettings{}.prepass_first_unit;
  for (int unit = first; unit < first + 3; ++unit) {
    SCOPED_TRACE("unit " + std::to_string(unit));
    EXPECT_THROW(masks_of(pass, scene.frame(),
                          [&](GLuint program, glm::vec2 jitter) {
                            glBindTextureUnit(GLuint(unit), albedo.get());
                            draw(program, jitter);
                          }),
                 std::logic_error);
  }
  gl::check("rebound unit");
}

// An engine program built from another pass's prepass_glsl() (other code bits, or a jittered
// pass's text in a pass writing records, as a cached program would be after the settings or the
// driver changed) was accepted and gave wrong masks; the pass's own text is still accepted.
TEST_F(RsaaPassMisuse, AnotherPassesPrePassProgramIsRefused) {
  const test::SceneFrame scene("builtin:default", kWidth, kHeight);
  RsaaSettings bits8, bits32, jittered, records;
  bits32.code_bits = 32;
  jittered.prepass = "jittered", records.prepass = "records";
  const struct {
    const char* name;
    RsaaSettings pass, program;
  } cases[] = {{"8-bit pass, 32-bit program", bits8, bits32},
               {"records pass, jittered program", records, jittered},
               {"jittered pass, records program", jittered, records}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    RsaaPass pass(c.pass, kWidth, kHeight);
    const RsaaPass other(c.program, kWidth, kHeight);
    const gl::Program own = test::engine_prepass_program(pass.prepass_glsl());
    const gl::Program foreign = test::engine_prepass_program(other.prepass_glsl());
    const auto draw_with = [&](GLuint program) {
      pass.render_subsamples_with_own_shaders(scene.frame(), [&] {
        SceneRenderer::draw(scene.gpu, scene.view, glm::vec2(0.0f), program);
      });
    };
    EXPECT_NO_THROW(draw_with(own.get()));
    EXPECT_THROW(draw_with(foreign.get()), std::logic_error);
  }
  // A pass that differs in its post-process alone writes the same codes with the same program:
  // the mask output, authentication 0/1, the split cap, the checks.
  RsaaSettings post_only = RsaaSettings{};
  post_only.output_mask = true, post_only.auth = 0, post_only.split_cap = 0.0f, post_only.fetch_check = "off";
  post_only.split_check = "off", post_only.multi_surface = "fetch";
  RsaaPass pass(post_only, kWidth, kHeight);
  const RsaaPass other(RsaaSettings{}, kWidth, kHeight);
  const gl::Program shared = test::engine_prepass_program(other.prepass_glsl());
  EXPECT_NO_THROW(pass.render_subsamples_with_own_shaders(scene.frame(), [&] {
    SceneRenderer::draw(scene.gpu, scene.view, glm::vec2(0.0f), shared.get());
  }));
  gl::check("foreign program");
}

// A pipeline of separable programs was refused as "program 0 has no RsaaUniforms block".
TEST_F(RsaaPassMisuse, AProgramPipelineIsRefusedNamingPipelines) {
  const test::SceneFrame scene("builtin:default", kWidth, kHeight);
  RsaaPass pass(RsaaSettings{}, kWidth, kHeight);
  GLuint pipeline = 0;
  glCreateProgramPipelines(1, &pipeline);
  std::string error;
  try {
    pass.render_subsamples_with_own_shaders(scene.frame(), [&] {
      glUseProgram(0);
      glBindProgramPipeline(pipeline);
    });
  } catch (const std::logic_error& e) {
    error = e.what();
  }
  glBindProgramPipeline(0);
  EXPECT_NE(error.find("pipeline"), std::string::npos) << error;
  // Not deleted: Mesa's glUseProgram(0) later rebinds its current pipeline by name, and a deleted
  // one left GL_INVALID_OPERATION for the next test.
  gl::check("pipeline");
}

// Every position is rebuilt through the inverse projection: a NaN, infinite or singular matrix
// made every similarity NaN, and the masks wrong, without a word.
TEST_F(RsaaPassMisuse, ANonFiniteOrSingularInverseProjectionIsRefused) {
  const test::SceneFrame scene("builtin:default", kWidth, kHeight);
  const Draw draw = scene_draw(scene);
  RsaaPass pass(with_masks(RsaaSettings{}), kWidth, kHeight);
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  glm::mat4 one_nan = scene.view.inverse_projection(), one_inf = one_nan, no_w = one_nan;
  one_nan[2][2] = nan;
  one_inf[3][3] = inf;
  no_w[2][3] = no_w[3][3] = 0.0f;  // every point at infinity (w = 0), and singular
  const struct {
    const char* name;
    glm::mat4 matrix;
  } cases[] = {{"all NaN", glm::mat4(nan)}, {"one NaN", one_nan}, {"one infinity", one_inf},
               {"zero", glm::mat4(0.0f)}, {"w always 0", no_w}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    RsaaFrame frame = scene.frame();
    frame.inverse_projection = c.matrix;
    EXPECT_THROW(masks_of(pass, frame, draw), std::invalid_argument);
  }
  EXPECT_FALSE(masks_of(pass, scene.frame(), draw).empty());
  gl::check("projections");
}

// A moved-from pass or targets dereferenced no GL objects and crashed.
TEST_F(RsaaPassMisuse, AMovedFromPassOrTargetsIsAnError) {
  RsaaPass pass(RsaaSettings{}, kWidth, kHeight);
  RsaaPass moved_pass = std::move(pass);
  RsaaTargets targets(kWidth, kHeight);
  RsaaTargets moved_targets = std::move(targets);
  const RsaaFrame frame = moved_targets.frame(glm::mat4(1.0f));
  const gl::Texture output = gl::make_texture_2d(GL_RGBA16F, kWidth, kHeight);
  const float background[3] = {0.0f, 0.0f, 0.0f};
  EXPECT_THROW((void)pass.code_textures(), std::logic_error);
  EXPECT_THROW(pass.render_subsamples(frame, [](GLuint, glm::vec2) {}), std::logic_error);
  EXPECT_THROW(pass.render_subsamples_with_own_shaders(frame, [] {}), std::logic_error);
  EXPECT_THROW(pass.resolve(frame, output.get()), std::logic_error);
  EXPECT_THROW((void)targets.frame(glm::mat4(1.0f)), std::logic_error);
  EXPECT_THROW(targets.bind(), std::logic_error);
  EXPECT_THROW(targets.clear(background), std::logic_error);
  EXPECT_THROW((void)targets.colour(), std::logic_error);
  EXPECT_THROW(targets.use_colour(0), std::logic_error);
  EXPECT_EQ(moved_pass.code_textures().size(), 2u);
  gl::check("moved from");
}

// A table built in memory skipped the file reader's checks of its positions: NaN, infinite,
// outside the pixel or coinciding positions were drawn with (a NaN cast to an integer step).
TEST_F(RsaaPassMisuse, AnInMemoryTableWithImpossiblePositionsIsRefused) {
  const OffsetTable d3d4x = gl::builtin_offset_table("d3d4x");
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const struct {
    const char* name;
    Vec2 position;
  } cases[] = {{"NaN", {nan, 0.1}}, {"infinite", {inf, 0.0}}, {"outside the pixel", {3.0, -2.5}},
               {"sample 0's", d3d4x.pattern.positions[0]}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    auto table = std::make_shared<OffsetTable>(d3d4x);
    table->pattern.positions[1] = c.position;
    RsaaSettings settings;
    settings.table = table, settings.pattern = "";
    EXPECT_THROW(RsaaPass(settings, kWidth, kHeight), std::invalid_argument);
  }
  auto valid = std::make_shared<OffsetTable>(d3d4x);
  RsaaSettings settings;
  settings.table = valid, settings.pattern = "";
  EXPECT_NO_THROW(RsaaPass(settings, kWidth, kHeight));
}

// The facet colours' unit on one of the pre-pass's units put a buffer sampler and a 2D sampler on
// one unit: the draw failed without an error on llvmpipe (the jittered pre-pass's masks wrong in
// 28% of the pixels, found by a review). Refused; a facet program drawing a scene uploaded
// without its facet colours is an error too.
TEST_F(RsaaPassMisuse, AFacetColoursUnitOnAPrePassUnitIsRefused) {
  RsaaSettings settings;
  settings.material_edges = true;
  settings.facet_materials = true;
  EXPECT_NO_THROW(RsaaPass(settings, kWidth, kHeight));
  for (int first : {10, 11, 12}) {
    settings.prepass_first_unit = first;
    EXPECT_THROW(RsaaPass(settings, kWidth, kHeight), std::invalid_argument) << first;
  }
  settings.prepass_first_unit = 13;
  settings.facet_colours_unit = -1;
  EXPECT_THROW(RsaaPass(settings, kWidth, kHeight), std::invalid_argument);
  settings.facet_colours_unit = 12;
  settings.prepass = "jittered";
  const test::SceneFrame scene("builtin:default", kWidth, kHeight, true);  // uploaded without facet colours
  RsaaPass pass(settings, kWidth, kHeight);
  EXPECT_THROW(pass.render_subsamples(scene.frame(), scene_draw(scene)), std::logic_error);
}

// Texture reads apply a swizzle and image loads, blits and copies do not: a swizzled colour gave
// an image half swizzled, a swizzled normal other masks.
TEST_F(RsaaPassMisuse, ASwizzledFrameTextureIsRefused) {
  const test::SceneFrame scene("builtin:default", kWidth, kHeight);
  const Draw draw = scene_draw(scene);
  RsaaPass pass(with_masks(RsaaSettings{}), kWidth, kHeight);
  for (const GLuint texture : {scene.frame().colour, scene.frame().centre_normal}) {
    SCOPED_TRACE("texture " + std::to_string(texture));
    glTextureParameteri(texture, GL_TEXTURE_SWIZZLE_R, GL_GREEN);
    glTextureParameteri(texture, GL_TEXTURE_SWIZZLE_G, GL_RED);
    EXPECT_THROW(masks_of(pass, scene.frame(), draw), std::invalid_argument);
    glTextureParameteri(texture, GL_TEXTURE_SWIZZLE_R, GL_RED);
    glTextureParameteri(texture, GL_TEXTURE_SWIZZLE_G, GL_GREEN);
  }
  EXPECT_FALSE(masks_of(pass, scene.frame(), draw).empty());
  gl::check("swizzles");
}


// An engine keeps stencil in its depth buffer, or 24-bit depth: the frame's depth is taken as it
// is (the pass reads depth through its own sampler), with the masks of 32-bit float depth, and a
// depth-stencil texture set to read as stencil is refused.
TEST_F(RsaaPassMisuse, TheEnginesDepthStencilBufferIsTakenAsItIs) {
  const test::SceneFrame scene("builtin:default", kWidth, kHeight);
  RsaaPass pass(with_masks(RsaaSettings{}), kWidth, kHeight);
  const std::vector<std::uint32_t> expected = masks_of(pass, scene.frame(), scene_draw(scene));
  int edges = 0;
  for (const std::uint32_t m : expected) edges += m != 0xffu;
  ASSERT_GT(edges, 100);
  for (const GLenum format : {GLenum(GL_DEPTH32F_STENCIL8), GLenum(GL_DEPTH24_STENCIL8), GLenum(GL_DEPTH_COMPONENT24)}) {
    SCOPED_TRACE("depth format " + std::to_string(format));
    // The scene's G-buffer drawn again with this depth buffer.
    const gl::Texture depth = gl::make_texture_2d(format, kWidth, kHeight);
    RsaaFrame frame = scene.frame();
    const gl::Framebuffer framebuffer =
        gl::make_framebuffer({{frame.colour}, {frame.centre_normal}, {frame.centre_primitive}}, {depth.get()});
    const GLfloat far_depth = 1.0f;
    glClearNamedFramebufferfv(framebuffer.get(), GL_DEPTH, 0, &far_depth);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.get());
    SceneRenderer::draw(scene.gpu, scene.view, glm::vec2(0.0f), scene.renderer.gbuffer_program());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    frame.centre_depth = depth.get();
    const std::vector<std::uint32_t> masks = masks_of(pass, frame, scene_draw(scene));
    int differing = 0;
    for (std::size_t p = 0; p < masks.size(); ++p) differing += masks[p] != expected[p];
    EXPECT_LE(differing, format == GL_DEPTH32F_STENCIL8 ? 0 : edges / 50) << "of " << edges << " edge masks";
    if (format == GL_DEPTH_COMPONENT24) continue;  // no stencil to read instead
    glTextureParameteri(depth.get(), GL_DEPTH_STENCIL_TEXTURE_MODE, GL_STENCIL_INDEX);
    EXPECT_THROW(masks_of(pass, frame, scene_draw(scene)), std::invalid_argument);
  }
  gl::check("depth-stencil frame");
}

// Without a current context every GL call reads zeros: the pass said "this driver takes 1x1 to
// 0x0" or "1 is not a texture". The pass's calls now say that no context is current.
TEST_F(RsaaPassMisuse, NoCurrentContextIsAnErrorSayingSo) {
  const test::SceneFrame scene("builtin:default", kWidth, kHeight);
  RsaaPass pass(RsaaSettings{}, kWidth, kHeight);
  const gl::Texture output = gl::make_texture_2d(GL_RGBA16F, kWidth, kHeight);
  const EGLDisplay display = eglGetCurrentDisplay();
  const EGLContext context = eglGetCurrentContext();
  const EGLSurface draw = eglGetCurrentSurface(EGL_DRAW), read = eglGetCurrentSurface(EGL_READ);
  ASSERT_NE(context, EGL_NO_CONTEXT);
  ASSERT_TRUE(eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
  const auto expect_no_context = [](const std::function<void()>& call, const char* name) {
    try {
      call();
      ADD_FAILURE() << name << " did not throw without a current context";
    } catch (const gl::GlError& e) {
      EXPECT_NE(std::string(e.what()).find("no OpenGL context is current"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  };
  expect_no_context([] { RsaaPass another(RsaaSettings{}, kWidth, kHeight); }, "RsaaPass::RsaaPass");
  expect_no_context([] { RsaaTargets targets(kWidth, kHeight); }, "RsaaTargets::RsaaTargets");
  expect_no_context([&] { pass.render_subsamples(scene.frame(), scene_draw(scene)); }, "RsaaPass::render_subsamples");
  expect_no_context([&] { pass.resolve(scene.frame(), output.get()); }, "RsaaPass::resolve");
  expect_no_context([] { query_gl_sample_pattern(4); }, "query_gl_sample_pattern");
  ASSERT_TRUE(eglMakeCurrent(display, draw, read, context));
  // And the pass works again once it is current.
  EXPECT_GT(masks_of(pass, scene.frame(), scene_draw(scene)).size(), 0u);
  gl::check("context made current again");
}

// A pre-pass unit setting near INT_MAX overflowed the range check (undefined behaviour) and
// reached the shader compiler; shader defines divided by zero cells (SIGFPE).
TEST_F(RsaaPassMisuse, SettingsAtTheirLimitsAreRefusedNamingThem) {
  for (const int unit : {INT_MAX, INT_MAX - 1, INT_MAX - 2, -1}) {
    RsaaSettings settings;
    settings.prepass_first_unit = unit;
    try {
      RsaaPass pass(settings, kWidth, kHeight);
      ADD_FAILURE() << "prepass_first_unit " << unit << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("prepass_first_unit"), std::string::npos) << e.what();
    }
  }
  const RsaaSettings defaults;
  EXPECT_THROW(rsaa_shader_defines(defaults, 8, true, false, {0, 2}), std::invalid_argument);
  EXPECT_THROW(rsaa_shader_defines(defaults, 8, true, false, {2, 0}), std::invalid_argument);
  EXPECT_THROW(rsaa_shader_defines(defaults, 8, true, false, {3, 1}), std::invalid_argument);
  EXPECT_THROW(rsaa_shader_defines(defaults, 8, true, false, {-1, -8}), std::invalid_argument);
  EXPECT_THROW(rsaa_shader_defines(defaults, 7, true, true), std::invalid_argument);
  for (const int samples : {0, -1, 17, INT_MAX}) EXPECT_THROW(rsaa_shader_defines(defaults, samples, false), std::invalid_argument);
  RsaaSettings bits;
  bits.code_bits = 3;
  EXPECT_THROW(rsaa_shader_defines(bits, 8, false), std::invalid_argument);
  EXPECT_NO_THROW(rsaa_shader_defines(defaults, 8, true, false, {1, 2}));
  EXPECT_NO_THROW(rsaa_shader_defines(defaults, 16, true, false, {2, 2}));
  EXPECT_NO_THROW(rsaa_shader_defines(defaults, 8, true, true));
}

}  // namespace
}  // namespace rsaa
