// The GL coverage techniques (dcaa, dyncov, agaa) against their CPU references on the same inputs:
// the lists the GL geometry pass built are read back, replayed through core/dcaa and
// core/dynamic_coverage, and the resolved colours compared per pixel (within 2/255).
#include <gtest/gtest.h>

#include <filesystem>

#include <cmath>
#include <utility>

#include "core/reference/dcaa.h"
#include "core/reference/dynamic_coverage.h"
#include "core/reference/scene_shading.h"
#include "image/image_io.h"
#include "image/image_metrics.h"
#include "runtime/coverage_lists.h"
#include "runtime/gl_context.h"
#include "tests/gl_test.h"
#include "runtime/render.h"
#include "runtime/scene.h"
#include "runtime/technique_registry.h"
#include "runtime/technique_testing.h"
#include "runtime/techniques/techniques.h"

namespace rsaa {
namespace {

class CoverageGl : public test::GlTest {};

struct Rendered {
  DisplayImage gl, cpu;
  std::size_t fragments = 0, longest_list = 0;
  int worst = 0, worst_pixel = -1;
  int pixels_over_2 = 0;  // pixels with a channel more than 2/255 apart
};

// Renders `technique` and resolves the same fragment lists on the CPU.
Rendered render_both(const std::string& technique, const Scene& scene, int width, int height,
                     const std::string& rules = TechniqueOptions{}.rules,
                     const std::string& shade = TechniqueOptions{}.shade) {
  const GpuScene gpu(scene);
  const View view = make_view(choose_camera(scene, std::nullopt), width, height);
  TechniqueOptions options = technique_options(technique);
  options.rules = rules;
  options.shade = shade;
  auto t = make_technique(options, width, height);
  const gl::Texture output = gl::make_texture_2d(GL_RGBA16F, width, height);
  t->render(gpu, view, output.get());
  Rendered r;
  r.gl = to_display(read_back_image(output.get(), width, height));
  CoverageFragmentLists* lists = coverage_lists_of(*t);
  const auto pixels = lists->read_back();
  r.fragments = lists->fragments();
  const glm::vec3 bg = gpu.background();
  const Rgb background{bg.r, bg.g, bg.b};
  Image cpu(width, height);
  for (int i = 0; i < width * height; ++i) {
    if (technique == "dcaa") {
      DcaaPixel pixel(dcaa_settings(rules), &lists->lut().pattern(),
                      shade == "surface" ? dcaa_surface_shader(view, scene.point_lights, i % width, i / width)
                                           : DcaaSurfaceShader{});
      for (const CoverageFragment& f : pixels[i]) pixel.insert(f);
      cpu.pixels[i] = pixel.resolve(lists->lut().pattern(), background);
    } else {
      DynamicCoveragePixel pixel(background, dynamic_coverage_rules(rules));
      for (const CoverageFragment& f : pixels[i]) pixel.insert(f);
      cpu.pixels[i] = pixel.resolve();
    }
  }
  r.cpu = to_display(cpu);
  for (const auto& list : pixels) r.longest_list = std::max(r.longest_list, list.size());
  for (std::size_t p = 0; p < r.gl.rgb.size() / 3; ++p) {
    int d = 0;
    for (std::size_t c = 3 * p; c < 3 * p + 3; ++c) d = std::max(d, std::abs(int(r.gl.rgb[c]) - int(r.cpu.rgb[c])));
    if (d > r.worst) r.worst = d, r.worst_pixel = int(p);
    if (d > 2) ++r.pixels_over_2;
  }
  return r;
}

Rendered render_both(const std::string& technique, const std::string& scene_name, int width, int height,
                     const std::string& rules = TechniqueOptions{}.rules,
                     const std::string& shade = TechniqueOptions{}.shade) {
  return render_both(technique, load_scene(scene_name), width, height, rules, shade);
}

// One draw of every triangle, seen from (0, 0, 3) along -z: the hand-made scenes below.
Scene with_one_draw_seen_from_the_front(Scene s) {
  s.draws = {{0, std::uint32_t(s.indices.size()), -1}};
  Camera camera;
  camera.eye = {0.0f, 0.0f, 3.0f};
  camera.near_plane = 1.0f;
  camera.far_plane = 5.0f;
  s.camera = camera;
  return s;
}

// `count` triangles stacked front to back, each turned about the view axis (their edges cross
// the pixels at every angle) and tilted a little (some merge, some do not), each its own
// colour: the pixels near the centre get a fragment of every triangle.
Scene stacked_triangles(int count) {
  Scene s;
  s.name = "stacked triangles";
  for (int i = 0; i < count; ++i) {
    const float turn = 2.399963f * float(i);  // the golden angle
    const float tilt = 0.3f * std::sin(1.7f * float(i)), z = -0.5f * float(i) / float(count);
    const glm::vec3 normal = glm::normalize(glm::vec3(tilt, 0.5f * tilt, 1.0f));
    const glm::vec3 albedo{0.5f + 0.5f * std::sin(0.9f * float(i)), 0.5f + 0.5f * std::sin(1.3f * float(i) + 2.0f),
                           0.5f + 0.5f * std::sin(0.7f * float(i) + 4.0f)};
    for (int k = 0; k < 3; ++k) {
      const float a = turn + 2.0943951f * float(k);
      SceneVertex v;
      v.position = {std::cos(a), std::sin(a), z};
      v.position.z -= glm::dot(glm::vec2(normal), glm::vec2(v.position)) / normal.z;  // on the tilted plane
      v.normal = normal;
      v.albedo = albedo;
      s.indices.push_back(std::uint32_t(s.vertices.size()));
      s.vertices.push_back(v);
    }
  }
  return with_one_draw_seen_from_the_front(std::move(s));
}

TEST_F(CoverageGl, DcaaEqualsItsCpuReferenceOnTheSameFragments) {
  for (const char* shade : {"fragment", "surface"})
    for (const char* rules : {"surface", "paper"})
      for (const char* scene : {"builtin:default", "builtin:interpenetrating", "builtin:star"}) {
        const Rendered r = render_both("dcaa", scene, 96, 72, rules, shade);
        EXPECT_GT(r.fragments, std::size_t(96 * 72));
        EXPECT_LE(r.worst, 2) << shade << " " << rules << " " << scene << ": pixel " << r.worst_pixel % 96 << ", "
                              << r.worst_pixel / 96;
      }
}

// Shading each surface once from its merged attributes: a surface of many triangles (the
// sphere, the tiles) gives nearly the image of shading each fragment; the scene's point lights
// reach the resolve's shading (GL equal to the CPU reference with two of them).
TEST_F(CoverageGl, DcaaShadingSurfacesOnceIsCloseToShadingFragments) {
  Scene scene = load_scene("builtin:default");
  const GpuScene gpu(scene);
  const Camera camera = choose_camera(scene, std::nullopt);
  TechniqueOptions options = technique_options("dcaa");
  options.shade = "fragment";
  const DisplayImage per_fragment = to_display(render_frame(gpu, camera, options, 160, 120));
  options.shade = "surface";
  const DisplayImage per_surface = to_display(render_frame(gpu, camera, options, 160, 120));
  EXPECT_GT(compare_images(per_surface, per_fragment).psnr_db, 40.0);

  scene.point_lights = {PointLight{{0.5f, 0.5f, -2.0f}, 1.0f, {1.0f, 0.5f, 0.2f}},
                        PointLight{{-1.0f, 0.0f, -4.0f}, 2.0f, {0.2f, 0.4f, 1.0f}}};
  const Rendered r = render_both("dcaa", scene, 96, 72, "surface", "surface");
  EXPECT_LE(r.worst, 2) << "pixel " << r.worst_pixel % 96 << ", " << r.worst_pixel / 96;
}

TEST_F(CoverageGl, ListsLongerThanTheLocalSortAreReplayedInOrderToo) {
  // The whole default scene in 8x6 pixels: lists far longer than the 32 records the resolve
  // sorts locally, replayed by its continuation passes.
  // Over a hundred merges a pixel, a choice between two slots whose normals are equal to 1e-7
  // can go either way between the GL and CPU floats (seen once in 48 pixels with the surface
  // rules): one pixel may differ more, by less than 8/255.
  struct Case {
    const char *technique, *rules, *shade;
  };
  for (const auto& [technique, rules, shade] :
       {Case{"dcaa", "surface", "fragment"}, Case{"dcaa", "paper", "fragment"}, Case{"dcaa", "surface", "surface"},
        Case{"dyncov", "surface", "fragment"}, Case{"dyncov", "seed", "fragment"}}) {
    const Rendered r = render_both(technique, "builtin:default", 8, 6, rules, shade);
    EXPECT_GT(r.longest_list, 32u);
    EXPECT_LE(r.pixels_over_2, 1) << technique << " " << rules << " " << shade;
    EXPECT_LT(r.worst, 8) << technique << " " << rules << " " << shade << ": pixel " << r.worst_pixel % 8 << ", "
                          << r.worst_pixel / 8;
  }
}

// Lists of hundreds and thousands of fragments (the 2CylinderEngine at 640x480 has up to 311):
// replayed in one invocation they ran into llvmpipe's 65535 loop iterations per invocation and
// lost their fragments (the background came out). Every pixel equals the CPU reference; 2600
// records take a continuation pass more than one walk (1024 records).
TEST_F(CoverageGl, ThousandsOfStackedFragmentsEqualTheCpuReference) {
  for (int count : {400, 2600}) {
    const Scene scene = stacked_triangles(count);
    for (const auto& [technique, rules] : {std::pair{"dcaa", "surface"}, std::pair{"dcaa", "paper"},
                                           std::pair{"dyncov", "surface"}, std::pair{"dyncov", "seed"}}) {
      const Rendered r = render_both(technique, scene, 16, 12, rules);
      EXPECT_EQ(r.longest_list, std::size_t(count));
      EXPECT_EQ(r.pixels_over_2, 0) << count << " " << technique << " " << rules << ": worst " << r.worst
                                    << " at pixel " << r.worst_pixel % 16 << ", " << r.worst_pixel / 16;
    }
  }
}

// Two planes folded along x = f (off the pixel grid; the left half of one and the right half of the other in front),
// each made of two coplanar quads of different colours split at the fold: the dark quads are
// visible, the pale ones hidden behind them (the house's plinth flush with a pale slab,
// AC14-FZK-Haus). The pixels along the fold get all four.
Scene folded_planes() {
  Scene s;
  s.name = "folded planes";
  const auto quad = [&s](float x0, float x1, float slope, glm::vec3 albedo) {
    const glm::vec3 normal = glm::normalize(glm::vec3(-slope, 0.0f, 1.0f));
    const float f = 0.0123f;
    const glm::vec3 corners[4] = {
        {x0, -1, slope * (x0 - f)}, {x1, -1, slope * (x1 - f)}, {x1, 1, slope * (x1 - f)}, {x0, 1, slope * (x0 - f)}};
    for (int k : {0, 1, 2, 0, 2, 3}) {
      SceneVertex v;
      v.position = corners[k];
      v.normal = normal;
      v.albedo = albedo;
      s.indices.push_back(std::uint32_t(s.vertices.size()));
      s.vertices.push_back(v);
    }
  };
  const glm::vec3 dark{0.1f, 0.1f, 0.1f}, pale{0.8f, 0.8f, 0.7f};
  quad(-1.0f, 0.0123f, -0.3f, dark);  // in front where x < f
  quad(-1.0f, 0.0123f, 0.3f, pale);   // behind it
  quad(0.0123f, 1.0f, 0.3f, dark);    // in front where x > f
  quad(0.0123f, 1.0f, -0.3f, pale);   // behind it
  return with_one_draw_seen_from_the_front(std::move(s));
}

// The colour test of the first merge on GL: equal to the CPU reference, and what it changes
// (merged across colours, as the paper's rules do, the fold shows the hidden quads' mean).
TEST_F(CoverageGl, CoplanarPartsOfDifferentColoursStayApartOnGl) {
  const int width = 96, height = 72;
  const Scene scene = folded_planes();
  const GpuScene gpu(scene);
  const View view = make_view(choose_camera(scene, std::nullopt), width, height);
  auto t = make_technique(technique_options("dcaa"), width, height);
  const gl::Texture output = gl::make_texture_2d(GL_RGBA16F, width, height);
  t->render(gpu, view, output.get());
  const DisplayImage gl = to_display(read_back_image(output.get(), width, height));
  CoverageFragmentLists* lists = coverage_lists_of(*t);
  const auto pixels = lists->read_back();
  const glm::vec3 bg = gpu.background();
  DcaaSettings across = dcaa_settings("surface");
  across.merge_colour_tolerance = 0.0f;
  int worst = 0, changed = 0;
  for (int i = 0; i < width * height; ++i) {
    DcaaPixel kept(dcaa_settings("surface"), &lists->lut().pattern()), merged(across, &lists->lut().pattern());
    for (const CoverageFragment& f : pixels[i]) kept.insert(f), merged.insert(f);
    Image both(2, 1);
    both.pixels[0] = kept.resolve(lists->lut().pattern(), {bg.r, bg.g, bg.b});
    both.pixels[1] = merged.resolve(lists->lut().pattern(), {bg.r, bg.g, bg.b});
    const DisplayImage d = to_display(both);
    int d_gl = 0, d_merged = 0;
    for (int c = 0; c < 3; ++c) {
      d_gl = std::max(d_gl, std::abs(int(gl.rgb[3 * i + c]) - int(d.rgb[c])));
      d_merged = std::max(d_merged, int(d.rgb[3 + c]) - int(d.rgb[c]));
    }
    worst = std::max(worst, d_gl);
    changed += d_merged > 40;  // the pale quads' light
  }
  EXPECT_LE(worst, 2);
  EXPECT_GE(changed, height / 2) << "pixels along the fold lit by hidden quads when merged across colours";
}

// Every fragment's depth plane, near-plane triangles included (the grazing scene's floor reaches
// behind the eye and is rasterised by the hardware), predicts the depth its triangle records in
// the next pixel of the row: a flat plane there let the floor take the samples of the cylinder
// lying on it wherever it was nearer at the pixel centre.
TEST_F(CoverageGl, DepthPlanesPredictTheNeighbouringPixelNearPlaneTrianglesToo) {
  const int width = 96, height = 72;
  const Scene scene = load_scene("builtin:grazing");
  const GpuScene gpu(scene);
  const View view = make_view(choose_camera(scene, std::nullopt), width, height);
  auto t = make_technique(technique_options("dcaa"), width, height);
  const gl::Texture output = gl::make_texture_2d(GL_RGBA16F, width, height);
  t->render(gpu, view, output.get());
  const auto pixels = coverage_lists_of(*t)->read_back();
  // The next pixel right (x + 1) and the next row of the lists (one pixel down, as the planes' y).
  int pairs = 0, wrong = 0;
  for (int y = 0; y + 1 < height; ++y)
    for (int x = 0; x + 1 < width; ++x)
      for (const CoverageFragment& f : pixels[y * width + x])
        for (int next : {y * width + x + 1, (y + 1) * width + x})
          for (const CoverageFragment& g : pixels[next]) {
            const float step = g.depth.at_centre - f.depth.at_centre;
            if (g.order != f.order || !(std::abs(step) > 1e-6f)) continue;
            const float predicted = next == y * width + x + 1 ? f.depth.ddx : f.depth.ddy;
            ++pairs;
            // The slopes are stored to 2^-12 of the larger one (encode_slopes).
            const float stored = std::ldexp(std::max(std::abs(f.depth.ddx), std::abs(f.depth.ddy)), -11);
            wrong += std::abs(predicted - step) > 0.05f * std::abs(step) + stored;
          }
  EXPECT_GT(pairs, 1000);
  EXPECT_EQ(wrong, 0) << "of " << pairs << " neighbouring fragments of one triangle";
}

TEST_F(CoverageGl, DynamicCoverageEqualsItsCpuReferenceOnTheSameFragments) {
  for (const char* rules : {"surface", "seed"})
    for (const char* scene : {"builtin:default", "builtin:interpenetrating", "builtin:star"}) {
      const Rendered r = render_both("dyncov", scene, 96, 72, rules);
      EXPECT_LE(r.worst, 2) << rules << " " << scene << ": pixel " << r.worst_pixel % 96 << ", " << r.worst_pixel / 96;
    }
}

}  // namespace
}  // namespace rsaa

