// Inside runtime/techniques/: each file's TechniqueKind (listed by registry.cpp), its
// constructor, and what techniques share. Hooks for tests: runtime/technique_testing.h.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/reference/agaa.h"
#include "core/reference/dynamic_coverage.h"
#include "core/util/vec2.h"
#include "runtime/rsaa_pass.h"
#include "runtime/gl_context.h"
#include "runtime/scene_renderer.h"
#include "runtime/technique_registry.h"

namespace rsaa {

// For techniques that take no --samples.
inline void reject_samples(const TechniqueOptions& o) {
  if (o.samples > 1) throw std::invalid_argument(o.technique + " takes no --samples");
}
// "dcaa", "dyncov seed zpre": the coverage techniques' rules and z-prepass when not the default.
inline std::string coverage_technique_label(const TechniqueOptions& o) {
  return o.technique + (o.rules == TechniqueOptions{}.rules ? "" : " " + o.rules) + (o.z_prepass ? " zpre" : "") +
         (o.shade == TechniqueOptions{}.shade ? "" : " shade-" + o.shade);
}

std::unique_ptr<Technique> make_noaa(int width, int height);
// edge_pass false: fxaa.frag on every pixel, without the edge pass in front (the tests' check
// that the edge pass leaves out no pixel FXAA changes).
std::unique_ptr<Technique> make_fxaa(int width, int height, bool edge_pass = true);
// Draws at 2W x 2H into its own RGBA16F target, then downsamples with kernel 1, 2 or 3.
std::unique_ptr<Technique> make_filtered_ssaa(int kernel, int width, int height);
// Coverage-based techniques on the shared per-pixel fragment lists (runtime/coverage_lists.h).
// z_prepass: CoverageFragmentLists::enable_z_prepass().
// shade_surfaces: dcaa --shade surface (CoverageListTechnique's shade_surfaces).
std::unique_ptr<Technique> make_dcaa(const DcaaSettings& settings, bool z_prepass, bool shade_surfaces, int width,
                                     int height);
// --shade fragment | surface: true for surface; throws std::invalid_argument for another name.
bool dcaa_shade_surfaces(const std::string& shade);
std::unique_ptr<Technique> make_dynamic_coverage(DynamicCoverageRules rules, bool z_prepass, int width, int height);
// Sets the uniforms of coverage_resolve.frag's COVERAGE_DCAA variant: coverage samples and the
// DcaaSettings (dcaa, and dyncov's surface rules).
void configure_surface_resolve(GLuint program, const SamplePattern& pattern, const DcaaSettings& settings);
// AGAA with settings.aggregates aggregates over `samples` (4: hardware MSAA, 8 or 16: jittered)
// visibility samples; k_pixels > 0: k is that many pixel footprints (AgaaSettings::k_per_depth,
// set per frame from the view), else settings.k in scene units.
std::unique_ptr<Technique> make_agaa(int samples, AgaaSettings settings, float k_pixels, int width, int height);

std::unique_ptr<Technique> make_hardware_msaa(int samples, int width, int height);
std::unique_ptr<Technique> make_jittered_supersampling(std::vector<Vec2> positions, int width, int height);
// The pass settings of rsaa options (validated by the caller).
RsaaSettings rsaa_settings(const TechniqueOptions& options);
// mask_output: an R32UI texture that receives the masks when settings.output_mask (for
// rsaa diagnose, train --from-scene and tests).
std::unique_ptr<Technique> make_rsaa(const RsaaSettings& settings, int width, int height,
                                     GLuint mask_output = 0);

// One uniformly placed sample per cell of a per_side x per_side grid (pixel space).
std::vector<Vec2> stratified_positions(int per_side, std::uint64_t seed);

}  // namespace rsaa
