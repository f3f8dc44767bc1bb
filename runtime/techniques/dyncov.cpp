// dyncov: Bertolami's dynamic coverage (seed 002) on the shared fragment lists: 16 coverage
// samples (the d3d16x positions) from the half-plane LUT, two colour/depth/mask slots per pixel,
// evict-the-farther update, coverage-weighted resolve. The rules and the choices for the cases
// the seed leaves open are those of core/dynamic_coverage.h (the tests' oracle).
#include "runtime/coverage_lists.h"
#include "runtime/techniques/techniques.h"

namespace rsaa {

std::unique_ptr<Technique> make_dynamic_coverage(int width, int height) {
  return std::make_unique<CoverageListTechnique>(builtin_pattern("d3d16x"), "COVERAGE_DYNCOV", width, height);
}

}  // namespace rsaa
