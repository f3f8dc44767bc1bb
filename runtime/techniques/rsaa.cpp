// rsaa: the 1x frame with its G-buffer, the RsaaPass pre-pass, and the post-process.
#include "runtime/rsaa_pass.h"
#include "runtime/techniques/techniques.h"

namespace rsaa {
namespace {

class Rsaa : public Technique {
 public:
  Rsaa(const RsaaSettings& settings, int width, int height)
      : pass_(settings, width, height),
        colour_(gl::make_texture_2d(GL_RGBA16F, width, height, GL_LINEAR)),
        normal_(gl::make_texture_2d(GL_RG16UI, width, height)),
        primitive_(gl::make_texture_2d(GL_R32UI, width, height)),
        depth_(gl::make_texture_2d(GL_DEPTH_COMPONENT32F, width, height)),
        gbuffer_(gl::make_framebuffer({{colour_.get()}, {normal_.get()}, {primitive_.get()}},
                                      {depth_.get()})) {}

  void render(const GpuScene& scene, const View& view, GLuint output) override {
    timer_.begin("main");
    clear_to_background(gbuffer_.get(), scene);
    const GLuint zero[4] = {0, 0, 0, 0};
    glClearNamedFramebufferuiv(gbuffer_.get(), GL_COLOR, 1, zero);
    glClearNamedFramebufferuiv(gbuffer_.get(), GL_COLOR, 2, zero);
    glBindFramebuffer(GL_FRAMEBUFFER, gbuffer_.get());
    SceneRenderer::draw(scene, view, {0.0f, 0.0f}, renderer_.gbuffer_program());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    timer_.end();

    const RsaaFrame frame{colour_.get(), normal_.get(), primitive_.get(), depth_.get(),
                          view.width,    view.height,   view.inverse_projection()};
    timer_.begin("pre-pass");
    pass_.render_subsamples(frame, [&](GLuint program, glm::vec2 jitter) {
      SceneRenderer::draw(scene, view, jitter, program);
    });
    timer_.end();
    timer_.begin("post-process");
    pass_.resolve(frame, output, mask_output_);
    timer_.end();
  }

  double bytes_per_pixel() const override {
    // colour RGBA16F + normal 2x16 + primitive id + depth + the similarity codes.
    return 8 + 4 + 4 + 4 + pass_.code_bytes_per_pixel();
  }

  void set_mask_output(GLuint texture) { mask_output_ = texture; }

 private:
  RsaaPass pass_;
  SceneRenderer renderer_;
  gl::Texture colour_, normal_, primitive_, depth_;
  gl::Framebuffer gbuffer_;
  GLuint mask_output_ = 0;
};

}  // namespace

std::unique_ptr<Technique> make_rsaa(const RsaaSettings& settings, int width, int height,
                                     GLuint mask_output) {
  auto t = std::make_unique<Rsaa>(settings, width, height);
  t->set_mask_output(mask_output);
  return t;
}

}  // namespace rsaa
