// rsaa bench: the speed/accuracy trade of every technique on a set of scenes (docs/conventions.md
// section 5): per-pass and whole-frame times (medians, warm-up excluded, as ratios to the no-AA
// frame of the same run), PSNR / SSIM / luminance-error share against 64x SSAA, temporal quality
// over a short camera orbit, and memory per pixel.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "image/image_io.h"
#include "runtime/pass_timer.h"
#include "runtime/scene.h"
#include "runtime/technique_registry.h"

namespace rsaa::bench {

struct BenchOptions {
  std::vector<std::string> scenes;
  std::vector<TechniqueOptions> techniques;  // the first must be noaa (the ratio baseline)
  int width = 640, height = 480;
  int frames = 5;        // timed frames per technique (after one warm-up frame)
  int lights = 1;        // the fixed light plus lights - 1 point lights (growth.h: with_lights)
  float texture_anisotropy = kDefaultTextureAnisotropy;  // Scene::texture_anisotropy of every scene
  int orbit_frames = 4;  // frames of the camera animation for the temporal metrics
  double orbit_degrees_per_frame = 0.25;
  // When set, one side-by-side crop image per scene is written here (crops-<scene>.png).
  std::string crops_dir;
};

struct TechniqueResult {
  std::string scene, label;
  TechniqueOptions options;
  std::vector<PassTime> pass_medians;  // median over the timed frames, per pass
  double frame_ms = 0.0;               // median of the frames' summed wall-clock pass times
  // The baselines' frames timed in the same rounds as this technique's (time_rounds()): no AA's,
  // and 4x MSAA's when the run benches it (else 0; 0 in files from before they existed).
  double paired_noaa_ms = 0.0, paired_msaa_ms = 0.0;
  double frame_ratio = 0.0;            // frame_ms / paired_noaa_ms (files before it: / the noaa row's)
  // The speed of light: median wall time of a full-screen copy pass (copy_pass.h) timed after
  // each of this technique's timed frames, at the same size; 0 in files from before it existed.
  double copy_ms = 0.0;
  double psnr_db = 0.0, ssim = 0.0, luma_error_share = 0.0;  // static frame vs 64x SSAA
  double orbit_psnr_db = 0.0;    // mean per-frame PSNR over the orbit
  double flicker_psnr_db = 0.0;  // PSNR of frame-to-frame differences vs the reference's
  double bytes_per_pixel = 0.0;
  bool pareto = false;  // no other technique of the scene is both faster and better (PSNR)
};

// The default technique list: noaa, fxaa, msaa 4x, ssaa 8x/16x, ssaa-filtered kernels 1-3,
// dyncov, dcaa, agaa 4x/8x and the 12 RSAA variants.
std::vector<TechniqueOptions> default_techniques();
// The built-in scenes and the assimp test models the tests use.
std::vector<std::string> default_scenes();

using Progress = std::function<void(const std::string& what, int done, int total)>;

class CopyPass;
struct FrameTiming {
  std::vector<PassTime> pass_medians;  // median over the timed frames, per pass
  double frame_ms = 0.0;               // median of the frames' summed wall-clock pass times
  double copy_ms = 0.0;                // median of the copy pass timed after each frame
};
// One warm-up frame of each technique, then `frames` rounds: in each, every technique renders one
// frame followed by `copy`, the order rotated by one a round (none always runs after the same
// one). Techniques timed in one call see the same load on a shared machine, so their ratios are
// far steadier than those of techniques timed one after another (README, *Timing in rounds*).
// One timing per technique, in order.
std::vector<FrameTiming> time_rounds(const std::vector<Technique*>& techniques, const GpuScene& scene,
                                     const View& view, GLuint output, int frames, CopyPass& copy);

// Needs a current GL context.
std::vector<TechniqueResult> run_bench(const BenchOptions& options, const Progress& progress);

// A pass's wall time as a multiple of the copy pass timed beside it (0 when unknown).
double copy_multiple(const TechniqueResult& result, const PassTime& pass);

// Marks the Pareto front of each scene (time ratio down, PSNR up).
void mark_pareto(std::vector<TechniqueResult>& results);

// The cheapest technique of `scene` whose PSNR reaches `target_db`, or nullptr.
const TechniqueResult* cheapest_reaching(const std::vector<TechniqueResult>& results,
                                         const std::string& scene, double target_db);

std::string results_json(const BenchOptions& options, const std::vector<TechniqueResult>& results);
std::string results_csv(const std::vector<TechniqueResult>& results);
// Reads results_json() output back (for re-reporting and re-plotting without measuring).
// Throws std::runtime_error naming the file and field on a malformed file.
std::vector<TechniqueResult> read_results_json(const std::string& path, BenchOptions& options);

// Markdown: every row, then per scene the paper's trades (8 vs 4 samples, SADP vs depth) and
// where the RSAA variants sit against the Pareto front.
std::string results_markdown(const BenchOptions& options, const std::vector<TechniqueResult>& results);

// PNG plots made with OpenCV: PSNR against frame-time ratio with the Pareto front, and per-pass
// stacked times, for one scene.
void plot_pareto(const std::vector<TechniqueResult>& results, const std::string& scene,
                 const std::string& path);
void plot_pass_times(const std::vector<TechniqueResult>& results, const std::string& scene,
                     const std::string& path);

// The techniques shown side by side in the crop image (labels as technique_label()).
const std::vector<std::string>& crop_labels();
// Side-by-side crops (4x nearest-neighbour, labelled) of the same region of every image; the
// region is the window where images.front() differs most from `reference` (where aliasing is).
void plot_crops(const std::vector<std::pair<std::string, DisplayImage>>& images,
                const DisplayImage& reference, const std::string& path);

}  // namespace rsaa::bench

namespace rsaa::bench {

// A line chart of one or more y columns against an x column of a CSV table (header row, numbers
// below), for the trade curves. Throws std::runtime_error naming the file and column.
void plot_csv(const std::string& csv_path, const std::string& x_column,
              const std::vector<std::string>& y_columns, bool log_x, const std::string& title,
              const std::string& png_path);

}  // namespace rsaa::bench
