// The bench's measurements and output formats on a tiny run (timings are never asserted).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>

#include <nlohmann/json.hpp>

#include "runtime/gl_context.h"
#include "tests/test_util.h"
#include "tools/bench/bench.h"
#include "tools/bench/chart.h"
#include "tools/bench/copy_pass.h"
#include "tools/bench/growth.h"
#include "runtime/pass_timer.h"
#include "runtime/render.h"
#include "runtime/scene.h"
#include "image/image_metrics.h"
#include "image/image_io.h"
#include "core/reference/scene_shading.h"

namespace rsaa {
namespace {

bench::TechniqueResult row(const std::string& scene, const std::string& label, double ratio, double psnr) {
  bench::TechniqueResult r;
  r.scene = scene;
  r.label = label;
  r.frame_ratio = ratio;
  r.psnr_db = psnr;
  return r;
}

TEST(Bench, ParetoFrontAndCheapestTechnique) {
  std::vector<bench::TechniqueResult> r = {row("a", "noaa", 1.0, 30), row("a", "fast good", 1.5, 38),
                                           row("a", "slow worse", 2.0, 36), row("a", "slow best", 8.0, 45),
                                           row("b", "other scene", 9.0, 20)};
  bench::mark_pareto(r);
  EXPECT_TRUE(r[0].pareto);
  EXPECT_TRUE(r[1].pareto);
  EXPECT_FALSE(r[2].pareto);  // dominated by "fast good"
  EXPECT_TRUE(r[3].pareto);
  EXPECT_TRUE(r[4].pareto);   // alone in its scene
  EXPECT_EQ(bench::cheapest_reaching(r, "a", 37.0)->label, "fast good");
  EXPECT_EQ(bench::cheapest_reaching(r, "a", 50.0), nullptr);
}

// The report sets what each RSAA row adds to no AA's frame against what 4x MSAA adds (the issue's
// cost goals are those multiples), per scene, and says nothing where a scene lacks either baseline.
TEST(Bench, ReportsRsaasAddedCostAsAMultipleOfMsaas) {
  std::vector<bench::TechniqueResult> r = {row("a", "noaa", 1.0, 30), row("a", "msaa 4x", 2.0, 40),
                                           row("a", "rsaa 8x", 3.0, 41), row("b", "rsaa 8x", 3.0, 41),
                                           row("c", "noaa", 1.0, 30), row("c", "msaa 4x", 1.0, 40),
                                           row("c", "rsaa 8x", 1.0, 41)};
  const double frames[] = {10.0, 30.0, 50.0, 50.0, 10.0, 9.0, 12.0};
  for (std::size_t i = 0; i < r.size(); ++i) r[i].frame_ms = frames[i];
  r[2].options = r[3].options = r[6].options = technique_options("rsaa", 8);
  const std::string report = bench::results_markdown(bench::BenchOptions{}, r);
  const std::size_t from = report.find("Added cost"), to = report.find("Per scene:");
  ASSERT_LT(from, to) << report;
  const std::string added = report.substr(from, to - from);
  EXPECT_NE(added.find("| a | rsaa 8x | 40.0 | 20.0 | 2.00x |"), std::string::npos) << added;
  EXPECT_EQ(added.find("| b |"), std::string::npos) << added;  // no baselines in scene b
  // 4x MSAA measured no dearer than no AA (noise at tiny sizes): the row stays, without a multiple.
  EXPECT_NE(added.find("| c | rsaa 8x | 2.0 | -1.0 | - |"), std::string::npos) << added;
  // Rows without paired baselines (a file from before timing in rounds) say where the numbers come from.
  EXPECT_NE(added.find("from the noaa and msaa 4x rows"), std::string::npos) << added;
  EXPECT_NE(report.find("one technique after another"), std::string::npos) << report;
  // The baselines' frames timed in the RSAA row's own rounds decide where a run has them.
  r[2].paired_noaa_ms = 20.0, r[2].paired_msaa_ms = 60.0;
  r[6].paired_noaa_ms = 10.0, r[6].paired_msaa_ms = 9.0;
  const std::string paired = bench::results_markdown(bench::BenchOptions{}, r);
  EXPECT_NE(paired.find("| a | rsaa 8x | 30.0 | 40.0 | 0.75x |"), std::string::npos) << paired;
  EXPECT_NE(paired.find("timed in the same rounds as the RSAA row's"), std::string::npos) << paired;
  EXPECT_NE(paired.find("in rounds with no AA's frames"), std::string::npos) << paired;
}

// A technique for the timing rounds: renders nothing, logs its name, times one pass.
class LoggedTechnique : public Technique {
 public:
  LoggedTechnique(std::string name, std::vector<std::string>& log) : name_(std::move(name)), log_(log) {}
  void render(const GpuScene&, const View&, GLuint) override {
    timer_.begin(name_);
    timer_.end();
    log_.push_back(name_);
  }
  double bytes_per_pixel() const override { return 0.0; }

