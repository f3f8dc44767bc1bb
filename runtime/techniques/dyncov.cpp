// dyncov: Bertolami's dynamic coverage (seed 002) on the shared fragment lists: 16 coverage
// samples (the d3d16x positions) from the half-plane LUT, two colour/depth/mask slots per pixel,
// evict-the-farther update, coverage-weighted resolve. The rules and the choices for the cases
// the seed leaves open are those of core/dynamic_coverage.h (the tests' oracle).
#include "runtime/coverage_lists.h"
#include "runtime/techniques/techniques.h"

namespace rsaa {
namespace {

class DynamicCoverage : public Technique {
 public:
  DynamicCoverage(int width, int height)
      : lists_(builtin_pattern("d3d16x"), width, height),
        resolve_(make_fullscreen_program("coverage_resolve.frag", "#define COVERAGE_DYNCOV\n")) {}

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

std::unique_ptr<Technique> make_dynamic_coverage(int width, int height) {
  return std::make_unique<DynamicCoverage>(width, height);
}

}  // namespace rsaa
