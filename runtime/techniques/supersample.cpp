// Jittered supersampling: one single-sample pass per sample position, averaged in linear light
// in an RGBA32F accumulator. Serves `msaa --samples 8` (the d3d8x positions; every sample is
// shaded, so it bounds what 8x MSAA can reach) and `ssaa --samples 16|64` (stratified jitter:
// one uniformly placed sample per cell of a 4x4 / 8x8 grid; 64x is every metric's reference).
#include <cmath>

#include "core/random.h"
#include "runtime/camera.h"
#include "runtime/techniques/techniques.h"

namespace rsaa {
namespace {

class JitteredSupersampling : public Technique {
 public:
  JitteredSupersampling(std::vector<Vec2> positions, int width, int height)
      : positions_(std::move(positions)),
        pass_colour_(gl::make_texture_2d(GL_RGBA16F, width, height)),
        pass_depth_(gl::make_texture_2d(GL_DEPTH_COMPONENT32F, width, height)),
        accumulator_(gl::make_texture_2d(GL_RGBA32F, width, height)),
        pass_target_(gl::make_framebuffer({{pass_colour_.get()}}, {pass_depth_.get()})),
        accumulator_target_(gl::make_framebuffer({{accumulator_.get()}})),
        accumulate_(make_fullscreen_program("accumulate.frag", "")) {}

  void render(const GpuScene& scene, const View& view, GLuint output) override {
    const GLfloat zero[4] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(accumulator_target_.get(), GL_COLOR, 0, zero);
    const GLuint program = accumulate_.get();
    glProgramUniform1i(program, glGetUniformLocation(program, "u_pass"), 0);
    for (const Vec2& s : positions_) {
      timer_.begin("main");
      clear_to_background(pass_target_.get(), scene);
      glBindFramebuffer(GL_FRAMEBUFFER, pass_target_.get());
      SceneRenderer::draw(scene, view, jitter_ndc_for_sample(s.x, s.y, view.width, view.height),
                          renderer_.shade_program());
      timer_.end();
      timer_.begin("resolve");
      glBindFramebuffer(GL_FRAMEBUFFER, accumulator_target_.get());
      glEnable(GL_BLEND);
      glBlendFunc(GL_ONE, GL_ONE);
      glProgramUniform1f(program, glGetUniformLocation(program, "u_weight"), 1.0f / positions_.size());
      glBindTextureUnit(0, pass_colour_.get());
      glUseProgram(program);
      draw_fullscreen_triangle();
      glDisable(GL_BLEND);
      timer_.end();
    }
    // Copy the accumulated average into the RGBA16F output.
    const gl::Framebuffer out = gl::make_framebuffer({{output}});
    glBindFramebuffer(GL_FRAMEBUFFER, out.get());
    glProgramUniform1f(program, glGetUniformLocation(program, "u_weight"), 1.0f);
    glBindTextureUnit(0, accumulator_.get());
    draw_fullscreen_triangle();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    gl::check("jittered supersampling");
  }

  double bytes_per_pixel() const override { return 8 + 4 + 16 + 8; }

 private:
  std::vector<Vec2> positions_;
  SceneRenderer renderer_;
  gl::Texture pass_colour_, pass_depth_, accumulator_;
  gl::Framebuffer pass_target_, accumulator_target_;
  gl::Program accumulate_;
};

}  // namespace

std::vector<Vec2> stratified_positions(int per_side, std::uint64_t seed) {
  std::vector<Vec2> out;
  for (int j = 0; j < per_side; ++j)
    for (int i = 0; i < per_side; ++i) {
      CaseRandom random(seed, std::uint64_t(j * per_side + i));
      const double u = random.uniform(), v = random.uniform();
      out.push_back({(i + u) / per_side - 0.5, (j + v) / per_side - 0.5});
    }
  return out;
}

std::unique_ptr<Technique> make_jittered_supersampling(std::vector<Vec2> positions, int width, int height) {
  return std::make_unique<JitteredSupersampling>(std::move(positions), width, height);
}

}  // namespace rsaa