 private:
  std::string name_;
  std::vector<std::string>& log_;
};

// Timing in rounds: a warm-up frame of each technique, then every technique one frame a round,
// the order rotated by one each round; one timing per technique, in order, its own pass.
TEST(Bench, TimingRoundsInterleaveTheTechniquesFrames) {
  gl::HeadlessContext context;
  std::vector<std::string> log;
  LoggedTechnique a("a", log), b("b", log), c("c", log);
  const GpuScene scene(load_scene("builtin:edges"));
  const View view = make_view(choose_camera(load_scene("builtin:edges"), std::nullopt), 16, 12);
  const gl::Texture output = gl::make_texture_2d(GL_RGBA16F, 16, 12);
  bench::CopyPass copy(16, 12);
  const std::vector<bench::FrameTiming> timings = bench::time_rounds({&a, &b, &c}, scene, view, output.get(), 3, copy);
  EXPECT_EQ(log, (std::vector<std::string>{"a", "b", "c", "a", "b", "c", "b", "c", "a", "c", "a", "b"}));
  ASSERT_EQ(timings.size(), 3u);
  const char* names[] = {"a", "b", "c"};
  for (std::size_t i = 0; i < 3; ++i) {
    ASSERT_EQ(timings[i].pass_medians.size(), 1u);
    EXPECT_EQ(timings[i].pass_medians[0].pass, names[i]);
    EXPECT_GT(timings[i].copy_ms, 0.0);
  }
}

TEST(Bench, TinyRunWritesWellFormedResults) {
  gl::HeadlessContext context;
  bench::BenchOptions o;
  o.scenes = {"builtin:edges"};
  o.techniques = {technique_options("noaa"), technique_options("fxaa"), technique_options("msaa", 4),
                  technique_options("ssaa", 8), technique_options("ssaa", 16), technique_options("rsaa", 8)};
  o.width = 48, o.height = 36, o.frames = 2, o.orbit_frames = 2;
  test::TempDir crops;
  o.crops_dir = crops.path();
  const auto results = bench::run_bench(o, nullptr);
  ASSERT_EQ(results.size(), 6u);
  EXPECT_DOUBLE_EQ(results[0].frame_ratio, 1.0);
  for (const auto& r : results) {
    // No AA's and 4x MSAA's frames timed in every row's rounds; the ratio is against no AA's.
    EXPECT_GT(r.paired_noaa_ms, 0.0) << r.label;
    EXPECT_GT(r.paired_msaa_ms, 0.0) << r.label;
    EXPECT_DOUBLE_EQ(r.frame_ratio, r.frame_ms / r.paired_noaa_ms) << r.label;
    EXPECT_GT(r.psnr_db, 10.0) << r.label;
    EXPECT_LE(r.psnr_db, 99.0) << r.label;
    EXPECT_GT(r.flicker_psnr_db, 0.0) << r.label;
    EXPECT_GT(r.bytes_per_pixel, 0.0) << r.label;
    EXPECT_FALSE(r.pass_medians.empty()) << r.label;
    EXPECT_GT(r.copy_ms, 0.0) << r.label;
  }
  EXPECT_GT(results[4].psnr_db, results[0].psnr_db);  // ssaa 16x beats no AA
  EXPECT_GT(std::filesystem::file_size(crops.file("crops-edges.png")), 1000u);

  const auto json = nlohmann::json::parse(bench::results_json(o, results));
  EXPECT_EQ(json.at("format"), "rsaa-bench");
  ASSERT_EQ(json.at("results").size(), 6u);
  for (const char* key : {"scene", "technique", "passes", "frame_ms", "frame_ratio_to_noaa", "paired_noaa_ms",
                          "paired_msaa_4x_ms", "psnr_db", "ssim", "luma_error_share_percent", "orbit_psnr_db",
                          "flicker_psnr_db", "bytes_per_pixel", "pareto"})
    EXPECT_TRUE(json["results"][0].contains(key)) << key;
  for (const auto& pass : json["results"][1].at("passes"))
    EXPECT_DOUBLE_EQ(pass.at("copy_multiple").get<double>(),
                     pass.at("wall_ms").get<double>() / results[1].copy_ms);
  std::istringstream csv(bench::results_csv(results));
  std::string line;
  int lines = 0;
  std::getline(csv, line);
  EXPECT_EQ(line.rfind("scene,technique,frame_ms,", 0), 0u);
  while (std::getline(csv, line)) ++lines;
  EXPECT_EQ(lines, 6);

  test::TempDir dir;
  test::write_text(dir.file("bench.json"), bench::results_json(o, results));
  bench::BenchOptions read_options;
  const auto back = bench::read_results_json(dir.file("bench.json"), read_options);
  ASSERT_EQ(back.size(), results.size());
  EXPECT_EQ(back[5].options.technique, "rsaa");
  EXPECT_EQ(bench::results_json(read_options, back), bench::results_json(o, results));
  const std::string report = bench::results_markdown(o, results);
  // The Pareto marks follow the results (which rows are on the front depends on timings at this
  // size; the highest PSNR, 16x supersampling's, always is).
  EXPECT_TRUE(results[4].pareto);
  for (const auto& r : results)
    EXPECT_NE(report.find("| edges | " + std::string(r.pareto ? "* " : "") + r.label + " |"), std::string::npos)
        << r.label << "\n" << report;
  EXPECT_NE(report.find("RSAA 8x - 4x"), std::string::npos);
  EXPECT_NE(report.find("| edges | fxaa | "), std::string::npos) << report;  // the per-pass table
  test::write_text(dir.file("broken.json"), "{\"format\": \"rsaa-bench\"}");
  EXPECT_THROW(bench::read_results_json(dir.file("broken.json"), read_options), std::runtime_error);
  // A hand-edited measurement outside what a run can give (a PSNR of -3e9 hung the Pareto plot's
  // grid) is refused, naming the entry and the field; the file as written reads back.
  const std::vector<std::pair<std::string, nlohmann::json>> edits = {
      {"psnr_db", -3e9},          {"psnr_db", 2147483646.0}, {"psnr_db", nullptr},         {"frame_ms", -1.0},
      {"frame_ratio_to_noaa", -5.0}, {"frame_ratio_to_noaa", 1e300}, {"ssim", 2.0},          {"orbit_psnr_db", "40"},
      {"flicker_psnr_db", 1e10},  {"luma_error_share_percent", 101.0}, {"bytes_per_pixel", -8.0}, {"copy_ms", 1e300},
      {"paired_noaa_ms", -1.0},   {"paired_msaa_4x_ms", "12"}};
  for (const auto& [field, value] : edits) {
    nlohmann::json edited = json;
    edited["results"][3][field] = value;
    test::write_text(dir.file("edited.json"), edited.dump());
    try {
      bench::read_results_json(dir.file("edited.json"), read_options);
      ADD_FAILURE() << field << " = " << value.dump() << " was read";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("results[3]." + field), std::string::npos) << e.what();
    }
  }
  // Another layout's version (or none) is refused, naming it: fields may change meaning.
  for (const nlohmann::json& version : {nlohmann::json(999), nlohmann::json("abc"), nlohmann::json()}) {
    nlohmann::json other = json;
    if (version.is_null()) other.erase("version");
    else other["version"] = version;
    test::write_text(dir.file("other.json"), other.dump());
    try {
      bench::read_results_json(dir.file("other.json"), read_options);
      ADD_FAILURE() << "version " << version.dump() << " was read";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("this build reads version 1"), std::string::npos) << e.what();
    }
  }
  // A '|' in a scene's name is escaped in the report's tables, not a cell of its own.
  auto piped = results;
  for (auto& r : piped) r.scene = "pipe/a|b.obj";
  const std::string piped_report = bench::results_markdown(o, piped);
  EXPECT_NE(piped_report.find("| a\\|b | "), std::string::npos) << piped_report;
  EXPECT_EQ(piped_report.find("| a|b | "), std::string::npos) << piped_report;
  nlohmann::json edited = json;
  edited["results"][1]["passes"][0]["wall_ms"] = -2.0;
  test::write_text(dir.file("edited.json"), edited.dump());
  EXPECT_THROW(bench::read_results_json(dir.file("edited.json"), read_options), std::runtime_error);
  bench::plot_pareto(results, results[0].scene, dir.file("pareto.png"));
  bench::plot_pass_times(results, results[0].scene, dir.file("passes.png"));
  EXPECT_GT(std::filesystem::file_size(dir.file("pareto.png")), 1000u);
  EXPECT_GT(std::filesystem::file_size(dir.file("passes.png")), 1000u);
}