namespace rsaa {
namespace {

TEST_F(CoverageGl, EveryBuiltinSceneAndExtremeSizesGiveFiniteImages) {
  TechniqueOptions dcaa_per_surface = technique_options("dcaa");
  dcaa_per_surface.shade = "surface";
  for (const std::string& name : builtin_scene_names())
    for (const TechniqueOptions& technique : {technique_options("dcaa"), dcaa_per_surface, technique_options("dyncov"),
                                              technique_options("agaa", 4), technique_options("agaa", 8)})
      for (auto [w, h] : {std::pair{64, 48}, std::pair{1, 1}, std::pair{3, 2}}) {
        const Scene scene = load_scene("builtin:" + name);
        const GpuScene gpu(scene);
        const Image image = render_frame(gpu, choose_camera(scene, std::nullopt), technique, w, h);
        for (const Rgb& p : image.pixels)
          ASSERT_TRUE(std::isfinite(p.r) && std::isfinite(p.g) && std::isfinite(p.b))
              << name << " " << technique_label(technique);
      }
}

TEST_F(CoverageGl, DcaaBeatsNoAaAndListsGrowWhenTheyOverflow) {
  const Scene scene = load_scene("builtin:default");
  const GpuScene gpu(scene);
  const Camera camera = choose_camera(scene, std::nullopt);
  const auto display = [&](const char* t) { return to_display(render_frame(gpu, camera, technique_options(t), 160, 120)); };
  const DisplayImage reference = to_display(render_frame(gpu, camera, technique_options("ssaa", 64), 160, 120));
  const double noaa = compare_images(display("noaa"), reference).psnr_db;
  const double dcaa = compare_images(display("dcaa"), reference).psnr_db;
  EXPECT_GT(dcaa, noaa + 6.0);  // measured +11 dB at 320x240
  // The default scene needs more than the initial 2 records a pixel at 8x8: the lists grow.
  auto t = make_technique(technique_options("dcaa"), 8, 8);
  const gl::Texture output = gl::make_texture_2d(GL_RGBA16F, 8, 8);
  t->render(gpu, make_view(camera, 8, 8), output.get());
  const double needed = 4.0 + coverage_lists_of(*t)->record_bytes() * double(coverage_lists_of(*t)->fragments()) / 64.0;
  EXPECT_GE(t->bytes_per_pixel(), needed);
  // A frame with far fewer fragments (the same scene from far away) shrinks the buffer to its
  // own count, with room to spare.
  Camera far_camera = camera;
  far_camera.eye = camera.target + 20.0f * (camera.eye - camera.target);
  t->render(gpu, make_view(far_camera, 8, 8), output.get());
  t->render(gpu, make_view(far_camera, 8, 8), output.get());
  const double far_needed = 4.0 + coverage_lists_of(*t)->record_bytes() * double(coverage_lists_of(*t)->fragments()) / 64.0;
  EXPECT_LT(coverage_lists_of(*t)->bytes_per_pixel(), needed);
  EXPECT_GE(coverage_lists_of(*t)->bytes_per_pixel(), far_needed);
}

}  // namespace
}  // namespace rsaa

