// The conventions of core/rsaa/conventions.h and docs/conventions.md section 1, checked once here.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <tuple>

#include "core/rsaa/conventions.h"
#include "core/rsaa/line_case.h"
#include "core/rsaa/mask.h"
#include "core/rsaa/offset_table.h"
#include "core/rsaa/sample_pattern.h"

namespace rsaa {
namespace {

TEST(Conventions, BuiltinPatternsAreInSixteenthsWithYDown) {
  const SamplePattern p8 = builtin_pattern("d3d8x");
  ASSERT_EQ(p8.size(), 8);
  EXPECT_EQ(p8.positions[0], (Vec2{1 / 16.0, -3 / 16.0}));
  EXPECT_EQ(p8.positions[7], (Vec2{7 / 16.0, -7 / 16.0}));
  EXPECT_EQ(builtin_pattern("d3d4x").positions[3], (Vec2{2 / 16.0, 6 / 16.0}));
  const SamplePattern p16 = builtin_pattern("d3d16x");
  ASSERT_EQ(p16.size(), 16);
  EXPECT_EQ(p16.positions[15], (Vec2{-7 / 16.0, -8 / 16.0}));
  EXPECT_EQ(p8.mask_count(), 256u);
  EXPECT_THROW(builtin_pattern("d3d2x"), std::invalid_argument);
}

TEST(Conventions, PixelSpaceToGlFlipsYOnly) {
  EXPECT_EQ(pixel_to_gl({0.25, 0.5}), (Vec2{0.25, -0.5}));
  EXPECT_EQ(gl_to_pixel(pixel_to_gl({-0.3, 0.7})), (Vec2{-0.3, 0.7}));
}

TEST(Conventions, GlSamplePositionsMoveOriginToCentreAndFlipY) {
  // glGetMultisamplefv: origin bottom-left, y up; (0.75, 0.25) is right of and BELOW the
  // centre, which is +y in pixel space.
  EXPECT_EQ(gl_sample_position_to_pixel({0.5, 0.5}), (Vec2{0.0, 0.0}));
  EXPECT_EQ(gl_sample_position_to_pixel({0.75, 0.25}), (Vec2{0.25, 0.25}));
  const SamplePattern p = pattern_from_gl_positions("gl2x", {{0.375, 0.125}, {0.875, 0.375}});
  EXPECT_EQ(p.positions[0], (Vec2{-0.125, 0.375}));
  EXPECT_EQ(p.positions[1], (Vec2{0.375, 0.125}));
}

TEST(Conventions, MaskBitIMeansSubsampleIIsSimilar) {
  EXPECT_EQ(full_mask(8), 255u);
  EXPECT_EQ(full_mask(64), ~Mask{0});
  EXPECT_TRUE(is_similar(0b100, 2));
  EXPECT_FALSE(is_similar(0b100, 1));
  EXPECT_EQ(similar_count(0b1011), 3);

  // A vertical line at x = 0.2: subsamples right of it (2 at x = 5/16, 7 at x = 7/16) differ.
  LineCase vertical;
  vertical.lines[0] = {{0.2, 0.0}, M_PI / 2};
  EXPECT_EQ(vertical.mask(builtin_pattern("d3d8x")), 255u & ~((1u << 2) | (1u << 7)));
  // A horizontal line at y = +0.2 lies BELOW the centre (y down): subsamples 4 (y = 5/16) and
  // 6 (y = 7/16) differ.
  LineCase horizontal;
  horizontal.lines[0] = {{0.0, 0.2}, 0.0};
  EXPECT_EQ(horizontal.mask(builtin_pattern("d3d8x")), 255u & ~((1u << 4) | (1u << 6)));
}

TEST(Conventions, PatternFromPositionsRejectsBadPositions) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(pattern_from_positions("custom-x", {}), std::invalid_argument);
  EXPECT_THROW(pattern_from_positions("custom-x", {{0.6, 0.0}}), std::invalid_argument);
  EXPECT_THROW(pattern_from_positions("custom-x", {{nan, 0.0}}), std::invalid_argument);
  EXPECT_THROW(pattern_from_positions("custom-x", std::vector<Vec2>(65)), std::invalid_argument);
  EXPECT_NO_THROW(pattern_from_positions("custom-x", {{0.5, -0.5}}));
}

namespace rsaa {
namespace {

// Cell patterns (docs/conventions.md section 1): cell (column, row) maps base position p to
// ((column + 1/2 + p.x) / columns - 1/2, (row + 1/2 + p.y) / rows - 1/2), cells row by row from the
// top-left (y down), and the checked-in cell tables are the cells of the driver's 4x pattern.
TEST(Conventions, CellPatternsScaleTheBasePatternIntoEachCell) {
  const SamplePattern d3d4x = builtin_pattern("d3d4x");  // (-2,-6) (6,-2) (-6,2) (2,6) / 16
  const SamplePattern tall = cell_pattern(d3d4x, 1, 2);
  EXPECT_EQ(tall.name, "custom-d3d4x-tall");
  ASSERT_EQ(tall.size(), 8);
  EXPECT_EQ(tall.positions[0], (Vec2{-2.0 / 16, (0.5 - 6.0 / 16) / 2 - 0.5}));  // top cell: y in [-1/2, 0)
  EXPECT_EQ(tall.positions[7], (Vec2{2.0 / 16, (1.5 + 6.0 / 16) / 2 - 0.5}));   // bottom cell
  const SamplePattern quad = cell_pattern(d3d4x, 2, 2);
  EXPECT_EQ(quad.name, "custom-d3d4x-quad");
  EXPECT_EQ(quad.positions[5], (Vec2{(1.5 + 6.0 / 16) / 2 - 0.5, (0.5 - 2.0 / 16) / 2 - 0.5}));  // top-right cell
  for (const Vec2& p : quad.positions) EXPECT_TRUE(std::abs(p.x) < 0.5 && std::abs(p.y) < 0.5);
  EXPECT_EQ(cell_pattern(d3d4x, 2, 1).name, "custom-d3d4x-wide");
  EXPECT_EQ(cell_pattern(d3d4x, 3, 1).name, "custom-d3d4x-cells3x1");
  EXPECT_EQ(cell_pattern(tall, 2, 1).name, "custom-d3d4x-tall-wide");  // custom- is not repeated
  EXPECT_THROW(cell_pattern(d3d4x, 0, 2), std::invalid_argument);
  EXPECT_THROW(cell_pattern(builtin_pattern("d3d16x"), 3, 2), std::invalid_argument);  // 96 subsamples
  try {  // a name that the suffix makes too long is said to be so
    cell_pattern(pattern_from_positions("custom-" + std::string(55, 'a'), {{0.25, 0.25}}), 2, 1);
    ADD_FAILURE() << "a 70-character pattern name was made";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("give the pattern a shorter name"), std::string::npos) << e.what();
  }
  const SamplePattern gl4x = read_offset_table(std::string(RSAA_SOURCE_DIR) + "/tables/gl4x.json").pattern;
  for (const auto& [file, columns, rows] : {std::tuple{"custom-gl4x-wide", 2, 1}, std::tuple{"custom-gl4x-tall", 1, 2},
                                            std::tuple{"custom-gl4x-quad", 2, 2}}) {
    const SamplePattern checked_in =
        read_offset_table(std::string(RSAA_SOURCE_DIR) + "/tables/" + file + ".json").pattern;
    const SamplePattern made = cell_pattern(gl4x, columns, rows);
    EXPECT_EQ(made.name, checked_in.name);
    ASSERT_EQ(made.size(), checked_in.size()) << file;
    for (int i = 0; i < made.size(); ++i) EXPECT_EQ(made.positions[i], checked_in.positions[i]) << file << " " << i;
  }
}

TEST(Conventions, OutsidePixelTowardsSubsampleMatchesThePapersTableForD3D8x) {
  // Listing 2/3 of the paper: sampleOffset[] for the eight D3D 8x subsamples (y down).
  const int expected[8][2] = {{0, -1}, {0, 1}, {1, 0}, {-1, -1}, {-1, 1}, {-1, 0}, {0, 1}, {1, -1}};
  const SamplePattern p = builtin_pattern("d3d8x");
  for (int s = 0; s < 8; ++s) {
    const PixelStep step = outside_pixel_towards(p.positions[s]);
    EXPECT_EQ(step.i, expected[s][0]) << "subsample " << s;
    EXPECT_EQ(step.j, expected[s][1]) << "subsample " << s;
  }
  EXPECT_EQ(outside_pixel_towards({0, 0}).i, 1);
}

}  // namespace
}  // namespace rsaa