// A timer query longer than the wall clock around the same work cannot be right (llvmpipe answers
// a query begun before a frame's compute dispatches with its clock since boot): reported as
// kNoTimerQuery, "n/a" on the command line and null in bench.json, never as a time.
TEST(Bench, ImplausibleTimerQueriesAreNotReportedAsTimes) {
  EXPECT_EQ(plausible_timer_query(12.5, 14.0), 12.5);
  EXPECT_EQ(plausible_timer_query(0.0, 14.0), 0.0);
  EXPECT_EQ(plausible_timer_query(28.0, 14.0), 28.0);  // within the slack
  EXPECT_EQ(plausible_timer_query(54134627.27, 14.27), kNoTimerQuery);
  EXPECT_EQ(plausible_timer_query(-3.0, 14.0), kNoTimerQuery);
  EXPECT_EQ(plausible_timer_query(std::nan(""), 14.0), kNoTimerQuery);
  EXPECT_EQ(plausible_timer_query(std::numeric_limits<double>::infinity(), 14.0), kNoTimerQuery);
}

TEST(Bench, CopyPassCopiesTheFrame) {
  // The speed of light is only honest if the pass really reads and writes every pixel.
  gl::HeadlessContext context;
  const int w = 5, h = 3;
  std::vector<float> texels;
  for (int i = 0; i < w * h; ++i) texels.insert(texels.end(), {(i % w) / 4.0f, (i / w) / 2.0f, 0.25f, 1.0f});
  const gl::Texture source = gl::make_texture_2d(GL_RGBA16F, w, h);
  glTextureSubImage2D(source.get(), 0, 0, 0, w, h, GL_RGBA, GL_FLOAT, texels.data());
  bench::CopyPass copy(w, h);
  EXPECT_GE(copy.time_ms(source.get()), 0.0);
  std::vector<float> out(texels.size());
  glGetTextureImage(copy.target(), 0, GL_RGBA, GL_FLOAT, GLsizei(out.size() * sizeof(float)), out.data());
  for (std::size_t i = 0; i < out.size(); ++i) EXPECT_NEAR(out[i], texels[i], 0.51 / 255.0) << i;  // 8-bit rounding
}

