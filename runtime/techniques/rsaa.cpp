// rsaa: the 1x frame with its G-buffer, the RsaaPass pre-pass, and the post-process.
#include "runtime/rsaa_pass.h"
#include "runtime/techniques/techniques.h"

namespace rsaa {
namespace {

class Rsaa : public Technique {
 public:
  Rsaa(const RsaaSettings& settings, int width, int height)
      : pass_(settings, width, height), targets_(width, height) {}

  void render(const GpuScene& scene, const View& view, GLuint output) override {
    timer_.begin("main");
    renderer_.draw_gbuffer(scene, view, targets_);
    timer_.end();

    const RsaaFrame frame = targets_.frame(view.inverse_projection());
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
    return RsaaTargets::kBytesPerPixel + pass_.code_bytes_per_pixel();
  }

  void set_mask_output(GLuint texture) { mask_output_ = texture; }

 private:
  RsaaPass pass_;
  SceneRenderer renderer_;
  RsaaTargets targets_;
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