namespace rsaa {
namespace {

// AGAA 8x and 16x: the GL aggregate metadata against define_aggregates() on the read-back samples,
// and the GL image against agaa_resolve() on the read-back aggregate sums.
TEST_F(CoverageGl, AgaaEqualsItsCpuReferenceOnTheSameSamples) {
  struct Case {
    const char* name;
    int c, n;
  };
  for (const auto& [name, c, n] : {Case{"builtin:default", 2, 8}, Case{"builtin:fence", 4, 8}, Case{"builtin:fence", 4, 16}}) {
    const Scene scene = load_scene(name);
    const GpuScene gpu(scene);
    const int w = 96, h = 72;
    const View view = make_view(choose_camera(scene, std::nullopt), w, h);
    TechniqueOptions options = technique_options("agaa", n);
    options.agaa_aggregates = c;
    auto t = make_technique(options, w, h);
    const gl::Texture output = gl::make_texture_2d(GL_RGBA16F, w, h);
    t->render(gpu, view, output.get());
    const DisplayImage gl_image = to_display(read_back_image(output.get(), w, h));
    const AgaaFrameData data = read_back_agaa(*t, view);
    const glm::vec3 bg = gpu.background();
    Image cpu(w, h);
    int meta_mismatches = 0, several_aggregates = 0;
    for (int i = 0; i < w * h; ++i) {
      const std::vector<AgaaSample> samples(data.samples_of_pixels.begin() + i * n, data.samples_of_pixels.begin() + (i + 1) * n);
      const AgaaClusters clusters = define_aggregates(samples, data.settings);
      std::uint64_t meta = std::uint64_t(clusters.count) << (32 + 24);  // agaa_samples.glsl: x | y << 32
      for (int s = 0; s < n; ++s)
        if (clusters.aggregate[s] >= 0)
          meta |= (std::uint64_t{1} << (32 + s)) | (std::uint64_t(clusters.aggregate[s]) << (2 * s));
      meta_mismatches += meta != data.meta[i];
      several_aggregates += clusters.count == c;
      cpu.pixels[i] = agaa_resolve({data.aggregates.begin() + c * i, data.aggregates.begin() + c * (i + 1)},
                                   data.pixel_rays[i], {bg.r, bg.g, bg.b}, data.settings.filtered_diffuse);
    }
    EXPECT_GT(several_aggregates, 50) << name << " " << n;        // edges make c aggregates
    EXPECT_LE(meta_mismatches, w * h / 200) << name << " " << n;  // float ties may differ
    const DisplayImage cpu_image = to_display(cpu);
    int worst = 0;
    for (std::size_t i = 0; i < cpu_image.rgb.size(); ++i)
      worst = std::max(worst, std::abs(int(cpu_image.rgb[i]) - int(gl_image.rgb[i])));
    EXPECT_LE(worst, 2) << name << " " << n;
  }
}

// On flat faces (the default scene) and on a model of smooth normals (the spider, whose
// silhouettes' normals turn away from the eye: AGAA's aggregates turned them again per fragment
// after the scene's shading had settled each triangle's side, and fell 5 dB, to 2.5 dB above no AA
// at 160x120).
TEST_F(CoverageGl, AgaaBeatsNoAaWithHardwareAndJitteredSamples) {
  for (const std::string name : {"builtin:default", "/usr/share/assimp/models/OBJ/spider.obj"}) {
    if (!std::filesystem::exists(name) && name.rfind("builtin:", 0) != 0) continue;  // assimp-testmodels
    const Scene scene = load_scene(name);
    const GpuScene gpu(scene);
    const Camera camera = choose_camera(scene, std::nullopt);
    const auto display = [&](const TechniqueOptions& o) { return to_display(render_frame(gpu, camera, o, 160, 120)); };
    const DisplayImage reference = display(technique_options("ssaa", 64));
    const double noaa = compare_images(display(technique_options("noaa")), reference).psnr_db;
    for (int n : {4, 8}) {
      const double agaa = compare_images(display(technique_options("agaa", n)), reference).psnr_db;
      EXPECT_GT(agaa, noaa + 5.0) << name << ", " << n << " samples";
    }
  }
}

}  // namespace
}  // namespace rsaa