TEST(BenchGrowth, SubdividingChangesTheTriangleCountNotTheImage) {
  gl::HeadlessContext context;
  const Scene scene = load_scene("builtin:default");
  const Scene split = bench::subdivide(scene, 2);
  EXPECT_EQ(split.triangle_count(), 16 * scene.triangle_count());
  EXPECT_EQ(split.draws.size(), scene.draws.size());
  const Camera camera = choose_camera(scene, std::nullopt);
  const auto render = [&](const Scene& s) {
    const GpuScene gpu(s);
    return to_display(render_frame(gpu, camera, technique_options("noaa"), 160, 120));
  };
  // Only rasterisation of the new inner edges and float rounding may differ.
  EXPECT_GT(compare_images(render(split), render(scene)).psnr_db, 40.0);
}

TEST(BenchGrowth, SlopesOfKnownPoints) {
  bench::GrowthResults r;
  for (int side : {100, 200, 400}) {  // frame ms = 2 + 3 ms per megapixel; and proportional to triangles
    bench::GrowthPoint p;
    p.label = "t";
    p.width = side, p.height = side;
    p.frame_ms = 2.0 + 3.0 * side * side / 1e6;
    r.points.push_back(p);
    p.axis = bench::GrowthAxis::Triangles;
    p.triangles = std::size_t(side) * 1000;
    p.frame_ms = 0.5 * side;
    r.points.push_back(p);
  }
  const auto slopes = bench::growth_slopes(r);
  ASSERT_EQ(slopes.size(), 2u);
  EXPECT_EQ(slopes[0].axis, bench::GrowthAxis::Pixels);
  EXPECT_NEAR(slopes[0].ms_per_unit, 3.0, 1e-9);
  EXPECT_LT(slopes[0].exponent, 1.0);  // the constant 2 ms makes it sub-linear
  EXPECT_NEAR(slopes[1].exponent, 1.0, 1e-9);
  EXPECT_NEAR(slopes[1].ms_per_unit, 0.5 * 100, 1e-9);  // per 100k triangles
}

