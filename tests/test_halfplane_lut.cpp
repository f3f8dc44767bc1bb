// The half-plane coverage LUT against direct sample classification (all 64 samples, edges
// through and near samples), its watertightness and its extremes.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>

#include "core/reference/halfplane_lut.h"
#include "core/rsaa/line_case.h"

namespace rsaa {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Samples farther than the LUT's error bound from the edge must be classified exactly.
void expect_agrees_away_from_edge(const HalfPlaneLut& lut, const HalfPlane& h, int* near_edge = nullptr) {
  const Mask from_lut = lut.lookup(h), direct = half_plane_mask_direct(lut.pattern(), h);
  const Vec2 n{std::cos(h.theta), std::sin(h.theta)};
  for (int i = 0; i < lut.pattern().size(); ++i) {
    const double distance = std::abs(dot(n, lut.pattern().positions[i]) - h.distance);
    if (distance > lut.max_error())
      ASSERT_EQ(is_similar(from_lut, i), is_similar(direct, i))
          << "sample " << i << " at " << distance << " px from the edge theta " << h.theta << " d " << h.distance;
    else if (near_edge && is_similar(from_lut, i) != is_similar(direct, i))
      ++*near_edge;
  }
}

TEST(HalfPlaneLut, PatternHas64DistinctColumnsAndRows) {
  const SamplePattern p = dcaa_coverage_pattern();
  ASSERT_EQ(p.size(), 64);
  std::set<double> xs, ys;
  for (Vec2 s : p.positions) xs.insert(s.x), ys.insert(s.y);
  EXPECT_EQ(xs.size(), 64u);
  EXPECT_EQ(ys.size(), 64u);
}

TEST(HalfPlaneLut, ErrorBoundIsWellBelowTheSampleSpacing) {
  const HalfPlaneLut lut(dcaa_coverage_pattern());
  EXPECT_LT(lut.max_error(), 1.0 / 64.0);
  EXPECT_GT(lut.max_error(), 0.0);
}

TEST(HalfPlaneLut, AgreesWithDirectClassificationOnRandomEdges) {
  const HalfPlaneLut lut(dcaa_coverage_pattern());
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> angle(-4 * kPi, 4 * kPi), distance(-0.8, 0.8);
  for (int k = 0; k < 20000; ++k) expect_agrees_away_from_edge(lut, {angle(rng), distance(rng)});
}

TEST(HalfPlaneLut, EdgesThroughAndNearEverySample) {
  const HalfPlaneLut lut(dcaa_coverage_pattern());
  int near_edge_mismatches = 0;
  for (const Vec2 s : lut.pattern().positions)
    for (int a = 0; a < 48; ++a) {
      const double theta = a * kPi / 24.0 + 0.013;
      const Vec2 n{std::cos(theta), std::sin(theta)};
      for (double offset : {-0.05, -lut.max_error(), -1e-9, 0.0, 1e-9, lut.max_error(), 0.05})
        expect_agrees_away_from_edge(lut, {theta, dot(n, s) + offset}, &near_edge_mismatches);
    }
  // Within the bound the table may differ, and does for edges through samples: the bound is
  // needed, and the exact agreement beyond it (asserted above) is the table's guarantee.
  EXPECT_GT(near_edge_mismatches, 0);
}

TEST(HalfPlaneLut, OppositeEdgesAreComplementary) {
  // Two triangles sharing an edge see it with opposite normals: no sample is counted twice or
  // lost (away from samples lying exactly on the quantised edge, which the random draw avoids).
  const HalfPlaneLut lut(dcaa_coverage_pattern());
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> angle(0, 2 * kPi), distance(-0.75, 0.75);
  for (int k = 0; k < 5000; ++k) {
    const HalfPlane h{angle(rng), distance(rng)}, opposite{h.theta + kPi, -h.distance};
    EXPECT_EQ(lut.lookup(h) & lut.lookup(opposite), 0u);
    EXPECT_EQ(lut.lookup(h) | lut.lookup(opposite), lut.pattern().all_similar());
  }
}

TEST(HalfPlaneLut, SameClassificationAsTheTrainersLineCases) {
  // One geometry module, two uses: a one-line case's mask is the half-plane holding the centre.
  const HalfPlaneLut lut(dcaa_coverage_pattern());
  for (std::uint64_t i = 0; i < 2000; i += 2) {
    const LineCase c = draw_line_case(3, i, 1);
    const Line& line = c.lines[0];
    // side(p) = n.p - n.point with n = (-sin, cos) of the line's direction.
    Vec2 n{-std::sin(line.angle), std::cos(line.angle)};
    if (line.side({0, 0}) < 0) n = -1.0 * n;
    const HalfPlane h{std::atan2(n.y, n.x), dot(n, line.point)};
    EXPECT_EQ(half_plane_mask_direct(lut.pattern(), h), c.mask(lut.pattern())) << "case " << i;
  }
}

TEST(HalfPlaneLut, Extremes) {
  const HalfPlaneLut lut(dcaa_coverage_pattern());
  EXPECT_EQ(lut.lookup({0.3, -0.75}), lut.pattern().all_similar());
  EXPECT_EQ(lut.lookup({0.3, 0.75}), 0u);
  EXPECT_EQ(lut.lookup({0.3, -1e30}), lut.pattern().all_similar());
  EXPECT_EQ(lut.lookup({std::nan(""), 0.0}), 0u);
  EXPECT_EQ(lut.lookup({0.0, std::nan("")}), 0u);
  // Zero-area, non-finite and huge triangles.
  EXPECT_EQ(lut.triangle_coverage({0, 0}, {0.2, 0.2}, {0.4, 0.4}), 0u);
  EXPECT_EQ(lut.triangle_coverage({0, 0}, {0, 0}, {0, 0}), 0u);
  EXPECT_EQ(lut.triangle_coverage({0, 0}, {std::nan(""), 0}, {1, 1}), 0u);
  EXPECT_EQ(lut.triangle_coverage({-1e7, -1e7}, {1e7, -1e7}, {0, 1e7}), lut.pattern().all_similar());
  EXPECT_EQ(lut.triangle_coverage({-1e7, -1e7}, {0, 1e7}, {1e7, -1e7}), lut.pattern().all_similar());  // either winding
  EXPECT_THROW(HalfPlaneLut(dcaa_coverage_pattern(), 3, 8), std::invalid_argument);
}

TEST(HalfPlaneLut, TriangleCoverageMatchesPointInTriangle) {
  const HalfPlaneLut lut(builtin_pattern("d3d16x"));
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> coordinate(-1.5, 1.5);
  for (int k = 0; k < 5000; ++k) {
    const Vec2 v[3] = {{coordinate(rng), coordinate(rng)}, {coordinate(rng), coordinate(rng)},
                       {coordinate(rng), coordinate(rng)}};
    const Mask m = lut.triangle_coverage(v[0], v[1], v[2]);
    const double o = cross(v[1] - v[0], v[2] - v[0]) > 0 ? 1.0 : -1.0;
    for (int i = 0; i < 16; ++i) {
      const Vec2 p = lut.pattern().positions[i];
      bool inside = true, near = false;
      for (int e = 0; e < 3; ++e) {
        const Vec2 a = v[e], b = v[(e + 1) % 3];
        const double signed_distance = o * cross(b - a, p - a) / length(b - a);
        inside = inside && signed_distance > 0;
        near = near || std::abs(signed_distance) <= lut.max_error();
      }
      if (!near) {
        ASSERT_EQ(is_similar(m, i), inside) << "triangle " << k << " sample " << i;
      }
    }
  }
}

}  // namespace
}  // namespace rsaa
