// Read-back hooks of techniques, for the tests' CPU oracles and the papers' figures: not part
// of the Technique interface (runtime/technique.h).
#pragma once

#include <cstdint>
#include <vector>

#include "core/reference/agaa.h"
#include "core/reference/dcaa.h"
#include "core/reference/scene_shading.h"
#include "runtime/camera.h"
#include "runtime/technique.h"

namespace rsaa {

class CoverageFragmentLists;

// The last frame's buffers of an agaa technique with jittered samples (multisampled textures
// cannot be read back), rows top first: for the tests' CPU oracle.
struct AgaaFrameData {
  int width = 0, height = 0, samples = 0;
  AgaaSettings settings;  // as used for the frame (k_per_depth from its view)
  std::vector<AgaaSample> samples_of_pixels;  // width * height * samples
  std::vector<std::uint64_t> meta;            // width * height, agaa_samples.glsl's x | y << 32
  std::vector<AgaaAggregateSums> aggregates;  // width * height * settings.aggregates
  std::vector<Normal3> pixel_rays;            // width * height, view space
};
AgaaFrameData read_back_agaa(Technique& agaa, const View& view);

// The per-pixel fragment lists of a coverage technique (dcaa, dyncov), else nullptr: for tests
// that compare the GL resolve with the CPU reference on the same fragments.
CoverageFragmentLists* coverage_lists_of(Technique& technique);

// What coverage_resolve.frag does shading a surface once (dcaa --shade surface) in pixel (x, y)
// (rows top first): the scene's shading of the surface's albedo and shading normal at the view
// position of its depth at the pixel centre, with the scene's point lights (kept by reference).
DcaaSurfaceShader dcaa_surface_shader(const View& view, const std::vector<PointLight>& point_lights, int x, int y);

}  // namespace rsaa