TEST(BenchGrowth, LightCrossingIsWhereTheCheaperLineStartsBelow) {
  // a = 10 + N ms, b = 3N ms: a is cheaper from N = 5 on (fitted), first measured at N = 8.
  const std::string rsaa8 = technique_label(technique_options("rsaa", 8));
  bench::GrowthResults r;
  for (int n : {1, 2, 4, 8, 16}) {
    bench::GrowthPoint p;
    p.axis = bench::GrowthAxis::Lights;
    p.lights = n;
    p.label = rsaa8, p.frame_ms = 10.0 + n;
    r.points.push_back(p);
    p.label = "msaa 4x", p.frame_ms = 3.0 * n;
    r.points.push_back(p);
  }
  const bench::LightCrossing x = bench::light_crossing(r, rsaa8, "msaa 4x");
  EXPECT_EQ(x.measured, 8);
  EXPECT_NEAR(x.fitted, 5.0, 1e-9);
  const bench::LightCrossing never = bench::light_crossing(r, "msaa 4x", rsaa8);
  EXPECT_EQ(never.measured, 1);  // msaa is cheaper at N = 1 ...
  EXPECT_EQ(never.fitted, 0.0);  // ... but its line grows faster: not for large N
  // Only the pairs whose both techniques were measured are reported (no ssaa 8x, no RSAA 4x here).
  const auto crossings = bench::light_crossings(r);
  ASSERT_EQ(crossings.size(), 1u);
  EXPECT_EQ(crossings[0].b, "msaa 4x");
  // The --table row (a cell or union pattern) is set against 4x MSAA as well, once.
  for (int n : {1, 2, 4, 8, 16}) {
    bench::GrowthPoint p;
    p.axis = bench::GrowthAxis::Lights;
    p.lights = n;
    p.label = "rsaa table custom-gl4x-tall", p.frame_ms = 6.0 + n;
    r.points.push_back(p);
  }
  const auto with_table = bench::light_crossings(r);
  ASSERT_EQ(with_table.size(), 2u);
  EXPECT_EQ(with_table[1].a, "rsaa table custom-gl4x-tall");
  EXPECT_EQ(with_table[1].b, "msaa 4x");
  EXPECT_NEAR(with_table[1].fitted, 3.0, 1e-9);  // 6 + N = 3N
}

