// dcaa [--rules surface|paper] [--shade fragment|surface]: Decoupled Coverage Anti-Aliasing
// (seed 000) on the shared fragment lists: 64 coverage samples from the half-plane LUT, at most 4
// surfaces per pixel merged by Algorithm 1 (paper) or with the surface rules, per sample depth
// resolve; colours shaded per fragment and merged, or each surface shaded once. The rules
// are those of core/reference/dcaa.h (the tests' oracle).
#include "core/reference/dcaa.h"
#include "runtime/coverage_lists.h"
#include "runtime/techniques/techniques.h"

namespace rsaa {

void configure_surface_resolve(GLuint p, const SamplePattern& pattern, const DcaaSettings& settings) {
  std::vector<float> samples;
  for (const Vec2& s : pattern.positions) samples.insert(samples.end(), {float(s.x), float(s.y)});
  glProgramUniform2fv(p, glGetUniformLocation(p, "u_coverage_samples"), GLsizei(pattern.size()), samples.data());
  glProgramUniform1i(p, glGetUniformLocation(p, "u_coverage_sample_count"), pattern.size());
  glProgramUniform1f(p, glGetUniformLocation(p, "u_cos_normal_threshold"), settings.cos_normal_threshold);
  glProgramUniform1i(p, glGetUniformLocation(p, "u_per_sample_visibility"), settings.per_sample_visibility);
  glProgramUniform1i(p, glGetUniformLocation(p, "u_merge_hidden"), settings.merge_hidden);
  glProgramUniform1i(p, glGetUniformLocation(p, "u_merge_disjoint_only"), settings.merge_disjoint_only);
  glProgramUniform1i(p, glGetUniformLocation(p, "u_second_merge_into_all"), settings.second_merge_into_all);
  glProgramUniform1i(p, glGetUniformLocation(p, "u_second_merge_by_visible"), settings.second_merge_by_visible);
  glProgramUniform1f(p, glGetUniformLocation(p, "u_merge_colour_tolerance"), settings.merge_colour_tolerance);
  glProgramUniform1i(p, glGetUniformLocation(p, "u_second_merge_least_change"), settings.second_merge_least_change);
}

bool dcaa_shade_surfaces(const std::string& shade) {
  if (shade != "fragment" && shade != "surface")
    throw std::invalid_argument("dcaa --shade must be fragment or surface, not '" + shade + "'");
  return shade == "surface";
}

std::unique_ptr<Technique> make_dcaa(const DcaaSettings& settings, bool z_prepass, bool shade_surfaces, int width,
                                     int height) {
  auto t = std::make_unique<CoverageListTechnique>(dcaa_coverage_pattern(), "COVERAGE_DCAA", width, height, z_prepass,
                                                   shade_surfaces);
  for (GLuint p : t->resolve_programs()) configure_surface_resolve(p, t->coverage_lists()->lut().pattern(), settings);
  return t;
}

TechniqueKind dcaa_technique() {
  return {"dcaa", "Decoupled Coverage Anti-Aliasing: 64 coverage samples, up to 4 surfaces per pixel",
          [](const TechniqueOptions& o) {
            if (o.samples != 0 && o.samples != 64) throw std::invalid_argument("dcaa always uses 64 coverage samples");
            dcaa_settings(o.rules);
            dcaa_shade_surfaces(o.shade);
          },
          [](const TechniqueOptions& o) { return coverage_technique_label(o); },
          [](const TechniqueOptions& o, int width, int height) {
            return make_dcaa(dcaa_settings(o.rules), o.z_prepass, dcaa_shade_surfaces(o.shade), width, height);
          }};
}

}  // namespace rsaa
