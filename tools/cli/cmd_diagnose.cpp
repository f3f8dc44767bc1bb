// rsaa diagnose: where RSAA's image error lives (tools/bench/diagnosis.h), per pixel class, with
// an error map coloured by class and the oracle bound of a single bilinear fetch.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <optional>

#include "core/util/atomic_file.h"
#include "core/util/colour.h"
#include "image/image_io.h"
#include "runtime/camera.h"
#include "runtime/gl_context.h"
#include "runtime/render.h"
#include "runtime/scene.h"
#include "runtime/shader_library.h"
#include "runtime/techniques/techniques.h"
#include "tools/bench/diagnosis.h"
#include "tools/cli/commands.h"
#include "tools/cli/options.h"
#include "tools/cli/out_dir.h"
#include "tools/cli/technique_options.h"

namespace rsaa::cli {
namespace {

struct DiagnoseArgs {
  std::string scene = "builtin:default";
  TechniqueOptions technique = technique_options("rsaa");
  int width = 640, height = 480;
  std::string camera;
  std::string out_dir = "out/diagnose";
  int surface_samples_per_side = 8;
  float anisotropy = kDefaultTextureAnisotropy;
};

// Triangle id + 1 (0 = background) seen at each pixel for the sample at pixel-space `offset`.
std::vector<std::uint32_t> primitive_ids(const GpuScene& scene, const View& view, RsaaTargets& targets,
                                         const SceneRenderer& renderer, Vec2 offset) {
  renderer.draw_gbuffer(scene, view, targets, jitter_ndc_for_sample(offset.x, offset.y, view.width, view.height));
  return read_back_uints(targets.frame(view.inverse_projection()).centre_primitive, view.width, view.height);
}

std::uint32_t surface_of(const std::vector<std::uint32_t>& surface_ids, std::uint32_t primitive) {
  return primitive == 0 || primitive > surface_ids.size() ? 0u : surface_ids[primitive - 1];
}

// Surfaces per pixel from per_side^2 stratified samples, most samples first.
std::vector<PixelSurfaces> surfaces_seen(const GpuScene& scene, const View& view,
                                         const std::vector<std::uint32_t>& surface_ids, int per_side) {
  RsaaTargets targets(view.width, view.height);
  const SceneRenderer renderer;
  const std::size_t pixels = std::size_t(view.width) * view.height;
  std::vector<std::map<std::uint32_t, int>> counts(pixels);
  for (const Vec2& s : stratified_positions(per_side, 64)) {
    const std::vector<std::uint32_t> ids = primitive_ids(scene, view, targets, renderer, s);
    for (std::size_t p = 0; p < pixels; ++p) ++counts[p][surface_of(surface_ids, ids[p])];
  }
  std::vector<PixelSurfaces> out(pixels);
  for (std::size_t p = 0; p < pixels; ++p) {
    std::vector<std::pair<int, std::uint32_t>> by_count;
    for (const auto& [id, n] : counts[p]) by_count.push_back({-n, id});
    std::sort(by_count.begin(), by_count.end());
    out[p].count = int(by_count.size());
    for (const auto& [id, n] : counts[p]) out[p].total += n;
    for (int k = 0; k < std::min<int>(out[p].count, PixelSurfaces::kMaxKept); ++k)
      out[p].ids[k] = by_count[k].second, out[p].samples[k] = -by_count[k].first;
  }
  return out;
}

Image from_display(const std::vector<std::uint8_t>& rgb, int width, int height) {
  Image image(width, height);
  for (std::size_t p = 0; p < image.pixels.size(); ++p)
    image.pixels[p] = {srgb_to_linear(rgb[3 * p] / 255.0f), srgb_to_linear(rgb[3 * p + 1] / 255.0f),
                       srgb_to_linear(rgb[3 * p + 2] / 255.0f)};
  return image;
}

int run_diagnose(const DiagnoseArgs& a) {
  TechniqueOptions options = a.technique;
  if (options.technique != "rsaa") throw std::invalid_argument("diagnose measures rsaa only (--technique rsaa)");
  validate(options);
  validate_size(a.width, a.height);
  if (a.surface_samples_per_side < 2 || a.surface_samples_per_side > 16)
    throw std::invalid_argument("--surface-samples must be 2..16 per side");
  Scene scene = load_scene_within(a.scene, kSceneLoadSeconds);
  scene.texture_anisotropy = a.anisotropy;
  std::optional<Camera> requested;
  if (!a.camera.empty()) requested = parse_camera(a.camera, scene.bounds_min(), scene.bounds_max());
  const Camera camera = choose_camera(scene, requested);
  // The table and the pictures are one set (a failed write leaves the previous run's whole);
  // claimed before the renders, so that an unwritable --out-dir is said at once.
  StagedOutputs staged(a.out_dir, "rsaa diagnose");
  require_image_module();  // its images are written at the end: said now if they cannot be
  gl::HeadlessContext context;
  const GpuScene gpu_scene(scene, needs_facet_colours(options));
  const View view = make_view(camera, a.width, a.height);

  std::printf("diagnose %s on %s (%dx%d): rendering no AA, the reference and RSAA with its masks\n",
              technique_label(options).c_str(), scene.name.c_str(), a.width, a.height);
  std::fflush(stdout);
  DiagnosisInputs in;
  in.noaa = render_frame(gpu_scene, camera, technique_options("noaa"), a.width, a.height);
  in.reference = render_frame(gpu_scene, camera, technique_options("ssaa", 64), a.width, a.height);
  in.baseline = render_frame(gpu_scene, camera, technique_options("msaa", 4), a.width, a.height);
  RsaaSettings settings = rsaa_settings(options);
  settings.output_mask = true;
  const gl::Texture mask_texture = gl::make_texture_2d(GL_R32UI, a.width, a.height);
  const gl::Texture output = gl::make_texture_2d(GL_RGBA16F, a.width, a.height);
  auto technique = make_rsaa(settings, a.width, a.height, mask_texture.get());
  technique->render(gpu_scene, view, output.get());
  in.rsaa = read_back_image(output.get(), a.width, a.height);
  for (std::uint32_t m : read_back_uints(mask_texture.get(), a.width, a.height)) in.masks.push_back(m);
  const OffsetTable table = settings.table ? *settings.table : gl::builtin_offset_table(settings.pattern);
  in.table = &table;

  std::printf("diagnose: surfaces per pixel from %d samples\n", a.surface_samples_per_side * a.surface_samples_per_side);
  std::fflush(stdout);
  const std::vector<std::uint32_t> surface_ids = smooth_surface_ids(scene);
  in.surfaces = surfaces_seen(gpu_scene, view, surface_ids, a.surface_samples_per_side);
  {
    RsaaTargets targets(a.width, a.height);
    const SceneRenderer renderer;
    for (std::uint32_t id : primitive_ids(gpu_scene, view, targets, renderer, {0.0, 0.0}))
      in.centre_surface.push_back(surface_of(surface_ids, id));
    in.subsample_sees_other.assign(in.centre_surface.size(), 0);
    for (const Vec2& s : table.pattern.positions) {
      const std::vector<std::uint32_t> ids = primitive_ids(gpu_scene, view, targets, renderer, s);
      for (std::size_t p = 0; p < ids.size(); ++p)
        in.subsample_sees_other[p] |= surface_of(surface_ids, ids[p]) != in.centre_surface[p];
    }
  }

  std::printf("diagnose: classifying and searching the best single fetch per pixel\n");
  std::fflush(stdout);
  const Diagnosis d = diagnose(in);
  const std::string markdown =
      diagnosis_markdown(d, technique_label(options) + " on " + scene_short_name(a.scene), "msaa 4x");
  std::string legend = "\nError map colours (brightness = RSAA's error):";
  const auto& colours = diagnosis_class_colours();
  for (int c = 0; c < kDiagnosisClassCount; ++c) {
    char entry[160];
    std::snprintf(entry, sizeof entry, " %s = rgb(%d,%d,%d);", to_string(DiagnosisClass(c)), colours[c][0],
                  colours[c][1], colours[c][2]);
    legend += entry;
  }

  const std::filesystem::path dir(staged.dir());
  write_image((dir / "error_map.png").string(), from_display(diagnosis_picture(d), a.width, a.height));
  write_image((dir / "oracle.png").string(), d.oracle);
  write_image((dir / "coverage.png").string(), d.coverage);
  write_image((dir / "rsaa.png").string(), in.rsaa);
  write_image((dir / "noaa.png").string(), in.noaa);
  write_image((dir / "reference.png").string(), in.reference);
  write_file_atomically((dir / "diagnosis.md").string(), markdown + legend + "\n");
  const std::vector<std::string> written = staged.commit();
  std::printf("%s%s\n", markdown.c_str(), legend.c_str());
  std::fflush(stdout);
  print_written(a.out_dir, written);
  return 0;
}

}  // namespace

Action add_diagnose_command(CLI::App& app) {
  auto args = std::make_shared<DiagnoseArgs>();
  CLI::App* cmd = app.add_subcommand(
      "diagnose", "Split RSAA's image error against 64x SSAA by pixel class (surfaces seen, mask rule, missed "
                  "edges, no other colour nearby) with an error map and the best-single-fetch bound");
  cmd->add_option("--scene", args->scene, "builtin:NAME or a model file assimp reads")->capture_default_str();
  add_anisotropy_option(cmd, args->anisotropy);
  add_technique_options(cmd, args->technique);
  cmd->add_option("--width", args->width, "Image width")->capture_default_str();
  cmd->add_option("--height", args->height, "Image height")->capture_default_str();
  cmd->add_option("--camera", args->camera, "ex,ey,ez,tx,ty,tz[,fov] (default: the scene's view)");
  cmd->add_option("--surface-samples", args->surface_samples_per_side,
                  "samples per side of the surface-id pass (8: 64 per pixel)")
      ->capture_default_str();
  cmd->add_option("--out-dir", args->out_dir, "Where the table and pictures go")->capture_default_str();
  return [args] { return run_diagnose(*args); };
}

}  // namespace rsaa::cli
