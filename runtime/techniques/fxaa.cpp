// fxaa: the 1x frame, then the FXAA-style post-process (shaders/fxaa.frag): the single-sample
// post-process baseline beside RSAA.
#include "runtime/techniques/techniques.h"

namespace rsaa {
namespace {

class Fxaa : public Technique {
 public:
  Fxaa(int width, int height)
      : colour_(gl::make_texture_2d(GL_RGBA16F, width, height, GL_LINEAR)),
        depth_(gl::make_texture_2d(GL_DEPTH_COMPONENT32F, width, height)),
        frame_(gl::make_framebuffer({{colour_.get()}}, {depth_.get()})),
        post_(make_fullscreen_program("fxaa.frag", "")) {}

  void render(const GpuScene& scene, const View& view, GLuint output) override {
    timer_.begin("main");
    clear_to_background(frame_.get(), scene);
    glBindFramebuffer(GL_FRAMEBUFFER, frame_.get());
    SceneRenderer::draw(scene, view, {0.0f, 0.0f}, renderer_.shade_program());
    timer_.end();
    timer_.begin("post-process");
    const GLuint program = post_.get();
    glBindFramebuffer(GL_FRAMEBUFFER, output_target_.get({{output}}));
    glProgramUniform1i(program, glGetUniformLocation(program, "u_colour"), 0);
    glProgramUniform2f(program, glGetUniformLocation(program, "u_viewport"), float(view.width),
                       float(view.height));
    glBindTextureUnit(0, colour_.get());
    glUseProgram(program);
    draw_fullscreen_triangle();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    timer_.end();
    gl::check("FXAA");
  }

  double bytes_per_pixel() const override { return 8 + 4 + 8; }  // colour, depth, output

 private:
  SceneRenderer renderer_;
  gl::Texture colour_, depth_;
  gl::Framebuffer frame_;
  gl::Program post_;
  gl::CachedFramebuffer output_target_;
};

}  // namespace

std::unique_ptr<Technique> make_fxaa(int width, int height) { return std::make_unique<Fxaa>(width, height); }

TechniqueKind fxaa_technique() {
  return {"fxaa", "an FXAA-style post-process of the 1x frame",
          [](const TechniqueOptions& o) { reject_samples(o); },
          [](const TechniqueOptions&) { return std::string("fxaa"); },
          [](const TechniqueOptions&, int width, int height) { return make_fxaa(width, height); }};
}

}  // namespace rsaa
