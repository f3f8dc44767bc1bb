// ssaa-filtered --kernel 1|2|3: the frame rendered at twice the width and height (4 shaded
// samples a pixel), then one downsampling pass with the kernels of core/reference/filtered_downsample.h.
#include "core/rsaa/conventions.h"
#include "core/reference/filtered_downsample.h"
#include "runtime/techniques/techniques.h"

namespace rsaa {
namespace {

class FilteredSsaa : public Technique {
 public:
  FilteredSsaa(int kernel, int width, int height)
      : kernel_(kernel),
        supersampled_(gl::make_texture_2d(GL_RGBA16F, 2 * width, 2 * height, GL_LINEAR)),
        depth_(gl::make_texture_2d(GL_DEPTH_COMPONENT32F, 2 * width, 2 * height)),
        target_(gl::make_framebuffer({{supersampled_.get()}}, {depth_.get()})),
        downsample_(make_fullscreen_program("ssaa_filtered.frag", "")) {
    const GLuint p = downsample_.get();
    const auto set_taps = [&](const char* name, const FilterTaps& taps) {
      std::vector<float> window;
      for (const Vec2& t : taps) {
        const Vec2 w = pixel_to_gl(t);
        window.insert(window.end(), {float(w.x), float(w.y)});
      }
      glProgramUniform2fv(p, glGetUniformLocation(p, name), 5, window.data());
    };
    set_taps("u_small_taps", small_filter_taps());
    set_taps("u_large_taps", large_filter_taps());
    glProgramUniform1i(p, glGetUniformLocation(p, "u_kernel"), kernel);
    glProgramUniform1i(p, glGetUniformLocation(p, "u_supersampled"), 0);
    glProgramUniform2f(p, glGetUniformLocation(p, "u_supersampled_size"), float(2 * width), float(2 * height));
  }

  void render(const GpuScene& scene, const View& view, GLuint output) override {
    timer_.begin("main");
    View supersampled = view;
    supersampled.width *= 2;
    supersampled.height *= 2;
    clear_to_background(target_.get(), scene);
    glBindFramebuffer(GL_FRAMEBUFFER, target_.get());
    SceneRenderer::draw(scene, supersampled, {0.0f, 0.0f}, renderer_.shade_program());
    timer_.end();
    timer_.begin("resolve");
    glBindFramebuffer(GL_FRAMEBUFFER, output_target_.get({{output}}));
    glViewport(0, 0, view.width, view.height);
    glBindTextureUnit(0, supersampled_.get());
    glUseProgram(downsample_.get());
    draw_fullscreen_triangle();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    timer_.end();
    gl::check("filtered SSAA");
  }

  double bytes_per_pixel() const override { return 4 * (8 + 4) + 8; }

  GLuint supersampled() const { return supersampled_.get(); }

 private:
  int kernel_;
  SceneRenderer renderer_;
  gl::Texture supersampled_, depth_;
  gl::Framebuffer target_;
  gl::Program downsample_;
  gl::CachedFramebuffer output_target_;
};

}  // namespace

std::unique_ptr<Technique> make_filtered_ssaa(int kernel, int width, int height) {
  return std::make_unique<FilteredSsaa>(kernel, width, height);
}

TechniqueKind filtered_ssaa_technique() {
  return {"ssaa-filtered", "2x2 supersampling downsampled by kernel 1 (box), 2 (five-tap) or 3 (alpha-driven)",
          [](const TechniqueOptions& o) {
            if (o.samples != 0 && o.samples != 4)
              throw std::invalid_argument("ssaa-filtered always uses 4 samples (2x2)");
            if (o.kernel < 1 || o.kernel > 3) throw std::invalid_argument("ssaa-filtered --kernel must be 1, 2 or 3");
          },
          [](const TechniqueOptions& o) { return "ssaa-filtered k" + std::to_string(o.kernel); },
          [](const TechniqueOptions& o, int width, int height) { return make_filtered_ssaa(o.kernel, width, height); }};
}

}  // namespace rsaa