TEST(BenchGrowth, TinyRunWritesEveryPoint) {
  gl::HeadlessContext context;
  bench::GrowthOptions o;
  o.scene = "builtin:edges";
  o.techniques = {technique_options("noaa"), technique_options("rsaa", 8)};
  o.sizes = {{32, 24}, {64, 48}};
  o.subdivision_levels = {0, 1};
  o.width = 32, o.height = 24, o.frames = 1;
  const auto r = bench::run_growth(o, nullptr);
  ASSERT_EQ(r.points.size(), 8u);
  EXPECT_EQ(r.points[5].triangles, r.base_triangles);
  EXPECT_EQ(r.points[7].triangles, 4 * r.base_triangles);
  for (const auto& p : r.points) EXPECT_GT(p.frame_ms, 0.0) << p.label;
  const auto json = nlohmann::json::parse(bench::growth_json(o, r));
  EXPECT_EQ(json.at("points").size(), 8u);
  EXPECT_EQ(json.at("slopes").size(), 4u);
  const std::string md = bench::growth_markdown(o, r);
  EXPECT_NE(md.find("| " + technique_label(o.techniques[1]) + " |"), std::string::npos) << md;
  test::TempDir dir;
  bench::plot_growth(r, bench::GrowthAxis::Pixels, dir.file("pixels.png"));
  bench::plot_growth(r, bench::GrowthAxis::Triangles, dir.file("triangles.png"));
  EXPECT_GT(std::filesystem::file_size(dir.file("pixels.png")), 1000u);
  EXPECT_GT(std::filesystem::file_size(dir.file("triangles.png")), 1000u);

  // More techniques than one round makes at once: timed in groups, each with the baselines; every
  // technique's point once, in the techniques' order.
  o.techniques = {technique_options("noaa"),    technique_options("fxaa"),      technique_options("msaa", 4),
                  technique_options("ssaa", 8), technique_options("rsaa", 4),   technique_options("rsaa", 8),
                  technique_options("agaa", 4), technique_options("ssaa", 16)};
  o.sizes = {{16, 12}};
  o.subdivision_levels = {};
  o.light_counts = {};
  const auto grouped = bench::run_growth(o, nullptr);
  ASSERT_EQ(grouped.points.size(), o.techniques.size());
  for (std::size_t i = 0; i < o.techniques.size(); ++i) {
    EXPECT_EQ(grouped.points[i].label, technique_label(o.techniques[i]));
    EXPECT_GT(grouped.points[i].frame_ms, 0.0) << grouped.points[i].label;
    EXPECT_EQ(grouped.points[i].width, 16);
  }
}

TEST(BenchLights, PointLightsShadeAsTheCpuTwin) {
  // A grey square facing the camera; the centre pixel sees its centre, view position (0, 0, -5).
  gl::HeadlessContext context;
  Scene scene;
  scene.name = "square";
  for (const auto& [x, y] : std::vector<std::pair<float, float>>{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) {
    SceneVertex v;
    v.position = {x, y, 0.0f};
    v.normal = {0.0f, 0.0f, 1.0f};
    v.albedo = glm::vec3(0.5f);
    scene.vertices.push_back(v);
  }
  scene.indices = {0, 1, 2, 0, 2, 3};
  scene.draws = {{0, 6, -1}};
  Camera camera;  // at (0, 0, 5), looking at the origin
  scene.camera = camera;
  const Scene lit = bench::with_lights(scene, camera, 4);
  ASSERT_EQ(lit.point_lights.size(), 3u);
  const auto centre = [&](const Scene& s) {
    const GpuScene gpu(s);
    return render_frame(gpu, camera, technique_options("noaa"), 33, 33).at(16, 16);
  };
  const Rgb one = centre(scene), four = centre(lit);
  const Rgb cpu_one = shade_surface({0.5f, 0.5f, 0.5f}, {0, 0, 1}, {0, 0, -5}, kSceneSpecularExponent,
                                    kSceneSpecularScale);
  const Rgb cpu_four = shade_surface({0.5f, 0.5f, 0.5f}, {0, 0, 1}, {0, 0, -5}, kSceneSpecularExponent,
                                     kSceneSpecularScale, 1.0f, lit.point_lights);
  EXPECT_GT(cpu_four.r, cpu_one.r + 0.05f);  // the point lights reach the square
  for (const auto& [gl_value, cpu_value] : {std::pair{one.r, cpu_one.r}, {one.b, cpu_one.b}, {four.r, cpu_four.r},
                                            {four.g, cpu_four.g}, {four.b, cpu_four.b}})
    EXPECT_NEAR(gl_value, cpu_value, 2e-3 * (1.0f + cpu_value));  // RGBA16F
}

TEST(Bench, CropsShowTheRegionWhereTheFirstImageIsWrong) {
  DisplayImage reference{64, 48, std::vector<std::uint8_t>(64 * 48 * 3, 128)};
  DisplayImage wrong = reference;
  for (int y = 30; y < 34; ++y)
    for (int x = 40; x < 44; ++x) wrong.rgb[(y * 64 + x) * 3] = 255, wrong.rgb[(y * 64 + x) * 3 + 1] = 0;
  test::TempDir dir;
  bench::plot_crops({{"wrong", wrong}, {"right", reference}}, reference, dir.file("crops.png"));
  const DisplayImage canvas = read_display_image(dir.file("crops.png"));
  int red = 0;
  for (std::size_t i = 0; i < canvas.rgb.size(); i += 3) red += canvas.rgb[i] == 255 && canvas.rgb[i + 1] == 0;
  // The 4x4 square appears once, magnified 360 / 16 = 22 times in each direction.
  EXPECT_EQ(red, 4 * 4 * 22 * 22);
  EXPECT_THROW(bench::plot_crops({{"small", DisplayImage{8, 8, std::vector<std::uint8_t>(192)}}}, reference,
                                 dir.file("bad.png")),
               std::invalid_argument);
}

TEST(Bench, RejectsBadOptions) {
  gl::HeadlessContext context;
  bench::BenchOptions o;
  o.scenes = {"builtin:edges"};
  o.techniques = bench::default_techniques();
  std::swap(o.techniques[0], o.techniques[1]);
  EXPECT_THROW(bench::run_bench(o, nullptr), std::invalid_argument);  // noaa must come first
  o.techniques = bench::default_techniques();
  o.orbit_frames = 1;
  EXPECT_THROW(bench::run_bench(o, nullptr), std::invalid_argument);
}

}  // namespace
}  // namespace rsaa