namespace rsaa {
namespace {

// A model in other units gives the same image: the scene and its camera scaled by 10^3 and
// 10^-3 against the unscaled render, every technique (AGAA's k is relative to the view for this).
// The seed's dynamic coverage rules compare single depths at the pixel centre, where the two
// triangles of a quad tie over the reals and differ in float by rounding that the scale changes:
// with the literal float comparisons 38-39 dB at 160x120, with ties up to kSeedDepthTie 56-91 dB
// (65-67 at 640x480). The surface rules pass with less margin (53-55 dB; 49 dB at 96x72, where
// many triangles share a pixel and a sample flipping at an edge changes which fragments merge).
TEST_F(CoverageGl, EveryTechniqueRendersAScaledSceneTheSame) {
  const Scene scene = load_scene("builtin:default");
  std::vector<TechniqueOptions> techniques;
  for (const std::string& name : technique_names())
    if (name != "rsaa") techniques.push_back(technique_options(name));
  techniques.push_back(technique_options("agaa", 4));
  techniques.push_back(technique_options("msaa", 4));
  techniques.push_back(technique_options("ssaa", 8));
  TechniqueOptions dcaa_per_surface = technique_options("dcaa");
  dcaa_per_surface.shade = "surface";  // the position from the depth plane, shaded in the resolve
  techniques.push_back(dcaa_per_surface);
  TechniqueOptions dyncov_seed = technique_options("dyncov");
  dyncov_seed.rules = "seed";
  techniques.push_back(dyncov_seed);
  for (const TechniqueOptions& o : rsaa_variants())
    if (o.auth == 0 || o.samples == 4) techniques.push_back(o);
  const auto render = [&](const Scene& s, const TechniqueOptions& o) {
    const GpuScene gpu(s);
    return to_display(render_frame(gpu, choose_camera(s, std::nullopt), o, 160, 120));
  };
  for (const TechniqueOptions& o : techniques) {
    const DisplayImage unscaled = render(scene, o);
    for (float factor : {1e3f, 1e-3f})
      EXPECT_GE(compare_images(render(scaled_scene(scene, factor), o), unscaled).psnr_db, 50.0)
          << technique_label(o) << " at scale " << factor;
  }
}

}  // namespace
}  // namespace rsaa

