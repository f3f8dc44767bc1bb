// The fallback rule of core/rsaa/fallback.h against its definition.
#include <gtest/gtest.h>

#include <cmath>

#include "core/rsaa/fallback.h"
#include "core/rsaa/offset_table.h"

namespace rsaa {
namespace {

TEST(Fallback, LengthSolvesTheCentreWeightEquation) {
  for (double angle : {0.0, 0.3, M_PI / 4, 1.2, M_PI / 2, 2.5}) {
    const Vec2 u{std::cos(angle), std::sin(angle)};
    for (double s : {0.0, 0.125, 0.5, 0.875, 1.0}) {
      const double t = fallback_length(u, s);
      EXPECT_NEAR((1 - t * std::abs(u.x)) * (1 - t * std::abs(u.y)), s, 1e-12);
      EXPECT_LE(t * std::max(std::abs(u.x), std::abs(u.y)), 1.0 + 1e-12);
      EXPECT_GE(t, 0.0);
    }
  }
  // Axis-aligned: the outside weight is t itself.
  EXPECT_DOUBLE_EQ(fallback_length({1, 0}, 0.75), 0.25);
}

TEST(Fallback, PointsAtTheFarthestDissimilarSubsample) {
  const SamplePattern p = builtin_pattern("d3d8x");
  // Only subsample 7 (7/16, -7/16), the farthest of all, is dissimilar.
  const Vec2 d = fallback_offset(p, 255u & ~(1u << 7));
  EXPECT_NEAR(d.x, -d.y, 1e-12);
  EXPECT_GT(d.x, 0.0);
  const double t = length(d);
  EXPECT_NEAR((1 - t / std::sqrt(2.0)) * (1 - t / std::sqrt(2.0)), 7.0 / 8.0, 1e-12);
  // Subsamples 0 (1,-3) and 2 (5,1) dissimilar: 2 is farther.
  const Vec2 e = fallback_offset(p, 255u & ~0b101u);
  EXPECT_NEAR(e.y / e.x, 1.0 / 5.0, 1e-12);
}

TEST(Fallback, AllSimilarIsZeroAndEveryEntryIsBounded) {
  for (const std::string& name : builtin_pattern_names()) {
    const OffsetTable t = fallback_table(builtin_pattern(name));
    EXPECT_EQ(t.offsets.back(), (Vec2{0.0, 0.0})) << name;
    for (const Vec2 d : t.offsets) {
      ASSERT_TRUE(is_finite(d));
      ASSERT_LE(std::abs(d.x), 1.0);
      ASSERT_LE(std::abs(d.y), 1.0);
    }
  }
  // A pattern whose only dissimilar subsample is the centre: no direction, zero offset.
  const SamplePattern centre = pattern_from_positions("custom-centre", {{0, 0}, {0.25, 0}});
  EXPECT_EQ(fallback_offset(centre, 0b10), (Vec2{0.0, 0.0}));
}

}  // namespace
}  // namespace rsaa
