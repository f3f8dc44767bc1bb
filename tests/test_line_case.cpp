// Line-case geometry: exact coverage against closed forms, dense sampling, and the independent
// reference cases of tests/data (docs/conventions.md section 2).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "core/rsaa/bilinear.h"
#include "core/rsaa/case_set.h"
#include "core/rsaa/line_case.h"
#include "core/rsaa/polygon.h"

namespace rsaa {
namespace {

LineCase one_line(Vec2 point, double angle) {
  LineCase c;
  c.line_count = 1;
  c.lines[0] = {point, angle};
  return c;
}

LineCase two_lines(Vec2 p1, double a1, Vec2 p2, double a2) {
  LineCase c;
  c.line_count = 2;
  c.lines[0] = {p1, a1};
  c.lines[1] = {p2, a2};
  return c;
}

TEST(Polygon, SquareAreaAndClipping) {
  EXPECT_DOUBLE_EQ(polygon_area(pixel_square()), 1.0);
  // Keep x >= 0.25.
  EXPECT_DOUBLE_EQ(polygon_area(clip_to_half_plane(pixel_square(), 1, 0, -0.25)), 0.25);
  EXPECT_TRUE(clip_to_half_plane(pixel_square(), 1, 0, -1.0).empty());
  EXPECT_DOUBLE_EQ(polygon_area(clip_to_half_plane(pixel_square(), 1, 0, 1.0)), 1.0);
}

TEST(Coverage, HalfPlaneNearTheCentreIsOneHalf) {
  // A line through the centre itself is redrawn; one 1e-12 away leaves half the pixel.
  EXPECT_NEAR(one_line({0.0, 1e-12}, 0.0).coverage(), 0.5, 1e-11);
  EXPECT_NEAR(one_line({1e-12, 0.0}, M_PI / 2).coverage(), 0.5, 1e-11);
  EXPECT_NEAR(one_line({1e-12, 1e-12}, M_PI / 4).coverage(), 0.5, 1e-11);
}

TEST(Coverage, ClosedForms) {
  // Vertical line x = 0.25: the centre's side keeps 0.75.
  EXPECT_NEAR(one_line({0.25, 0.3}, M_PI / 2).coverage(), 0.75, 1e-12);
  // x + y = 0.25: cuts off a right triangle with legs 0.75 -> 1 - 0.28125.
  EXPECT_NEAR(one_line({0.25, 0.0}, 3 * M_PI / 4).coverage(), 0.71875, 1e-12);
  // Corner: x = 0.25 and y = 0.25 leave 0.75 * 0.75.
  EXPECT_NEAR(two_lines({0.25, 0.0}, M_PI / 2, {0.0, 0.25}, 0.0).coverage(), 0.5625, 1e-12);
  // Two lines through the corner region: x = -0.1 and y = -0.2 (centre right of / below both).
  EXPECT_NEAR(two_lines({-0.1, 0.0}, M_PI / 2, {0.0, -0.2}, 0.0).coverage(), 0.6 * 0.7, 1e-12);
  // A line that misses the pixel (through a corner point, outward diagonal) keeps it all.
  EXPECT_NEAR(one_line({0.5, 0.5}, 3 * M_PI / 4).coverage(), 1.0, 1e-12);
  // Parallel lines y = -0.1 and y = 0.3: a band of height 0.4.
  EXPECT_NEAR(two_lines({0.0, -0.1}, 0.0, {0.0, 0.3}, 0.0).coverage(), 0.4, 1e-12);
  // A thin wedge: both lines near y = 0 crossing at x = 0.3, centre inside the wedge.
  const double a = 0.01;
  const LineCase wedge = two_lines({0.3, 0.0}, a, {0.3, 0.0}, M_PI - a);
  // Wedge between y = tan(a)(x - 0.3) and y = -tan(a)(x - 0.3) for x < 0.3, inside the pixel.
  EXPECT_NEAR(wedge.coverage(), std::tan(a) * 0.8 * 0.8, 1e-12);
}

TEST(Coverage, AgreesWithDenseSamplingOnRandomCases) {
  const int grid = 400;
  for (std::uint64_t i = 0; i < 60; ++i) {
    const LineCase c = draw_line_case(99, i, line_count_of_case(i));
    int inside = 0;
    for (int y = 0; y < grid; ++y)
      for (int x = 0; x < grid; ++x)
        inside += c.in_centre_cell({-0.5 + (x + 0.5) / grid, -0.5 + (y + 0.5) / grid});
    // Midpoint sampling: the error is bounded by the cell boundary length times the spacing.
    EXPECT_NEAR(c.coverage(), double(inside) / (grid * grid), 4.0 / grid) << "case " << i;
  }
}

TEST(LineCase, CentreIsAlwaysWhiteAndMaskMatchesCells) {
  const SamplePattern p = builtin_pattern("d3d8x");
  for (std::uint64_t i = 0; i < 1000; ++i) {
    const LineCase c = draw_line_case(5, i, line_count_of_case(i));
    EXPECT_EQ(c.line_count, line_count_of_case(i));
    EXPECT_EQ(c.neighbourhood().at(0, 0), 1.0);
    EXPECT_GT(c.coverage(), 0.0);
    EXPECT_LE(c.coverage(), 1.0);
    for (int s = 0; s < p.size(); ++s)
      EXPECT_EQ(is_similar(c.mask(p), s), c.in_centre_cell(p.positions[s]));
  }
}

TEST(LineCase, DrawsAreDeterministicPerSeedAndIndex) {
  const LineCase a = draw_line_case(3, 17, 2), b = draw_line_case(3, 17, 2);
  EXPECT_EQ(a.lines[1].point, b.lines[1].point);
  EXPECT_EQ(a.lines[0].angle, b.lines[0].angle);
  EXPECT_NE(draw_line_case(4, 17, 2).lines[0].angle, a.lines[0].angle);
}

TEST(Bilinear, EstimateAtGridPointsAndKnownValue) {
  Neighbourhood3x3 n;
  for (int j = -1; j <= 1; ++j)
    for (int i = -1; i <= 1; ++i) n.at(i, j) = 3 * (j + 1) + (i + 1);
  for (int j = -1; j <= 1; ++j)
    for (int i = -1; i <= 1; ++i) EXPECT_DOUBLE_EQ(bilinear_estimate(n, i, j), n.at(i, j));
  // Bilinear in a linear field is exact: value = 4 + i + 3j.
  EXPECT_NEAR(bilinear_estimate(n, -0.3, 0.7), 4 - 0.3 + 2.1, 1e-12);
  EXPECT_EQ(Neighbourhood3x3::from_binary_code(0b100010001).binary_code(), 0b100010001);
}

// tests/data/line_cases_d3d8x.csv, computed independently of this project (tests/data/README.md).
TEST(ReferenceCases, ReproduceMasksColoursCoverageAndEstimates) {
  const std::string path = std::string(RSAA_SOURCE_DIR) + "/tests/data/line_cases_d3d8x.csv";
  std::ifstream in(path);
  ASSERT_TRUE(in) << "missing reference data " << path;
  const SamplePattern pattern = builtin_pattern("d3d8x");
  const Vec2 offsets[4] = {{0, 0}, {0.5, 0}, {-0.3, 0.7}, {0.9, -0.9}};
  std::string line;
  int rows = 0, two_line_rows = 0;
  bool header_seen = false;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (!header_seen) {
      header_seen = true;
      ASSERT_EQ(line.rfind("lines,p1x,p1y,angle1,p2x,p2y,angle2,mask,coverage,c_m1_m1", 0), 0u);
      continue;
    }
    std::vector<std::string> f;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) f.push_back(cell);
    ASSERT_EQ(f.size(), 22u) << line;
    LineCase c;
    c.line_count = std::stoi(f[0]);
    c.lines[0] = {{std::stod(f[1]), std::stod(f[2])}, std::stod(f[3])};
    if (c.line_count == 2) c.lines[1] = {{std::stod(f[4]), std::stod(f[5])}, std::stod(f[6])};
    two_line_rows += c.line_count == 2;
    EXPECT_EQ(c.mask(pattern), std::stoull(f[7])) << "row " << rows;
    EXPECT_NEAR(c.coverage(), std::stod(f[8]), 1e-9) << "row " << rows;
    const Neighbourhood3x3 n = c.neighbourhood();
    int k = 9;
    for (int j = -1; j <= 1; ++j)
      for (int i = -1; i <= 1; ++i, ++k) EXPECT_EQ(n.at(i, j), std::stod(f[k])) << "row " << rows;
    for (int o = 0; o < 4; ++o)
      EXPECT_NEAR(bilinear_estimate(n, offsets[o].x, offsets[o].y), std::stod(f[18 + o]), 1e-9)
          << "row " << rows << " offset " << o;
    ++rows;
  }
  EXPECT_EQ(rows, 2000);
  EXPECT_EQ(two_line_rows, 1000);
}

}  // namespace
}  // namespace rsaa
