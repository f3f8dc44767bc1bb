#include "tools/scene_training/scene_tables.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <glm/gtc/matrix_transform.hpp>

#include "image/image_io.h"
#include "image/image_metrics.h"
#include "core/util/parallel.h"
#include "core/util/shell_quote.h"
#include "core/rsaa/postprocess_cpu.h"
#include "runtime/render.h"
#include "runtime/scene.h"
#include "runtime/techniques/techniques.h"
#include "trainer/offset_fit.h"

namespace rsaa::bench {
namespace {

struct View3 {
  Image noaa, reference;
  std::vector<Mask> masks;
};

View3 render_view(const GpuScene& gpu, const Camera& camera, int width, int height) {
  View3 v;
  v.noaa = render_frame(gpu, camera, technique_options("noaa"), width, height);
  v.reference = render_frame(gpu, camera, technique_options("ssaa", 64), width, height);
  RsaaSettings settings;
  settings.output_mask = true;
  const gl::Texture mask_texture = gl::make_texture_2d(GL_R32UI, width, height);
  const gl::Texture output = gl::make_texture_2d(GL_RGBA16F, width, height);
  auto rsaa = make_rsaa(settings, width, height, mask_texture.get());
  rsaa->render(gpu, make_view(camera, width, height), output.get());
  for (std::uint32_t m : read_back_uints(mask_texture.get(), width, height)) v.masks.push_back(m);
  return v;
}

float channel(const Rgb& c, int k) { return k == 0 ? c.r : k == 1 ? c.g : c.b; }

double psnr(const Image& a, const Image& reference) {
  const double db = compare_images(to_display(a), to_display(reference)).psnr_db;
  return std::isfinite(db) ? db : 99.0;
}

}  // namespace

SceneTableReport train_scene_table(const SceneTableOptions& o, const OffsetTable& generic,
                                   const std::function<void(const std::string&)>& progress) {
  if (generic.pattern.name != "d3d8x") throw std::invalid_argument("scene tables start from the d3d8x table");
  if (o.training_views < 1 || o.held_out_views < 1) throw std::invalid_argument("need training and held-out views");
  validate_size(o.width, o.height);
  const Scene scene = load_scene_within(o.scene, 120.0);
  const GpuScene gpu(scene, /*with_facet_colours=*/false);  // RsaaSettings{}: no facet materials
  const Camera start = choose_camera(scene, std::nullopt);
  const auto say = [&](const std::string& s) {
    if (progress) progress(s);
  };

  // Harvest: one FitCase per edge pixel and colour channel, grouped by mask.
  std::map<Mask, std::vector<FitCase>> cases;
  std::map<Mask, std::uint64_t> pixels;
  SceneTableReport report;
  const Mask all = generic.pattern.all_similar();
  for (int v = 0; v < o.training_views; ++v) {
    say("training view " + std::to_string(v + 1) + "/" + std::to_string(o.training_views));
    const View3 view = render_view(gpu, orbit_camera(start, v * o.degrees_between_views), o.width, o.height);
    for (int y = 0; y < o.height; ++y)
      for (int x = 0; x < o.width; ++x) {
        const Mask m = view.masks[std::size_t(y) * o.width + x];
        if (m == all) continue;
        ++pixels[m];
        ++report.edge_pixels;
        for (int k = 0; k < 3; ++k) {
          FitCase c;
          for (int j = -1; j <= 1; ++j)
            for (int i = -1; i <= 1; ++i)
              c.neighbourhood.at(i, j) = channel(
                  view.noaa.at(std::clamp(x + i, 0, o.width - 1), std::clamp(y + j, 0, o.height - 1)), k);
          c.coverage = channel(view.reference.at(x, y), k);  // the target colour
          c.weight = 1.0;
          if (std::isfinite(c.coverage)) cases[m].push_back(c);
        }
      }
  }
  // Fit the masks the scene reaches often enough, in parallel, with the trainer's Ceres fit.
  std::vector<Mask> fitted_masks;
  for (const auto& [m, n] : pixels)
    if (n >= std::uint64_t(o.min_pixels)) fitted_masks.push_back(m);
  say("fitting " + std::to_string(fitted_masks.size()) + " masks");
  std::vector<Vec2> offsets(fitted_masks.size());
  parallel_for(fitted_masks.size(), 1, 0, [&](std::uint64_t b, std::uint64_t e) {
    for (std::uint64_t i = b; i < e; ++i) offsets[i] = fit_offset(cases[fitted_masks[i]]).offset;
  });
  report.table = generic;
  for (std::size_t i = 0; i < fitted_masks.size(); ++i) {
    const Vec2 d = offsets[i];
    report.table.offsets[fitted_masks[i]] = {std::round(d.x * 1e6) / 1e6 + 0.0, std::round(d.y * 1e6) / 1e6 + 0.0};
    report.table.sources[fitted_masks[i]] = OffsetSource::Scene;
    report.table.cases_per_mask[fitted_masks[i]] = pixels[fitted_masks[i]];
  }
  report.masks_fitted = int(fitted_masks.size());
  for (const auto& [m, n] : pixels) report.masks.push_back({m, n});
  std::sort(report.masks.begin(), report.masks.end(), [](auto& a, auto& b) { return a.second > b.second; });

  // Held-out views lie between the training views.
  for (int v = 0; v < o.held_out_views; ++v) {
    say("held-out view " + std::to_string(v + 1) + "/" + std::to_string(o.held_out_views));
    const double degrees = (v + 0.5) * o.degrees_between_views * std::max(1, o.training_views - 1) / o.held_out_views;
    const View3 view = render_view(gpu, orbit_camera(start, degrees), o.width, o.height);
    report.held_out_psnr_noaa += psnr(view.noaa, view.reference) / o.held_out_views;
    report.held_out_psnr_generic += psnr(apply_offset_table(view.noaa, view.masks, generic), view.reference) / o.held_out_views;
    report.held_out_psnr_scene +=
        psnr(apply_offset_table(view.noaa, view.masks, report.table), view.reference) / o.held_out_views;
  }
  // Every option that shapes the table, so that the recorded command makes it again.
  report.table.training = {{"command", "rsaa train --from-scene " + shell_quoted(o.scene) + " --width " + std::to_string(o.width) +
                                           " --height " + std::to_string(o.height) + " --views " +
                                           std::to_string(o.training_views) +
                                           (o.generic_file.empty() ? "" : " --generic " + shell_quoted(o.generic_file))},
                           {"from_scene", o.scene},
                           {"generic_table", generic.training.value("command", std::string("?"))},
                           {"training_views", o.training_views},
                           {"degrees_between_views", o.degrees_between_views},
                           {"min_pixels", o.min_pixels},
                           {"masks_fitted", report.masks_fitted},
                           {"edge_pixels", report.edge_pixels}};
  return report;
}

}  // namespace rsaa::bench
