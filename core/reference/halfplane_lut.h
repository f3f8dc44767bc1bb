// Coverage masks of triangles from a lookup table of half-plane masks (DCAA, seed 000, sec. 3.1):
// each directed edge indexes the mask of the samples on its inner side; a triangle's coverage is
// the AND of its three edge masks. The table is built with Line::side(), the classification the
// RSAA trainer uses for its line cases (one geometry module, two uses).
//
// Parametrisation (pixel space, centre (0, 0), y down): an edge is the line n.p = d with unit
// normal n = (cos theta, sin theta) pointing to the covered side; covered means n.p > d
// (strictly). theta in [0, 2 pi) has `angle_bins` bins, d in [-R, R] (R = sqrt(2)/2, the pixel's
// circumradius) `distance_bins` bins; d <= -R covers the whole pixel, d >= R none of it.
// Entries hold the masks of the bin centres, so a sample farther than max_error() from the true
// edge is classified exactly.
#pragma once

#include <cstdint>
#include <vector>

#include "core/rsaa/line_case.h"
#include "core/rsaa/mask.h"
#include "core/rsaa/sample_pattern.h"
#include "core/util/vec2.h"

namespace rsaa {

struct HalfPlane {
  double theta = 0.0;     // normal direction, radians
  double distance = 0.0;  // n.p on the edge
};

// The half-plane on the inner side of the directed edge a -> b of a triangle whose signed area
// (cross(b - a, c - a)) has sign `orientation` (+1 or -1).
HalfPlane inner_half_plane(Vec2 a, Vec2 b, double orientation);

// The samples strictly inside `h`, by direct classification (Line::side).
Mask half_plane_mask_direct(const SamplePattern& pattern, const HalfPlane& h);

class HalfPlaneLut {
 public:
  static constexpr int kDefaultAngleBins = 256, kDefaultDistanceBins = 128;

  explicit HalfPlaneLut(SamplePattern pattern, int angle_bins = kDefaultAngleBins,
                        int distance_bins = kDefaultDistanceBins);

  Mask lookup(const HalfPlane& h) const;
  // Samples inside the triangle (AND of its 3 inner half-planes); 0 for a degenerate or
  // non-finite triangle.
  Mask triangle_coverage(Vec2 a, Vec2 b, Vec2 c) const;

  // Bound on the distance from the true edge of a sample the table can misclassify.
  double max_error() const;
  static double max_distance();  // R

  const SamplePattern& pattern() const { return pattern_; }
  int angle_bins() const { return angle_bins_; }
  int distance_bins() const { return distance_bins_; }
  // Row-major [angle][distance] masks: the texture the GL techniques upload.
  const std::vector<Mask>& entries() const { return entries_; }

 private:
  SamplePattern pattern_;
  int angle_bins_, distance_bins_;
  std::vector<Mask> entries_;
};

// 64 coverage samples for DCAA: one per cell of an 8x8 grid, placed so that all 64 x and all 64
// y coordinates differ (an axis-aligned edge moves through 64 coverage levels, not 8).
SamplePattern dcaa_coverage_pattern();

}  // namespace rsaa
