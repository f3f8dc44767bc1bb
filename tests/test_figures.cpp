// rsaa figures (tools/bench/paper_figures.h): the numbers each figure computes, on hand-made
// inputs against closed forms, and a tiny run of every figure for well-formed tables.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numeric>

#include "core/reference/halfplane_lut.h"
#include "image/image_metrics.h"
#include "tests/gl_test.h"
#include "tests/test_util.h"
#include "tools/bench/chart.h"
#include "tools/bench/paper_figures.h"

namespace rsaa {
namespace {

DisplayImage grey(int width, int height, std::uint8_t value) {
  DisplayImage d;
  d.width = width, d.height = height;
  d.rgb.assign(std::size_t(width) * height * 3, value);
  return d;
}

void set_grey(DisplayImage& d, std::size_t pixel, std::uint8_t value) {
  for (int c = 0; c < 3; ++c) d.rgb[3 * pixel + c] = value;
}

TEST(Figures, LumaErrorSharesOfHandMadeImages) {
  // 100 pixels: 50 off by 10 grey levels, 25 by 40, 25 equal. A grey difference d is a luma
  // difference d / 255 (the Rec. 709 weights sum to 1).
  const DisplayImage reference = grey(10, 10, 100);
  DisplayImage a = reference;
  for (std::size_t p = 0; p < 50; ++p) set_grey(a, p, 110);
  for (std::size_t p = 50; p < 75; ++p) set_grey(a, p, 60);
  const std::vector<double> shares = luma_error_shares(a, reference, {5 / 255.0, 20 / 255.0, 50 / 255.0, 0.0});
  ASSERT_EQ(shares.size(), 4u);
  EXPECT_DOUBLE_EQ(shares[0], 75.0);
  EXPECT_DOUBLE_EQ(shares[1], 25.0);
  EXPECT_DOUBLE_EQ(shares[2], 0.0);
  EXPECT_DOUBLE_EQ(shares[3], 75.0);  // strictly above 0: the equal pixels do not count
  // One channel: red 51 levels apart is a luma difference of 0.2126 * 51 / 255 = 0.04252.
  DisplayImage red = reference;
  red.rgb[0] = 151;
  const auto one = luma_error_shares(red, reference, {0.0420, 0.0430});
  EXPECT_DOUBLE_EQ(one[0], 1.0);
  EXPECT_DOUBLE_EQ(one[1], 0.0);
  // The same measure as compare_images' luminance-error share at its default threshold.
  EXPECT_DOUBLE_EQ(luma_error_shares(a, reference, {1.0 / 64.0})[0], compare_images(a, reference).luma_error_share);
  EXPECT_THROW(luma_error_shares(grey(2, 2, 0), reference, {0.1}), std::invalid_argument);
  EXPECT_THROW(luma_error_shares(a, reference, {std::nan("")}), std::invalid_argument);
}

TEST(Figures, Figure1ThresholdsDoubleFromHalfALevel) {
  const auto t = bench::figure1_thresholds();
  ASSERT_EQ(t.size(), 9u);
  EXPECT_DOUBLE_EQ(t.front() * 255.0, 0.5);
  EXPECT_DOUBLE_EQ(t.back() * 255.0, 128.0);
}

CoverageFragment fragment(std::uint32_t order, Mask coverage, float depth, Normal3 normal, float slope = 0.0f) {
  CoverageFragment f;
  f.order = order;
  f.coverage = coverage;
  f.depth = {depth, slope, 0.0f};
  f.normal = normal;
  f.colour = {0.5f, 0.5f, 0.5f};
  return f;
}

TEST(Figures, DcaaSurfaceHistogramOfHandMadePixels) {
  const SamplePattern pattern = dcaa_coverage_pattern();
  const Mask left = 0x00000000ffffffffull, right = ~left, quarter = 0xffull;
  const Normal3 facing{0, 0, 1}, sideways{0.8f, 0, 0.6f}, up{0, 0.8f, 0.6f};
  std::vector<std::vector<CoverageFragment>> pixels(4);
  // Pixel 1: two triangles of one plane, disjoint halves: merged into one surface.
  pixels[1] = {fragment(0, left, 0.5f, facing, 0.01f), fragment(1, right, 0.5f, facing, 0.01f)};
  // Pixel 2: three surfaces apart in depth and normal, the nearest covering a quarter: all seen.
  pixels[2] = {fragment(0, left, 0.8f, facing), fragment(1, right, 0.5f, sideways), fragment(2, quarter, 0.2f, up)};
  // Pixel 3: a surface hidden behind another that covers the whole pixel: stored, not visible.
  pixels[3] = {fragment(0, left | right, 0.3f, facing), fragment(1, left | right, 0.7f, sideways)};
  const auto stored = bench::dcaa_surface_histogram(pixels, dcaa_settings("surface"), pattern);
  ASSERT_EQ(stored.size(), 5u);  // 0..4 surfaces (4 slots by default)
  EXPECT_EQ(stored, (std::vector<std::size_t>{1, 1, 1, 1, 0}));
  EXPECT_EQ(bench::dcaa_surface_histogram(pixels, dcaa_settings("surface"), pattern, true),
            (std::vector<std::size_t>{1, 2, 0, 1, 0}));
  DcaaSettings two = dcaa_settings("surface");
  two.max_surfaces = 2;
  EXPECT_EQ(bench::dcaa_surface_histogram(pixels, two, pattern), (std::vector<std::size_t>{1, 1, 2}));
}

TEST(Figures, PullBackKeepsTheViewDirectionAndScalesTheDepthRange) {
  Camera c;
  c.eye = {1, 2, 3};
  c.target = {1, 2, 0};
  const Camera far = bench::pulled_back_camera(c, 4.0, 0.0);
  EXPECT_NEAR(far.eye.z, 12.0f, 1e-5f);
  EXPECT_NEAR(far.eye.x, 1.0f, 1e-5f);
  EXPECT_FLOAT_EQ(far.near_plane, 4 * c.near_plane);
  EXPECT_FLOAT_EQ(far.far_plane, 4 * c.far_plane);
  const Camera turned = bench::pulled_back_camera(c, 1.0, 90.0);
  EXPECT_NEAR(glm::length(turned.eye - turned.target), 3.0f, 1e-5f);
  EXPECT_NEAR(turned.eye.z, 0.0f, 1e-4f);
  EXPECT_DOUBLE_EQ(bench::pull_back_factor(0, 3, 16.0), 1.0);
  EXPECT_DOUBLE_EQ(bench::pull_back_factor(1, 3, 16.0), 4.0);
  EXPECT_DOUBLE_EQ(bench::pull_back_factor(2, 3, 16.0), 16.0);
  EXPECT_THROW(bench::pulled_back_camera(c, 0.0, 0.0), std::invalid_argument);
}

TEST(Figures, TablesWriteCsvAndCharts) {
  bench::FigureTable t;
  t.columns = {"x", "a \"quoted\"", "b"};
  t.add({1, 2.5, 3});
  t.add({2, 4, 1e-7}, "second");
  EXPECT_EQ(bench::table_csv(t), "label,\"x\",\"a \"\"quoted\"\"\",\"b\"\n\"\",1,2.5,3\n\"second\",2,4,1e-07\n");
  EXPECT_THROW(t.add({1, 2}), std::invalid_argument);
  EXPECT_EQ(t.column("b"), 2u);
  test::TempDir dir;
  bench::plot_lines(t, {"lines", "x", "y", false, {"b"}}, dir.file("lines.png"));
  bench::plot_bars(t, {"bars", "", "y", false, {}}, dir.file("bars.png"));
  EXPECT_GT(read_display_image(dir.file("lines.png")).width, 500);
  EXPECT_GT(read_display_image(dir.file("bars.png")).width, 500);
  // The legend widens with its longest label (RSAA's labels name every option they set; they ran
  // off the image's edge).
  const int short_width = read_display_image(dir.file("lines.png")).width;
  t.columns[2] = "rsaa 8x sadp-plane auth1 cap1.5 ms sc fc me and a label longer still than that";
  bench::plot_lines(t, {"lines", "x", "y", false, {}}, dir.file("long.png"));
  EXPECT_GT(read_display_image(dir.file("long.png")).width, short_width + 100);
}

class FiguresGl : public test::GlTest {};

TEST_F(FiguresGl, TinyRunOfEveryFigure) {
  bench::FigureOptions o;
  o.scenes = {"builtin:edges"};
  o.width = 48, o.height = 36, o.frames = 3;
  test::TempDir dir;
  for (const std::string& name : bench::figure_names()) {
    const bench::Figure f = bench::make_figure(name, o, nullptr);
    ASSERT_FALSE(f.parts.empty()) << name;
    for (const auto& part : f.parts)
      for (const auto& row : part.table.rows) {
        ASSERT_EQ(row.size(), part.table.columns.size()) << name;
        for (double v : row) EXPECT_TRUE(std::isfinite(v) || name == "memory") << name;
      }
    bench::write_figure(f, dir.path());
    // A cell without a value (memory: a technique without that buffer) is written empty, as
    // the Markdown's "-": never "nan" or "inf" in a file a spreadsheet reads.
    for (const auto& part : f.parts) {
      const std::string csv = test::read_text(dir.file(part.stem + ".csv"));
      EXPECT_EQ(csv.find("nan"), std::string::npos) << part.stem << "\n" << csv;
      EXPECT_EQ(csv.find("inf"), std::string::npos) << part.stem << "\n" << csv;
    }
    if (name == "fig9") {
      const auto& t = f.parts[0].table;
      ASSERT_EQ(t.rows.size(), 3u);
      EXPECT_DOUBLE_EQ(t.rows[2][1], 16.0);  // the last frame at the full pull-back
      for (const auto& row : t.rows)
        for (std::size_t c = 2; c < row.size(); ++c) EXPECT_GT(row[c], 10.0) << t.columns[c];
    }
    if (name == "fig1") {  // a share can only fall as the threshold rises
      for (std::size_t c = 1; c < f.parts[0].table.columns.size(); ++c)
        for (std::size_t r = 1; r < f.parts[0].table.rows.size(); ++r)
          EXPECT_LE(f.parts[0].table.rows[r][c], f.parts[0].table.rows[r - 1][c]);
    }
    if (name == "dcaa") {
      double total = 0;
      for (const auto& row : f.parts[0].table.rows) total += row[1];
      EXPECT_NEAR(total, 100.0, 1e-9);
      for (std::size_t r = 0; r < f.parts[0].table.rows.size(); ++r)  // stored at least as many as visible
        EXPECT_LE(std::accumulate(f.parts[0].table.rows.begin() + long(r), f.parts[0].table.rows.end(), 0.0,
                                  [](double sum, const auto& row) { return sum + row[2]; }),
                  std::accumulate(f.parts[0].table.rows.begin() + long(r), f.parts[0].table.rows.end(), 0.0,
                                  [](double sum, const auto& row) { return sum + row[1]; }) + 1e-9);
      EXPECT_EQ(f.parts[1].table.rows.size(), 7u);  // 2..8 surfaces
    }
    if (name == "agaa") {
      EXPECT_EQ(f.parts[0].table.rows.size(), 4u);  // c = 1..4
    }
  }
  EXPECT_THROW(bench::make_figure("fig2", o, nullptr), std::invalid_argument);
  EXPECT_NE(test::read_text(dir.file("fig9.csv")).find("distance"), std::string::npos);
}

TEST(FiguresCli, RefusesAnUnknownFigure) {
  const auto r = test::run_rsaa("figures --figure fig2 --out-dir /nonexistent/x");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("fig9, fig1, dcaa, agaa, memory"), std::string::npos) << r.output;
}

// A run's figures are one set: a run that fails on a later figure (here a scene that does not
// load, which fig9, animating the first scene only, never reads) leaves the previous run's files
// as they were, never its first figures beside them.
TEST(FiguresCli, ARunThatFailsOnALaterFigureLeavesThePreviousSet) {
  test::TempDir dir;
  test::write_text(dir.file("broken.obj"), "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  std::filesystem::create_directories(dir.file("out"));
  test::write_text(dir.file("out/fig9.csv"), "previous");
  const auto r = test::run_rsaa("figures --scenes builtin:edges," + dir.file("broken.obj") +
                                " --width 48 --height 36 --frames 2 --out-dir " + dir.file("out"));
  EXPECT_NE(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("broken.obj"), std::string::npos) << r.output;
  EXPECT_EQ(test::read_text(dir.file("out/fig9.csv")), "previous");
  for (const auto& entry : std::filesystem::directory_iterator(dir.file("out")))
    EXPECT_EQ(entry.path().filename().string(), "fig9.csv") << "left behind";
}

}  // namespace
}  // namespace rsaa
