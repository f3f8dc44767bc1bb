// CPU reference of Aggregate G-Buffer Anti-Aliasing (AGAA, seed 001): the n visibility samples of
// a pixel (view-space position and facet normal of the surface each one sees) are clustered into
// at most c aggregates (the paper's Algorithm 1 with its distance, eq. 1); a second geometry pass
// accumulates each aggregate's coverage-weighted shading inputs; each aggregate is shaded once,
// its specular lobe widened by Toksvig's factor, and the pixel is the coverage-weighted sum over
// the background. The GL technique (runtime/techniques/agaa.cpp) implements the same steps.
#pragma once

#include <array>
#include <vector>

#include "core/reference/coverage_fragment.h"
#include "core/util/image.h"

namespace rsaa {

struct AgaaSettings {
  int aggregates = 2;            // c, 1..4
  float k = 0.1f;                // characteristic length in scene units (the paper: 10 cm)
  float min_separation = 0.25f;  // t: a further aggregate only when this far (eq. 1) from the others
  // > 0: k relative to the view instead, k = k_per_depth * |z| of the pixel's mean sample
  // position (view space). With k_per_depth = K * 2 tan(fov_y / 2) / height, k is K pixel
  // footprints at the surface: the same clustering for a model in metres or millimetres.
  float k_per_depth = 0.0f;
  bool filtered_diffuse = true;  // agaa_resolve()'s filtered_diffuse
};

// k_per_depth for k = `pixels` pixel footprints in a view whose projection has P[1][1] =
// `projection_y_scale` (= 1 / tan(fov_y / 2)) and `height` rows.
inline float agaa_k_per_depth(float pixels, float projection_y_scale, int height) {
  return pixels * 2.0f / (projection_y_scale * float(height));
}

struct AgaaSample {
  bool valid = false;  // false: the sample sees the background
  Normal3 position;    // view space
  Normal3 normal;      // unit facet normal
};

// Eq. 1: |(a - b) / k|^2 + (1 - na . nb)^2.
float agaa_distance(const AgaaSample& a, const AgaaSample& b, float k);

struct AgaaClusters {
  int count = 0;               // aggregates defined (0 when no sample is valid)
  std::vector<int> aggregate;  // per sample: its aggregate, -1 for background samples
};

// Algorithm 1: s0 = the valid sample farthest from the average (mean position, normalised mean
// normal), s1 = the one farthest from s0, each further seed the one with the largest sum of
// squared distances to the seeds, each only among the samples farther than t from every earlier
// seed (none: no further aggregate). Every valid sample then joins its nearest seed. Ties: the lower sample index,
// the lower aggregate.
AgaaClusters define_aggregates(const std::vector<AgaaSample>& samples, const AgaaSettings& settings);

// What the accumulation pass adds up for one aggregate: each fragment contributes its shading
// inputs times w = (its visible samples in the aggregate) / n.
struct AgaaAggregateSums {
  Rgb albedo;          // sum of w * albedo
  Normal3 normal{0, 0, 0};  // sum of w * unit shading normal (its length / weight is Toksvig's |Na|)
  float view_z = 0.0f;      // sum of w * view-space z
  float weight = 0.0f;      // sum of w: the aggregate's share of the pixel
};

// Toksvig: the Phong exponent s of a lobe whose averaged normal has length |Na|:
// ft = |Na| / (|Na| + s (1 - |Na|)), s' = ft s. |Na| = 1 leaves s; |Na| -> 0 gives the floor
// 1e-3 (a nearly uniform lobe; GLSL's pow(0, 0) is undefined).
float toksvig_exponent(float normal_length, float exponent);

// Shades each aggregate once (mean albedo, normalised mean normal, the pixel ray at the mean
// depth, Toksvig-filtered specular with its peak scaled by (1 + s') / (1 + s) so the lobe keeps
// its energy) and composites: sum_a weight_a colour_a + (1 - sum weight) background.
// `pixel_ray`: view-space direction through the pixel centre. Empty aggregates are skipped; the
// result is finite for any finite input.
// filtered_diffuse: the Lambert term scaled by |Na| (the mean of n.l over the aggregate's unit
// normals is Na.l while none faces away from the light; the paper filters diffuse from the same
// Toksvig length); false shades the normalised mean normal as one surface.
Rgb agaa_resolve(const std::vector<AgaaAggregateSums>& aggregates, Normal3 pixel_ray, Rgb background,
                 bool filtered_diffuse = true);

// The paper's memory: 6 B per visibility sample + 16 B per aggregate.
constexpr double agaa_paper_bytes_per_pixel(int samples, int aggregates) { return 6.0 * samples + 16.0 * aggregates; }

}  // namespace rsaa
