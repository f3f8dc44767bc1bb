// dyncov: Bertolami's dynamic coverage (seed 002) on the shared fragment lists: 16 coverage
// samples (the d3d16x positions) from the half-plane LUT, two slots per pixel. `rules` picks the
// seed's literal update and resolve (evict the farther) or the surface rules, which are DCAA's
// resolve program with 2 surfaces and dynamic_coverage_surface_settings(). Both rule sets, and
// the choices for the cases the seed leaves open, are in core/reference/dynamic_coverage.h (the oracle).
#include "runtime/coverage_lists.h"
#include "runtime/techniques/techniques.h"

namespace rsaa {

std::unique_ptr<Technique> make_dynamic_coverage(DynamicCoverageRules rules, bool z_prepass, int width, int height) {
  if (rules == DynamicCoverageRules::Seed)
    return std::make_unique<CoverageListTechnique>(dynamic_coverage_pattern(), "COVERAGE_DYNCOV_SEED", width, height,
                                                   z_prepass);
  const DcaaSettings settings = dynamic_coverage_surface_settings();
  auto t = std::make_unique<CoverageListTechnique>(
      dynamic_coverage_pattern(), "COVERAGE_DCAA\n#define DCAA_MAX_SURFACES " + std::to_string(settings.max_surfaces),
      width, height, z_prepass);
  for (GLuint p : t->resolve_programs()) configure_surface_resolve(p, dynamic_coverage_pattern(), settings);
  return t;
}

TechniqueKind dyncov_technique() {
  return {"dyncov", "dynamic coverage: 16 coverage samples, two surface slots per pixel",
          [](const TechniqueOptions& o) {
            if (o.samples != 0 && o.samples != 16) throw std::invalid_argument("dyncov always uses 16 coverage samples");
            dynamic_coverage_rules(o.rules);
            if (o.shade != "fragment" && o.shade != TechniqueOptions{}.shade)
              throw std::invalid_argument("dyncov shades each fragment: --shade " + o.shade + " is for dcaa");
          },
          [](const TechniqueOptions& o) { return coverage_technique_label(o); },
          [](const TechniqueOptions& o, int width, int height) {
            return make_dynamic_coverage(dynamic_coverage_rules(o.rules), o.z_prepass, width, height);
          }};
}

}  // namespace rsaa
