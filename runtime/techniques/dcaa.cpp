// dcaa: Decoupled Coverage Anti-Aliasing (seed 000) on the shared fragment lists: 64 coverage
// samples from the half-plane LUT, at most 4 surfaces per pixel merged by the paper's rules, per
// sample depth resolve. The rules are those of core/dcaa.h (the tests' oracle).
#include "core/dcaa.h"
#include "runtime/coverage_lists.h"
#include "runtime/techniques/techniques.h"

namespace rsaa {

std::unique_ptr<Technique> make_dcaa(int width, int height) {
  auto t = std::make_unique<CoverageListTechnique>(dcaa_coverage_pattern(), "COVERAGE_DCAA", width, height);
  const GLuint p = t->resolve_program();
  const SamplePattern& pattern = t->coverage_lists()->lut().pattern();
  std::vector<float> samples;
  for (const Vec2& s : pattern.positions) samples.insert(samples.end(), {float(s.x), float(s.y)});
  glProgramUniform2fv(p, glGetUniformLocation(p, "u_coverage_samples"), GLsizei(pattern.size()), samples.data());
  glProgramUniform1i(p, glGetUniformLocation(p, "u_coverage_sample_count"), pattern.size());
  glProgramUniform1f(p, glGetUniformLocation(p, "u_cos_normal_threshold"), DcaaSettings{}.cos_normal_threshold);
  return t;
}

}  // namespace rsaa
