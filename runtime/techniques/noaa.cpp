// noaa: one shaded sample at each pixel centre (the 1x frame RSAA and FXAA start from).
#include "runtime/techniques/techniques.h"

namespace rsaa {
namespace {

class NoAA : public Technique {
 public:
  NoAA(int width, int height) : depth_(gl::make_texture_2d(GL_DEPTH_COMPONENT32F, width, height)) {}

  void render(const GpuScene& scene, const View& view, GLuint output) override {
    const GLuint fb = target_.get({{output}}, {depth_.get()});
    timer_.begin("main");
    clear_to_background(fb, scene);
    glBindFramebuffer(GL_FRAMEBUFFER, fb);
    // RSAA's G-buffer program (its normal and primitive outputs are dropped: nothing attached):
    // a post-process that changes nothing gives this image bit for bit.
    SceneRenderer::draw(scene, view, {0.0f, 0.0f}, renderer_.gbuffer_program());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    timer_.end();
  }

  double bytes_per_pixel() const override { return 8 + 4; }  // RGBA16F colour + depth

 private:
  SceneRenderer renderer_;
  gl::Texture depth_;
  gl::CachedFramebuffer target_;
};

}  // namespace

std::unique_ptr<Technique> make_noaa(int width, int height) {
  return std::make_unique<NoAA>(width, height);
}

TechniqueKind noaa_technique() {
  return {"noaa", "no anti-aliasing: the 1x frame",
          [](const TechniqueOptions& o) { reject_samples(o); },
          [](const TechniqueOptions&) { return std::string("noaa"); },
          [](const TechniqueOptions&, int width, int height) { return make_noaa(width, height); }};
}

}  // namespace rsaa