// Post-pass authentication picks the farthest dissimilar subsample; among equally distant ones
// the last in pattern order, as the paper's Listing 3 (which keeps the last dissimilar one).
TEST(Conventions, RepresentativeDissimilarBreaksTiesAsListing3) {
  const SamplePattern d3d8x = builtin_pattern("d3d8x");
  // Subsamples 4 (-5,5) and 5 (-7,-1) are both sqrt(50)/16 from the centre; 6 and 7 are farther.
  const Mask only_4_and_5_dissimilar = full_mask(8) & ~Mask{0x30};
  EXPECT_EQ(representative_dissimilar(d3d8x, only_4_and_5_dissimilar), 5);
  EXPECT_EQ(representative_dissimilar(d3d8x, full_mask(8) & ~Mask{0x10}), 4);
  EXPECT_EQ(representative_dissimilar(d3d8x, Mask{0}), 7);  // the farthest, (7,-7)
  EXPECT_EQ(representative_dissimilar(d3d8x, full_mask(8)), -1);
  // d3d4x: all four subsamples equally distant, so the last dissimilar one wins.
  const SamplePattern d3d4x = builtin_pattern("d3d4x");
  EXPECT_EQ(representative_dissimilar(d3d4x, Mask{0b0000}), 3);
  EXPECT_EQ(representative_dissimilar(d3d4x, Mask{0b1000}), 2);
  EXPECT_EQ(representative_dissimilar(d3d4x, Mask{0b1010}), 2);
  EXPECT_EQ(representative_dissimilar(d3d4x, Mask{0b1110}), 0);
}

}  // namespace
}  // namespace rsaa
