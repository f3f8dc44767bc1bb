// Image channels read by layout, alpha composited over black, NaN/Inf never "equal", image
// budgets, and the bench's CSV read back (issue 15).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <OpenImageIO/imageio.h>

#include "core/util/atomic_file.h"
#include "core/util/colour.h"
#include "image/image_io.h"
#include "image/image_metrics.h"
#include "tests/test_util.h"
#include "tools/bench/bench.h"
#include "tools/bench/csv.h"

namespace rsaa {
namespace {

using test::TempDir;

// Writes a w x h 8-bit image with `channels` channels, alpha (if any) in `alpha`, all pixels `value`.
void write_8bit(const std::string& path, int channels, int alpha, const std::vector<std::uint8_t>& value) {
  auto out = OIIO::ImageOutput::create(path);
  OIIO::ImageSpec spec(3, 2, channels, OIIO::TypeDesc::UINT8);
  spec.alpha_channel = alpha;
  spec.attribute("oiio:UnassociatedAlpha", 1);  // store these values as they are
  std::vector<std::uint8_t> pixels;
  for (int i = 0; i < 6; ++i) pixels.insert(pixels.end(), value.begin(), value.end());
  ASSERT_TRUE(out && out->open(path, spec) && out->write_image(OIIO::TypeDesc::UINT8, pixels.data()) && out->close());
}

TEST(ImageLayout, GreyGreyAlphaRgbAndRgbaAreReadByTheirLayout) {
  TempDir dir;
  const float grey = srgb_to_linear(200 / 255.0f);
  write_8bit(dir.file("g.png"), 1, -1, {200});
  write_8bit(dir.file("ga.png"), 2, 1, {200, 255});
  write_8bit(dir.file("ga-half.png"), 2, 1, {200, 51});
  write_8bit(dir.file("rgb.png"), 3, -1, {200, 10, 90});
  write_8bit(dir.file("rgba.png"), 4, 3, {200, 10, 90, 0});
  for (const char* name : {"g.png", "ga.png"}) {
    const Rgb p = read_image(dir.file(name)).at(2, 1);
    EXPECT_FLOAT_EQ(p.r, grey) << name;
    EXPECT_FLOAT_EQ(p.g, grey) << name;  // not the alpha channel
    EXPECT_FLOAT_EQ(p.b, grey) << name;
  }
  // Straight alpha 0.2 over black: the linear colour times 0.2.
  const Rgb half = read_image(dir.file("ga-half.png")).at(0, 0);
  EXPECT_NEAR(half.r, grey * 0.2f, 1e-6f);
  EXPECT_NEAR(half.b, grey * 0.2f, 1e-6f);
  const Rgb rgb = read_image(dir.file("rgb.png")).at(1, 1);
  EXPECT_FLOAT_EQ(rgb.g, srgb_to_linear(10 / 255.0f));
  const Rgb transparent = read_image(dir.file("rgba.png")).at(1, 1);
  EXPECT_EQ(transparent.r + transparent.g + transparent.b, 0.0f);
  // Opaque 8-bit files are compared on their stored values.
  const DisplayImage d = read_display_image(dir.file("rgb.png"));
  EXPECT_EQ(d.rgb[0], 200);
  EXPECT_EQ(d.rgb[1], 10);
  EXPECT_EQ(d.rgb[2], 90);
  // Two channels that are not grey+alpha: refused, naming the layout.
  auto out = OIIO::ImageOutput::create(dir.file("rg.exr"));
  OIIO::ImageSpec spec(2, 2, 2, OIIO::TypeDesc::FLOAT);
  spec.channelnames = {"R", "G"};
  std::vector<float> rg(8, 0.5f);
  ASSERT_TRUE(out->open(dir.file("rg.exr"), spec) && out->write_image(OIIO::TypeDesc::FLOAT, rg.data()) && out->close());
  try {
    read_image(dir.file("rg.exr"));
    FAIL() << "a two-channel RG image was read";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("expected grey, grey+alpha, RGB or RGBA"), std::string::npos) << e.what();
  }
}

// A 61 x 47 8-bit RGB gradient, as OpenImageIO writes it to `path` (tiled 16 x 16 when `tiled`).
void write_gradient(const std::string& path, bool tiled) {
  constexpr int w = 61, h = 47;
  auto out = OIIO::ImageOutput::create(path);
  OIIO::ImageSpec spec(w, h, 3, OIIO::TypeDesc::UINT8);
  if (tiled) spec.tile_width = spec.tile_height = 16;
  std::vector<std::uint8_t> pixels;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      pixels.insert(pixels.end(), {std::uint8_t(x * 4), std::uint8_t(y * 5), std::uint8_t((x + y) * 2)});
  ASSERT_TRUE(out && out->open(path, spec) && out->write_image(OIIO::TypeDesc::UINT8, pixels.data()) && out->close())
      << path;
}

// Tiled files (TIFF, EXR, MIP-mapped .tx) are read by rows of tiles, partial tiles at the right and
// bottom included: OpenImageIO's scanline reader died of SIGFPE on them (compare, a model's texture).
TEST(ImageLayout, TiledFilesAreReadAsTheirScanlineTwins) {
  TempDir dir;
  write_gradient(dir.file("scan.png"), false);
  write_gradient(dir.file("tiled.tif"), true);
  const DisplayImage scan = read_display_image(dir.file("scan.png")), tiled = read_display_image(dir.file("tiled.tif"));
  ASSERT_EQ(tiled.width, 61);
  ASSERT_EQ(tiled.height, 47);
  EXPECT_EQ(tiled.rgb, scan.rgb);
}

// OpenImageIO's GIF reader gives four channels (R, G, B, "A") and alpha index 4, past the last:
// the alpha is found by its name (read at the index, every pixel was taken five channels apart).
TEST(ImageLayout, AnAlphaIndexPastTheChannelsIsFoundByName) {
  TempDir dir;
  write_8bit(dir.file("c.png"), 3, -1, {200, 10, 90});
  write_8bit(dir.file("c.gif"), 3, -1, {200, 10, 90});
  auto in = OIIO::ImageInput::open(dir.file("c.gif"));
  ASSERT_TRUE(in);
  EXPECT_GE(in->spec().alpha_channel, in->spec().nchannels) << "the reader this guards against is fixed";
  const Rgb png = read_image(dir.file("c.png")).at(2, 1), gif = read_image(dir.file("c.gif")).at(2, 1);
  EXPECT_FLOAT_EQ(gif.r, png.r);
  EXPECT_FLOAT_EQ(gif.g, png.g);
  EXPECT_FLOAT_EQ(gif.b, png.b);
}

TEST(ImageMetrics, NonFinitePixelsMakeEveryFigureUndefined) {
  Image nan(4, 4), black(4, 4);
  nan.at(1, 2).g = std::numeric_limits<float>::quiet_NaN();
  nan.at(3, 3).r = std::numeric_limits<float>::infinity();
  const DisplayImage dn = to_display(nan), db = to_display(black);
  EXPECT_EQ(dn.non_finite_pixels, 2u);
  const ImageComparison c = compare_images(dn, db);
  EXPECT_FALSE(c.defined());
  EXPECT_TRUE(std::isnan(c.psnr_db));
  EXPECT_TRUE(std::isnan(c.ssim));
  EXPECT_EQ(c.non_finite_a, 2u);
  EXPECT_TRUE(std::isinf(compare_images(db, db).psnr_db));  // equal finite images: +inf, as before
}

TEST(ImageBudget, DeclaredSizeIsCheckedBeforeDecoding) {
  TempDir dir;
  Image wide(64, 2);
  write_image(dir.file("wide.png"), wide);
  const ImageBudget tiny{1 << 20, 32, 1 << 20, "texture"};
  try {
    decode_image(dir.file("wide.png"), test::read_text(dir.file("wide.png")), tiny);
    FAIL() << "over the budget";
  } catch (const LimitError& e) {
    EXPECT_EQ(std::string(e.what()), dir.file("wide.png") +
                                         ": texture declares 64x2 pixels; the limit is 32 per side and 1048576 pixels");
  }
}

// The race between the check that log4cplus's threads can start and the load of the image module
// (another process of the user can take the room between them), made certain by a preloaded
// library under which every thread started during the load fails: log4cplus's static
// initialiser then calls std::terminate. The process ends with status 1 and says what failed
// and why, not "terminate called without an active exception".
TEST(ImageModule, ThreadsFailingWhileItLoadsEndTheProcessWithAMessage) {
  TempDir dir;
  Image black(4, 4);
  write_image(dir.file("black.png"), black);
  const test::CommandResult r = test::run_command("LD_PRELOAD=" + std::string(RSAA_THREADS_FAIL_PRELOAD) + " " +
                                                  RSAA_BINARY + " compare " + dir.file("black.png") + " " +
                                                  dir.file("black.png"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("rsaa: error: the process ended while loading the image module"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("log4cplus"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("ulimit"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("terminate called"), std::string::npos) << r.output;
}

TEST(BenchCsv, ThePlotReaderReadsTheBenchsOwnCsv) {
  bench::TechniqueResult r;
  r.scene = "a \"quoted\", scene";
  r.label = "rsaa 8x, sadp";
  r.frame_ms = 1.5;
  r.psnr_db = 31.25;
  r.pass_medians = {{"scene", 1.0, 0.9}, {"post", 0.5, 0.4}};
  TempDir dir;
  test::write_text(dir.file("bench.csv"), bench::results_csv({r, r}));
  const bench::CsvTable t = bench::read_csv(dir.file("bench.csv"));
  ASSERT_EQ(t.rows.size(), 2u);
  ASSERT_EQ(t.header.size(), t.rows[0].size());
  EXPECT_EQ(t.rows[1][1], "rsaa 8x, sadp");
  EXPECT_EQ(bench::csv_number(t, "bench.csv", 0, 4), 31.25);
  const std::string png = dir.file("plot.png");
  EXPECT_EQ(test::run_rsaa("plot " + dir.file("bench.csv") + " --x frame_ms --y psnr_db,ssim --out " + png).exit_code, 0);
}

}  // namespace
}  // namespace rsaa