#include "core/rsaa/offset_table.h"
#include "tools/scene_training/scene_tables.h"

namespace rsaa {
namespace {

TEST(SceneTables, FitsTheMasksASceneReachesAndMeasuresHeldOutViews) {
  gl::HeadlessContext context;
  const OffsetTable generic = read_offset_table(std::string(RSAA_SOURCE_DIR) + "/tables/d3d8x.json");
  bench::SceneTableOptions o;
  o.scene = "builtin:default";
  o.width = 96, o.height = 72, o.training_views = 2, o.held_out_views = 1, o.min_pixels = 10;
  const auto r = bench::train_scene_table(o, generic, nullptr);
  EXPECT_GT(r.masks_fitted, 5);
  EXPECT_GT(r.edge_pixels, 500u);
  int scene_entries = 0;
  for (std::size_t m = 0; m < r.table.offsets.size(); ++m) {
    ASSERT_TRUE(is_finite(r.table.offsets[m]));
    ASSERT_LE(std::abs(r.table.offsets[m].x), 1.0);
    ASSERT_LE(std::abs(r.table.offsets[m].y), 1.0);
    if (r.table.sources[m] == OffsetSource::Scene) {
      ++scene_entries;
      EXPECT_GE(r.table.cases_per_mask[m], 10u);
    } else {
      EXPECT_EQ(r.table.offsets[m], generic.offsets[m]);  // untouched
    }
  }
  EXPECT_EQ(scene_entries, r.masks_fitted);
  EXPECT_EQ(r.table.offsets[255], (Vec2{0, 0}));  // all-similar pixels are never harvested
  // The file form round-trips (the "scene" source included).
  const OffsetTable back = parse_offset_table(offset_table_json(r.table), "scene-table");
  EXPECT_EQ(back.sources, r.table.sources);
  // Quality on the held-out view: both tables beat no AA. (At this tiny size the scene table is
  // not always better than the generic one; the README reports full-size runs.)
  EXPECT_GT(r.held_out_psnr_generic, r.held_out_psnr_noaa);
  EXPECT_GT(r.held_out_psnr_scene, r.held_out_psnr_noaa);
}

}  // namespace
}  // namespace rsaa

