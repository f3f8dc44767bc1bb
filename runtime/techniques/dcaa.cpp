// dcaa: Decoupled Coverage Anti-Aliasing (seed 000) on the shared fragment lists: 64 coverage
// samples from the half-plane LUT, at most 4 surfaces per pixel merged by the paper's rules, per
// sample depth resolve. The rules are those of core/dcaa.h (the tests' oracle).
#include "core/dcaa.h"
#include "runtime/coverage_lists.h"
#include "runtime/techniques/techniques.h"

namespace rsaa {
namespace {

class Dcaa : public Technique {
 public:
  Dcaa(int width, int height)
      : lists_(dcaa_coverage_pattern(), width, height),
        resolve_(make_fullscreen_program("coverage_resolve.frag", "#define COVERAGE_DCAA\n")) {
    const GLuint p = resolve_.get();
    std::vector<float> samples;
    for (const Vec2& s : lists_.lut().pattern().positions) samples.insert(samples.end(), {float(s.x), float(s.y)});
    glProgramUniform2fv(p, glGetUniformLocation(p, "u_coverage_samples"), GLsizei(samples.size() / 2), samples.data());
    glProgramUniform1i(p, glGetUniformLocation(p, "u_coverage_sample_count"), lists_.lut().pattern().size());
    glProgramUniform1f(p, glGetUniformLocation(p, "u_cos_normal_threshold"), DcaaSettings{}.cos_normal_threshold);
  }

  void render(const GpuScene& scene, const View& view, GLuint output) override {
    timer_.begin("main");
    lists_.build(scene, view);
    timer_.end();
    timer_.begin("resolve");
    resolve_coverage_lists(lists_, resolve_.get(), scene, view, output_target_.get({{output}}));
    timer_.end();
  }

  double bytes_per_pixel() const override { return lists_.bytes_per_pixel(); }
  CoverageFragmentLists* coverage_lists() override { return &lists_; }

 private:
  CoverageFragmentLists lists_;
  gl::Program resolve_;
  gl::CachedFramebuffer output_target_;
};

}  // namespace

std::unique_ptr<Technique> make_dcaa(int width, int height) { return std::make_unique<Dcaa>(width, height); }

}  // namespace rsaa
