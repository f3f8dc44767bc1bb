// Jittered supersampling: one single-sample pass per sample position, averaged in linear light
// in an RGBA32F accumulator. Serves `ssaa --samples 8` (the d3d8x positions; every sample is
// shaded, so it bounds what 8x MSAA can reach: llvmpipe has no 8x MSAA, and calling this
// "msaa 8x" compared the papers against a stronger baseline than theirs) and `ssaa --samples 16|64` (stratified jitter:
// one uniformly placed sample per cell of a 4x4 / 8x8 grid; 64x is every metric's reference).
#include <algorithm>
#include <cmath>

#include "core/util/random.h"
#include "runtime/camera.h"
#include "runtime/techniques/techniques.h"

namespace rsaa {
namespace {

class JitteredSupersampling : public Technique {
 public:
  static constexpr int kBatch = 8;  // passes rendered before each accumulation

  JitteredSupersampling(std::vector<Vec2> positions, int width, int height)
      : positions_(std::move(positions)),
        batch_(int(std::min<std::size_t>(kBatch, positions_.size()))),
        pass_colours_(gl::make_texture_2d_array(GL_RGBA16F, width, height, batch_)),
        pass_depth_(gl::make_texture_2d(GL_DEPTH_COMPONENT32F, width, height)),
        accumulator_(gl::make_texture_2d(GL_RGBA32F, width, height)),
        accumulator_target_(gl::make_framebuffer({{accumulator_.get()}})),
        accumulate_(make_fullscreen_program("accumulate.frag", "")) {
    for (int i = 0; i < batch_; ++i)
      pass_targets_.push_back(gl::make_framebuffer({{pass_colours_.get(), i}}, {pass_depth_.get()}));
  }

  void render(const GpuScene& scene, const View& view, GLuint output) override {
    const GLfloat zero[4] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(accumulator_target_.get(), GL_COLOR, 0, zero);
    const GLuint program = accumulate_.get();
    glProgramUniform1i(program, glGetUniformLocation(program, "u_passes"), 0);
    for (std::size_t first = 0; first < positions_.size(); first += batch_) {
      const int count = int(std::min<std::size_t>(batch_, positions_.size() - first));
      timer_.begin("main");
      for (int i = 0; i < count; ++i) {
        const Vec2 s = positions_[first + i];
        clear_to_background(pass_targets_[i].get(), scene);
        glBindFramebuffer(GL_FRAMEBUFFER, pass_targets_[i].get());
        SceneRenderer::draw(scene, view, jitter_ndc_for_sample(s.x, s.y, view.width, view.height),
                            renderer_.shade_program());
      }
      timer_.end();
      timer_.begin("resolve");
      accumulate(accumulator_target_.get(), pass_colours_.get(), count, 1.0f / positions_.size(), true);
      timer_.end();
    }
    // The accumulated average into the RGBA16F output (a batch of one layer, weight 1).
    timer_.begin("resolve");
    accumulate(output_target_.get({{output}}), accumulator_as_array(), 1, 1.0f, false);
    timer_.end();
    gl::check("jittered supersampling");
  }

  double bytes_per_pixel() const override { return batch_ * 8 + 4 + 16 + 8; }

 private:
  void accumulate(GLuint framebuffer, GLuint layers, int count, float weight, bool blend) {
    const GLuint program = accumulate_.get();
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    if (blend) {
      glEnable(GL_BLEND);
      glBlendFunc(GL_ONE, GL_ONE);
    }
    glProgramUniform1i(program, glGetUniformLocation(program, "u_count"), count);
    glProgramUniform1f(program, glGetUniformLocation(program, "u_weight"), weight);
    glBindTextureUnit(0, layers);
    glUseProgram(program);
    draw_fullscreen_triangle();
    glDisable(GL_BLEND);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }

  // The accumulator seen as a one-layer array texture, for the final copy.
  GLuint accumulator_as_array() {
    if (!accumulator_view_.get()) {
      GLuint id;
      glGenTextures(1, &id);
      glTextureView(id, GL_TEXTURE_2D_ARRAY, accumulator_.get(), GL_RGBA32F, 0, 1, 0, 1);
      accumulator_view_ = gl::Texture(id);
    }
    return accumulator_view_.get();
  }

  std::vector<Vec2> positions_;
  int batch_;
  SceneRenderer renderer_;
  gl::Texture pass_colours_, pass_depth_, accumulator_, accumulator_view_;
  std::vector<gl::Framebuffer> pass_targets_;
  gl::Framebuffer accumulator_target_;
  gl::Program accumulate_;
  gl::CachedFramebuffer output_target_;
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

TechniqueKind ssaa_technique() {
  return {"ssaa", "jittered supersampling: 8 (d3d8x), 16 or 64 (the reference) shaded samples per pixel",
          [](const TechniqueOptions& o) {
            const int n = samples_or(o, 64);
            if (n != 8 && n != 16 && n != 64)
              throw std::invalid_argument("ssaa --samples must be 8, 16 or 64, not " + std::to_string(n));
          },
          [](const TechniqueOptions& o) { return "ssaa " + std::to_string(samples_or(o, 64)) + "x"; },
          [](const TechniqueOptions& o, int width, int height) {
            const int n = samples_or(o, 64);
            if (n == 8) return make_jittered_supersampling(builtin_pattern("d3d8x").positions, width, height);
            return make_jittered_supersampling(stratified_positions(n == 64 ? 8 : 4, 64), width, height);
          }};
}

}  // namespace rsaa
