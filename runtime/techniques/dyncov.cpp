// dyncov: Bertolami's dynamic coverage (seed 002) on the shared fragment lists: 16 coverage
// samples (the d3d16x positions) from the half-plane LUT, two slots per pixel, coverage-weighted
// resolve. `rules` picks the seed's literal update (evict the farther) or the surface rules
// (merge fragments of one surface); both are defined, with the choices for the cases the seed
// leaves open, in core/dynamic_coverage.h (the tests' oracle).
#include "core/dcaa.h"
#include "runtime/coverage_lists.h"
#include "runtime/techniques/techniques.h"

namespace rsaa {

std::unique_ptr<Technique> make_dynamic_coverage(DynamicCoverageRules rules, int width, int height) {
  const bool seed = rules == DynamicCoverageRules::Seed;
  auto t = std::make_unique<CoverageListTechnique>(builtin_pattern("d3d16x"),
                                                   seed ? "COVERAGE_DYNCOV_SEED" : "COVERAGE_DYNCOV_SURFACE", width, height);
  const GLuint p = t->resolve_program();
  if (!seed) glProgramUniform1f(p, glGetUniformLocation(p, "u_cos_normal_threshold"), DcaaSettings{}.cos_normal_threshold);
  return t;
}

}  // namespace rsaa