namespace rsaa {
namespace {

// DCAA's z-prepass: fewer fragments reach the lists, the GL resolve still equals the CPU
// reference on what was stored, and the image loses little (cracks where the 4 depth samples
// miss a surface the 64 coverage samples see; measured -0.4 dB at 640x480).
TEST_F(CoverageGl, ZPrepassCullsHiddenFragments) {
  const Scene scene = load_scene("builtin:default");
  const GpuScene gpu(scene);
  const Camera camera = choose_camera(scene, std::nullopt);
  const View view = make_view(camera, 160, 120);
  const DisplayImage reference = to_display(render_frame(gpu, camera, technique_options("ssaa", 64), 160, 120));
  std::size_t fragments[2];
  double psnr[2];
  for (bool prepass : {false, true}) {
    TechniqueOptions o = technique_options("dcaa");
    o.z_prepass = prepass;
    auto t = make_technique(o, 160, 120);
    const gl::Texture output = gl::make_texture_2d(GL_RGBA16F, 160, 120);
    t->render(gpu, view, output.get());
    fragments[prepass] = coverage_lists_of(*t)->fragments();
    psnr[prepass] = compare_images(to_display(read_back_image(output.get(), 160, 120)), reference).psnr_db;
    bool has_prepass_time = false;
    for (const PassTime& p : t->take_pass_times()) has_prepass_time |= p.pass == "z-prepass";
    EXPECT_EQ(has_prepass_time, prepass);
  }
  EXPECT_LT(double(fragments[1]), 0.9 * double(fragments[0]));
  EXPECT_GT(psnr[1], psnr[0] - 1.0);
}

}  // namespace
}  // namespace rsaa
