// What the coverage-based techniques (DCAA, dynamic coverage) receive per pixel and triangle: a
// shaded colour (or, for DCAA's shading once per surface, the shading inputs: albedo and shading
// normal), a coverage mask over the technique's coverage samples, the depth plane of the triangle
// over the pixel and its facet normal, in primitive (submission) order.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/util/image.h"
#include "core/rsaa/mask.h"
#include "core/util/vec2.h"

namespace rsaa {

struct Normal3 {
  float x = 0.0f, y = 0.0f, z = 1.0f;
};
inline float dot(Normal3 a, Normal3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// Window depth (0 near, 1 far) as a plane over the pixel: depth(p) = at_centre + ddx p.x + ddy p.y,
// p in pixel space (centre (0, 0), y down).
struct DepthPlane {
  float at_centre = 1.0f, ddx = 0.0f, ddy = 0.0f;

  float at(Vec2 p) const { return at_centre + ddx * float(p.x) + ddy * float(p.y); }
  // Extent over the pixel square: the bounding interval the merge heuristics compare.
  float half_range() const { return 0.5f * (std::abs(ddx) + std::abs(ddy)); }
  float min_over_pixel() const { return at_centre - half_range(); }
  float max_over_pixel() const { return at_centre + half_range(); }
};

struct CoverageFragment {
  std::uint32_t order = 0;  // submission order of the primitive: fragments are replayed by it
  Mask coverage = 0;
  DepthPlane depth;
  Normal3 normal;  // unit facet normal, facing the viewer
  Rgb colour;      // linear, shaded once for the fragment (dcaa --shade fragment, dyncov)
  // dcaa --shade surface: what the scene's shading needs besides the position (which the depth
  // plane gives): linear albedo (texture included, fetched per fragment as a G-buffer would) and
  // the unit shading normal, facing the viewer or not (the shading is two-sided).
  Rgb albedo;
  Normal3 shading_normal;
};

inline bool depth_intervals_overlap(const DepthPlane& a, const DepthPlane& b) {
  return a.min_over_pixel() <= b.max_over_pixel() && b.min_over_pixel() <= a.max_over_pixel();
}
inline float depth_overlap_amount(const DepthPlane& a, const DepthPlane& b) {
  return std::min(a.max_over_pixel(), b.max_over_pixel()) - std::max(a.min_over_pixel(), b.min_over_pixel());
}

}  // namespace rsaa
