// The drop-in pass's contract with an engine (runtime/rsaa_pass.h): a missing or wrong frame
// texture is an error naming the field, a callback that draws with another program is an
// error, and the engine's GL state is as it was after both calls.
#include <gtest/gtest.h>

#include "runtime/gl_context.h"
#include "tests/gl_test.h"
#include "runtime/render.h"
#include "runtime/rsaa_pass.h"
#include "runtime/scene.h"
#include "runtime/scene_renderer.h"

namespace rsaa {
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

void run_pre_pass(RsaaPass& pass, const RsaaFrame& frame, const GpuScene& gpu, const View& view) {
  pass.render_subsamples(frame, [&](GLuint program, glm::vec2 jitter) {
    SceneRenderer::draw(gpu, view, jitter, program);
  });
}

TEST_F(RsaaPassApi, TheEngineGlStateIsRestored) {
  const Scene scene = load_scene("builtin:default");
  const GpuScene gpu(scene);
  const View view = make_view(choose_camera(scene, std::nullopt), kWidth, kHeight);
  SceneRenderer renderer;
  const RsaaTargets targets(kWidth, kHeight);
  renderer.draw_gbuffer(gpu, view, targets);

  // An engine's state, all of it different from what the pass draws with.
  const gl::Texture engine_texture = gl::make_texture_2d(GL_RGBA8, 4, 4);
  const gl::Framebuffer engine_framebuffer = gl::make_framebuffer({{engine_texture.get()}});
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

  RsaaPass pass(RsaaSettings{}, kWidth, kHeight);
  const RsaaFrame frame = targets.frame(view.inverse_projection());
  run_pre_pass(pass, frame, gpu, view);
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
  EXPECT_EQ(GLuint(program), renderer.shade_program());
  EXPECT_TRUE(glIsEnabled(GL_BLEND));
  EXPECT_TRUE(glIsEnabled(GL_SCISSOR_TEST));
  EXPECT_FALSE(glIsEnabled(GL_DEPTH_TEST));
  EXPECT_EQ(depth_mask, GL_FALSE);
  EXPECT_EQ(depth_func, GL_GREATER);
  EXPECT_EQ(GLuint(texture), engine_texture.get());

  // The engine's scissor and masks did not reach the pass: the same frame without them gives
  // the same image.
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_BLEND);
  glDepthMask(GL_TRUE);
  const gl::Texture clean_output = gl::make_texture_2d(GL_RGBA16F, kWidth, kHeight);
  run_pre_pass(pass, frame, gpu, view);
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
  gl::check("state test");
}

}  // namespace
}  // namespace rsaa