namespace rsaa {
namespace {

TEST(PlotCsv, DrawsColumnsAndRejectsBadTables) {
  test::TempDir dir;
  test::write_text(dir.file("t.csv"), "cases,a,b\n1000,0.1,0.2\n10000,0.05,0.1\n100000,0.04,0.08\n");
  bench::plot_csv(dir.file("t.csv"), "cases", {"a", "b"}, true, "title", dir.file("t.png"));
  EXPECT_GT(std::filesystem::file_size(dir.file("t.png")), 1000u);
  EXPECT_THROW(bench::plot_csv(dir.file("t.csv"), "cases", {"c"}, false, "", dir.file("x.png")), std::runtime_error);
  test::write_text(dir.file("bad.csv"), "x,y\n1,2\n2,oops\n");
  EXPECT_THROW(bench::plot_csv(dir.file("bad.csv"), "x", {"y"}, false, "", dir.file("x.png")), std::runtime_error);
  test::write_text(dir.file("neg.csv"), "x,y\n-1,2\n2,3\n");
  EXPECT_THROW(bench::plot_csv(dir.file("neg.csv"), "x", {"y"}, true, "", dir.file("x.png")), std::runtime_error);
  EXPECT_FALSE(std::filesystem::exists(dir.file("x.png")));
}

// Pixels of the first line's colour (red) in a plot: the data drawn, not only the legend.
int red_pixels(const std::string& png) {
  const Image image = read_image(png);
  int n = 0;
  for (const Rgb& p : image.pixels) n += p.r > 0.3f && p.g < 0.1f && p.b < 0.1f;
  return n;
}

// Values a double holds but a chart's arithmetic did not: a constant column of 2e7 (the padding
// lost to rounding) drew no line, x and y near 1e16 the same; 1e308 and 1.7e308 overflowed the
// grid lines into a crash (SIGFPE).
TEST(PlotCsv, ExtremeButFiniteValuesAreDrawnOrRefused) {
  test::TempDir dir;
  for (const char* csv : {"x,y\n1,20000000\n2,20000000\n", "x,y\n1,1000\n2,1000\n",
                          "x,y\n1e16,5\n1e16,6\n", "x,y\n1,1e16\n2,1.0000000000000002e16\n",
                          "x,y\n-1e300,1e300\n1e300,-1e300\n"}) {
    test::write_text(dir.file("t.csv"), csv);
    bench::plot_csv(dir.file("t.csv"), "x", {"y"}, false, "t", dir.file("t.png"));
    EXPECT_GT(red_pixels(dir.file("t.png")), 300) << csv;
  }
  // 1e308 and 1.7e308 crashed the grid (its arithmetic overflowed); drawn now. A span beyond a
  // double is refused, naming the values.
  test::write_text(dir.file("big.csv"), "x,y\n1,1e308\n2,1.7e308\n");
  bench::plot_csv(dir.file("big.csv"), "x", {"y"}, false, "t", dir.file("big.png"));
  EXPECT_GT(red_pixels(dir.file("big.png")), 300);
  for (const auto& [csv, message] : std::vector<std::pair<std::string, std::string>>{
           {"x,y\n1,-1.7e308\n2,1.7e308\n", "span more than can be drawn (y from -1.7e+308 to 1.7e+308)"},
           {"x,y\n1,1.75e308\n2,1.75e308\n", "span more than can be drawn (y is 1.75e+308)"},
           // x values a chart cannot tell apart were drawn at one x, their labels over each other.
           {"x,y\n1e-320,1\n2e-320,2\n", "too narrow a span to tell the points apart on the x axis"},
           // A name the header repeats: which column was drawn was the first's, silently.
           {"x,y,x\n1,2,3\n2,3,4\n", "column 'x' appears more than once in the header"}}) {
    test::write_text(dir.file("huge.csv"), csv);
    try {
      bench::plot_csv(dir.file("huge.csv"), "x", {"y"}, false, "t", dir.file("huge.png"));
      ADD_FAILURE() << "drawn: " << csv;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
    EXPECT_FALSE(std::filesystem::exists(dir.file("huge.png")));
  }
  // Variation far below the values' magnitude keeps its shape (1e9 and 1e9 + 900 are drawn apart);
  // a difference a double can barely hold is drawn as one value, widened.
  const bench::AxisRange apart = bench::drawable_range(1e9, 1e9 + 900, 0.08, "y");
  EXPECT_LT(apart.hi - apart.lo, 1100.0);
  EXPECT_GT(apart.hi - apart.lo, 900.0);
  const bench::AxisRange one = bench::drawable_range(1e16, 1e16 + 2, 0.08, "y");
  EXPECT_GT(one.hi - one.lo, 1e14);
  // The figures' line charts share the ranges.
  bench::FigureTable table;
  table.columns = {"x", "y"};
  table.add({1.0, 2e7});
  table.add({2.0, 2e7});
  bench::ChartStyle style;
  style.title = "t";
  bench::plot_lines(table, style, dir.file("lines.png"));
  EXPECT_GT(std::filesystem::file_size(dir.file("lines.png")), 1000u);
  table.rows[1][1] = 1.7e308, table.rows[0][1] = -1.7e308;
  EXPECT_THROW(bench::plot_lines(table, style, dir.file("lines2.png")), std::runtime_error);
}

}  // namespace
}  // namespace rsaa
