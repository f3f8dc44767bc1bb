// msaa --samples 4: hardware multisampling (llvmpipe allows at most 4), resolved by a blit
// (box filter of linear RGBA16F samples).
#include "runtime/techniques/techniques.h"

namespace rsaa {
namespace {

class HardwareMsaa : public Technique {
 public:
  HardwareMsaa(int samples, int width, int height)
      : samples_(samples),
        colour_(gl::make_texture_2d_multisample(GL_RGBA16F, width, height, samples)),
        depth_(gl::make_texture_2d_multisample(GL_DEPTH_COMPONENT32F, width, height, samples)),
        target_(gl::make_framebuffer({{colour_.get()}}, {depth_.get()})) {}

  void render(const GpuScene& scene, const View& view, GLuint output) override {
    timer_.begin("main");
    clear_to_background(target_.get(), scene);
    glBindFramebuffer(GL_FRAMEBUFFER, target_.get());
    glEnable(GL_MULTISAMPLE);
    SceneRenderer::draw(scene, view, {0.0f, 0.0f}, renderer_.shade_program());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    timer_.end();
    timer_.begin("resolve");
    glBlitNamedFramebuffer(target_.get(), resolved_.get({{output}}), 0, 0, view.width, view.height, 0, 0,
                           view.width, view.height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    timer_.end();
    gl::check("MSAA resolve");
  }

  double bytes_per_pixel() const override { return samples_ * (8 + 4) + 8; }

 private:
  int samples_;
  SceneRenderer renderer_;
  gl::Texture colour_, depth_;
  gl::Framebuffer target_;
  gl::CachedFramebuffer resolved_;
};

}  // namespace

std::unique_ptr<Technique> make_hardware_msaa(int samples, int width, int height) {
  return std::make_unique<HardwareMsaa>(samples, width, height);
}

TechniqueKind msaa_technique() {
  return {"msaa", "hardware 4x MSAA, resolved by the driver",
          [](const TechniqueOptions& o) {
            // llvmpipe's only multisample count is 4; a jittered 8-sample baseline shades every
            // sample, which is supersampling, so it is named ssaa --samples 8.
            const int n = samples_or(o, 4);
            if (n == 8)
              throw std::invalid_argument("msaa --samples 8: the driver has no 8x MSAA; its jittered stand-in "
                                          "shades every sample: use ssaa --samples 8");
            if (n != 4) throw std::invalid_argument("msaa --samples must be 4, not " + std::to_string(n));
          },
          [](const TechniqueOptions& o) { return "msaa " + std::to_string(samples_or(o, 4)) + "x"; },
          [](const TechniqueOptions&, int width, int height) { return make_hardware_msaa(4, width, height); }};
}

}  // namespace rsaa
