// rsaa render / compare as a user runs them: images written, and clear errors without partial
// output on bad input.
#include <gtest/gtest.h>

#include <filesystem>

#include <nlohmann/json.hpp>

#include "image/image_io.h"
#include "tests/test_util.h"

namespace rsaa {
namespace {

using test::run_rsaa;
using test::TempDir;

TEST(RenderCli, WritesPngAndExrAndComparesThem) {
  TempDir dir;
  const std::string size = " --width 64 --height 48 ";
  auto r = run_rsaa("render --technique rsaa --auth 1" + size + "--out " + dir.file("a.png"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("post-process"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("bytes/pixel"), std::string::npos) << r.output;
  r = run_rsaa("render --technique noaa" + size + "--out " + dir.file("b.exr"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Image a = read_image(dir.file("a.png"));
  EXPECT_EQ(a.width, 64);
  EXPECT_EQ(a.height, 48);

  r = run_rsaa("compare --json " + dir.file("a.png") + " " + dir.file("a.png"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(nlohmann::json::parse(r.output).at("psnr_db").is_null());
  EXPECT_EQ(nlohmann::json::parse(r.output).at("identical"), true);
  r = run_rsaa("compare --json " + dir.file("a.png") + " " + dir.file("b.exr"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto j = nlohmann::json::parse(r.output);
  EXPECT_GT(j.at("psnr_db").get<double>(), 15.0);
  EXPECT_LE(j.at("ssim").get<double>(), 1.0);
}

// RSAA says which pre-pass `auto` took on this driver and size: d3d8x's draws writing records,
// a cell pattern's one draw at its multiple of the image, and no line for techniques without a choice.
TEST(RenderCli, RsaaSaysWhichPrePassItTook) {
  TempDir dir;
  const std::string size = " --width 64 --height 48 --out " + dir.file("a.png");
  auto r = run_rsaa("render --technique rsaa" + size);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("pre-pass in use: records, 8 jittered draws"), std::string::npos) << r.output;
  r = run_rsaa("render --technique rsaa --table " + std::string(RSAA_SOURCE_DIR) + "/tables/custom-gl4x-tall.json" + size);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("pre-pass in use: msaa, one 4-sample draw at 1x2 cells (64x96)"), std::string::npos) << r.output;
  r = run_rsaa("render --technique msaa --samples 4" + size);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("pre-pass in use"), std::string::npos) << r.output;
}

TEST(RenderCli, BadInputFailsClearlyWithoutOutput) {
  TempDir dir;
  const std::string out = dir.file("out.png");
  test::write_text(dir.file("junk.obj"), "this is not a model\n\x01\x02\n");
  test::write_text(dir.file("empty.gltf"), "");
  struct Bad {
    std::string args, message;
  };
  for (const Bad& bad : std::vector<Bad>{
           {"--scene /no/such/model.obj", "'/no/such/model.obj': file not found"},
           {"--scene " + dir.path(), "is a directory"},
           {"--scene /usr/share/assimp/models/OBJ/testpoints.obj", "no triangles"},
           {"--scene " + dir.file("junk.obj"), "junk.obj"},
           {"--scene " + dir.file("empty.gltf"), "empty.gltf"},
           {"--scene builtin:nope", "unknown built-in scene 'builtin:nope'"},
           {"--camera 1,2,3", "expected ex,ey,ez,tx,ty,tz"},
           {"--camera 0,0,0,0,0,0", "eye equals target"},
           {"--camera 0,0,5,0,0,0,200", "fov"},
           {"--camera 0,0,5,0,0,x", "'x' is not a number"},
           {"--width 0 --height 24", "image size 0x24"},
           {"--width 32 --height 100000", "outside 1..8192"},
           {"--technique smaa", "unknown technique 'smaa'"},
           {"--technique rsaa --auth 3", "--auth"},
           {"--technique rsaa --samples 16", "--samples must be 4 or 8"},
           {"--technique rsaa --similarity normals", "--similarity"},
           {"--technique ssaa --samples 4", "8, 16 or 64"},
           {"--technique msaa --samples 8", "use ssaa --samples 8"},
           {"--technique dyncov --rules evict", "--rules must be seed or surface"},
           {"--technique rsaa --code-bits 12", "--code-bits"},
           {"--technique rsaa --material-edges yes", "--material-edges must be off or on, not 'yes'"},
           {"--technique rsaa --facet-edges yes", "--facet-edges must be off, on or auto, not 'yes'"},
           {"--technique rsaa --facet-edges on --material-edges off", "--facet-edges on needs --material-edges on"},
           {"--technique msaa --facet-edges on", "--facet-edges is an option of rsaa, not of msaa"},
           // Given, never ignored: an option of another technique, an empty value, a camera with a
           // trailing comma or in hexadecimal (each once taken without a word).
           {"--technique noaa --similarity bogus", "--similarity is an option of rsaa, not of noaa"},
           {"--technique msaa --z-prepass", "--z-prepass is an option of dcaa and dyncov, not of msaa"},
           {"--technique fxaa --kernel 2", "--kernel is an option of ssaa-filtered"},
           {"--technique rsaa --table ''", "--table: an empty value names nothing"},
           {"--camera ''", "--camera: an empty value names nothing"},
           {"--camera 1,2,3,0,0,0,", "--camera: '' is not a number"},
           {"--camera 0x10,2,3,0,0,0", "'0x10' is not a number"},
           {"--technique rsaa --z-prepass", "--z-prepass is an option of dcaa and dyncov, not of rsaa"},
       }) {
    const std::string size = bad.args.find("--width") == std::string::npos ? "--width 32 --height 24 " : "";
    const auto r = run_rsaa("render " + size + bad.args + " --out " + out);
    EXPECT_NE(r.exit_code, 0) << bad.args;
    EXPECT_NE(r.output.find(bad.message), std::string::npos) << bad.args << "\n" << r.output;
    EXPECT_FALSE(std::filesystem::exists(out)) << bad.args;
  }
  auto r = run_rsaa("render --width 8 --height 8 --out /no/such/dir/x.png");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("/no/such/dir/x.png"), std::string::npos) << r.output;
  r = run_rsaa("render --width 8 --height 8 --out " + dir.file("x.unknownext"));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 2);  // inputs only
}

// A texture that is missing, a directory or cannot be decoded leaves the material's colour (the
// geometry is still worth drawing), and says so: it used to be dropped without a word.
TEST(RenderCli, AModelsMissingOrBrokenTextureIsSaid) {
  TempDir dir;
  test::write_text(dir.file("m.obj"), "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl a\nf 1/1 2/2 3/3\n");
  test::write_text(dir.file("m.mtl"), "newmtl a\nKd 1 0 0\nmap_Kd t.png\n");
  auto r = run_rsaa("render --scene " + dir.file("m.obj") + " --width 32 --height 24 --out " + dir.file("a.png"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("warning: model '" + dir.file("m.obj") + "': texture '" + dir.file("t.png") + "' not found"),
            std::string::npos)
      << r.output;
  test::write_text(dir.file("t.png"), "not a PNG");
  r = run_rsaa("render --scene " + dir.file("m.obj") + " --width 32 --height 24 --out " + dir.file("b.png"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("texture not used (" + dir.file("t.png")), std::string::npos) << r.output;
  // A texture name that resolves to a directory names no image: the same (it refused the model).
  test::write_text(dir.file("m.mtl"), "newmtl a\nKd 1 0 0\nmap_Kd sub/\n");
  std::filesystem::create_directory(dir.file("sub"));
  r = run_rsaa("render --scene " + dir.file("m.obj") + " --width 32 --height 24 --out " + dir.file("c.png"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("is a directory; drawn in its material's colour"), std::string::npos) << r.output;
  // An empty texture name is no texture (MD5's `shader ""`, which resolved to the model's
  // directory and refused the model); nothing to say.
  const std::string md5 = "/usr/share/assimp/models/MD5/SimpleCube.md5mesh";
  if (!std::filesystem::exists(md5)) GTEST_SKIP() << md5 << " (assimp-testmodels) is not installed";
  r = run_rsaa("render --scene " + md5 + " --width 32 --height 24 --out " + dir.file("d.png"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("texture"), std::string::npos) << r.output;
}

// Vertex colours are reflectances, as material colours: clamped to [0, 1]. A colour of -5 gave
// negative linear pixels and one of 1e38 the half float's largest value, without a word.
TEST(RenderCli, VertexColoursOutsideZeroToOneAreClamped) {
  TempDir dir;
  for (const char* colour : {"-5 -5 -5", "1e38 1e38 1e38"}) {
    SCOPED_TRACE(colour);
    std::string obj;
    for (const char* corner : {"0 0 0", "1 0 0", "0 1 0", "1 1 0"}) obj += std::string("v ") + corner + " " + colour + "\n";
    test::write_text(dir.file("m.obj"), obj + "f 1 2 3\nf 2 4 3\n");
    const auto r = run_rsaa("render --scene " + dir.file("m.obj") + " --width 32 --height 24 --out " + dir.file("m.exr"));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const Image image = read_image(dir.file("m.exr"));
    float lowest = 0.0f, highest = 0.0f;
    for (const Rgb& p : image.pixels)
      for (const float c : {p.r, p.g, p.b}) lowest = std::min(lowest, c), highest = std::max(highest, c);
    EXPECT_GE(lowest, 0.0f);
    EXPECT_LE(highest, 2.0f);  // white lit by the scene's light and highlight
  }
}

// Two-sided shading turns a triangle's normals once per triangle (scene_normal_side.glsl): a quad
// facing the eye whose smooth normals turn away from it towards one side is shaded smoothly
// across. Turned per fragment by the interpolated normal, as it was, the light jumped where that
// normal crossed the view plane: a hard line inside one surface (seen on a box with averaged
// normals and on character models). And a quad seen from its back (normals away from the eye) is
// shaded as its front.
TEST(RenderCli, TwoSidedShadingIsContinuousAcrossATriangle) {
  TempDir dir;
  const auto quad = [&](const std::string& name, const char* left_normal, const char* right_normal) {
    test::write_text(dir.file(name), std::string("v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvn ") + left_normal +
                                         "\nvn " + right_normal + "\nf 1//1 2//2 3//2\nf 1//1 3//2 4//1\n");
    const auto r = run_rsaa("render --scene " + dir.file(name) + " --camera 0,0,3,0,0,0,60 --width 64 --height 48 --out " +
                            dir.file(name + ".exr"));
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return read_image(dir.file(name + ".exr"));
  };
  // Left edge's normal 107 degrees from the eye, the right edge's towards it.
  const Image turning = quad("turning.obj", "-1 0 -0.3", "0 0 1");
  const Rgb background = turning.at(0, 0);
  const auto luminance = [](const Rgb& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; };
  float largest_step = 0.0f;
  int inside = 0;
  for (int x = 1; x < turning.width; ++x) {
    const Rgb a = turning.at(x - 1, 24), b = turning.at(x, 24);
    if (a.r == background.r || b.r == background.r) continue;
    ++inside;
    largest_step = std::max(largest_step, std::abs(luminance(a) - luminance(b)));
  }
  EXPECT_GT(inside, 20);
  EXPECT_LT(largest_step, 0.05f) << "a jump of the light inside the quad";
  const Image front = quad("front.obj", "0 0 1", "0 0 1"), back = quad("back.obj", "0 0 -1", "0 0 -1");
  ASSERT_EQ(front.pixels.size(), back.pixels.size());
  int differing = 0;
  for (std::size_t p = 0; p < front.pixels.size(); ++p)
    differing += front.pixels[p].r != back.pixels[p].r || front.pixels[p].g != back.pixels[p].g ||
                 front.pixels[p].b != back.pixels[p].b;
  EXPECT_EQ(differing, 0);
}

TEST(CompareCli, RejectsMissingAndMismatchedImages) {
  TempDir dir;
  ASSERT_EQ(run_rsaa("render --width 16 --height 16 --out " + dir.file("a.png")).exit_code, 0);
  ASSERT_EQ(run_rsaa("render --width 16 --height 8 --out " + dir.file("b.png")).exit_code, 0);
  auto r = run_rsaa("compare " + dir.file("a.png") + " " + dir.file("b.png"));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find(dir.file("a.png") + " is 16x16, " + dir.file("b.png") + " 16x8"), std::string::npos)
      << r.output;
  // An EXR whose data window is moved off the origin, or smaller than its display window: read
  // as a grid from 0,0 it would compare shifted, so it is refused, named.
  ASSERT_EQ(run_rsaa("render --width 16 --height 16 --out " + dir.file("a.exr")).exit_code, 0);
  for (const char* window : {"--origin +5+5", "--fullsize 20x20"}) {
    ASSERT_EQ(test::run_command("oiiotool " + dir.file("a.exr") + " " + window + " -o " + dir.file("w.exr")).exit_code, 0);
    r = run_rsaa("compare " + dir.file("w.exr") + " " + dir.file("a.exr"));
    EXPECT_NE(r.exit_code, 0) << window;
    EXPECT_NE(r.output.find(dir.file("w.exr") + ": its data window"), std::string::npos) << window << r.output;
  }
  r = run_rsaa("compare " + dir.file("a.png") + " " + dir.file("missing.png"));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("missing.png"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace rsaa

namespace rsaa {
namespace {

// The window under Xvfb: switch technique with keys, screenshot the window, and find exactly
// what `rsaa render` makes headless.
TEST(ViewCli, SwitchesTechniquesAndTakesScreenshotsUnderXvfb) {
  TempDir dir;
  const std::string size = " --width 96 --height 72 ";
  const auto r = test::run_command("xvfb-run -a -s '-screen 0 640x480x24' " + std::string(RSAA_BINARY) +
                                   " view" + size + "--keys '6P1P7P8P9PQ' --screenshot " +
                                   dir.file("shot-%d.png"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("screenshot " + dir.file("shot-2.png") + ": noaa"), std::string::npos) << r.output;
  const std::pair<const char*, const char*> expected[] = {
      {"shot-1.png", "--technique rsaa --samples 8"},
      {"shot-2.png", "--technique noaa"},
      {"shot-3.png", "--technique rsaa --samples 4"},
      {"shot-4.png", "--technique dcaa"},
      {"shot-5.png", "--technique dyncov"}};
  for (const auto& [shot, technique] : expected) {
    ASSERT_TRUE(std::filesystem::exists(dir.file(shot))) << shot << "\n" << r.output;
    ASSERT_EQ(run_rsaa(std::string("render ") + technique + size + "--out " + dir.file("headless.png")).exit_code, 0);
    const auto c = run_rsaa("compare --json " + dir.file(shot) + " " + dir.file("headless.png"));
    ASSERT_EQ(c.exit_code, 0) << c.output;
    EXPECT_EQ(nlohmann::json::parse(c.output).at("identical"), true) << shot;
  }
  // Started on a technique without facet edges, then switched to rsaa's defaults (which draw with
  // them): the scene is uploaded again with its facets on the switch, not before.
  const auto from_noaa = test::run_command("xvfb-run -a -s '-screen 0 640x480x24' " + std::string(RSAA_BINARY) +
                                           " view --technique noaa" + size + "--keys '6PQ' --screenshot " +
                                           dir.file("from-noaa-%d.png"));
  ASSERT_EQ(from_noaa.exit_code, 0) << from_noaa.output;
  const std::size_t facets = from_noaa.output.find("finding the scene's facets");
  ASSERT_NE(facets, std::string::npos) << from_noaa.output;
  EXPECT_GT(facets, from_noaa.output.find("showing noaa")) << from_noaa.output;
  ASSERT_EQ(run_rsaa("render --technique rsaa --samples 8" + size + "--out " + dir.file("headless.png")).exit_code, 0);
  const auto c = run_rsaa("compare --json " + dir.file("from-noaa-1.png") + " " + dir.file("headless.png"));
  ASSERT_EQ(c.exit_code, 0) << c.output;
  EXPECT_EQ(nlohmann::json::parse(c.output).at("identical"), true);
  const auto bad = test::run_command("xvfb-run -a " + std::string(RSAA_BINARY) + " view --keys '6#'");
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_NE(bad.output.find("no key '#'"), std::string::npos) << bad.output;
}

}  // namespace
}  // namespace rsaa
